// The on-disk program cache: a second context loads the binary instead of
// compiling, a corrupt entry is a miss, keys change with options and source.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include "device/context.h"
#include "device/kernel_source.h"

using namespace prism;
namespace fs = std::filesystem;

namespace {

// Launches round the global size up to the work-group size, so the kernel checks its count.
const char* kSource =
    "__kernel void twice(__global float* x, int n) { int i = get_global_id(0); if (i < n) x[i] *= 2.0f; }\n";
// The same kernel for the other test: text of its own, so that PoCL's own cache
// keeps it apart. Run at once on a cold cache (ctest --parallel), the two tests
// compiled one program into one PoCL cache entry, and the binary the first test
// took from it once failed PoCL's own check when loaded (an assertion in
// pocl_binary_get_kernels_metadata, under the sanitizers' build).
const char* kPolicySource =
    "// the cache policy test's\n"
    "__kernel void twice(__global float* x, int n) { int i = get_global_id(0); if (i < n) x[i] *= 2.0f; }\n";

std::vector<fs::path> cacheFiles(const fs::path& folder) {
  std::vector<fs::path> files;
  if (fs::exists(folder))
    for (const auto& e : fs::directory_iterator(folder)) files.push_back(e.path());
  return files;
}

float runTwice(Context& ctx, const char* source = kSource) {
  cl_kernel k = ctx.kernelFromText(source, "twice.cl", "twice");
  Buffer b(ctx, sizeof(float));
  float v = 21;
  b.write(&v, sizeof v);
  ctx.launch(k).arg(b).arg(1).run(1);
  b.read(&v, sizeof v);
  return v;
}

}  // namespace

TEST_CASE("compiled programs are cached on disk and a corrupt entry is a miss", "[device][cache]") {
  fs::path folder = fs::temp_directory_path() / ("prism-cache-test-" + std::to_string(::getpid()));
  fs::remove_all(folder);
  // PRISM_CACHE_DIR, not XDG_CACHE_HOME: PoCL keeps its own cache under the latter.
  ::setenv("PRISM_CACHE_DIR", folder.c_str(), 1);
  fs::path kernels = folder;
  DeviceDescription device = selectDevice("cpu");

  {
    Context ctx(device, true, BinaryCache::Always);
    CHECK(runTwice(ctx) == 42.0f);
  }
  auto files = cacheFiles(kernels);
  REQUIRE(files.size() == 1);
  auto first_write = fs::last_write_time(files[0]);

  {
    Context ctx(device, true, BinaryCache::Always);  // loads the binary: the entry is not rewritten
    CHECK(runTwice(ctx) == 42.0f);
  }
  CHECK(fs::last_write_time(files[0]) == first_write);

  {
    std::fstream f(files[0], std::ios::in | std::ios::out | std::ios::binary);
    f.seekp(40);
    f.put('\x5a');  // flip bytes in the payload: the checksum no longer matches
    f.put('\xa5');
  }
  {
    Context ctx(device, true, BinaryCache::Always);  // a miss: compiles again and rewrites the entry
    CHECK(runTwice(ctx) == 42.0f);
  }
  ProgramCache cache(kernels.string());
  CHECK(cache.load(files[0].stem().string()).has_value());

  {
    Context ctx(device, false, BinaryCache::Always);  // --no-cache: nothing new is written
    CHECK(runTwice(ctx) == 42.0f);
    ctx.kernelFromText(kSource, "twice.cl", "twice", "-DUNUSED=1");
  }
  CHECK(cacheFiles(kernels).size() == 1);

  CHECK(cache.keyFor(device, "", kSource) != cache.keyFor(device, "-DX", kSource));
  CHECK(cache.keyFor(device, "", kSource) != cache.keyFor(device, "", std::string(kSource) + " "));
  ::unsetenv("PRISM_CACHE_DIR");
  fs::remove_all(folder);
}

// PoCL caches its builds itself, and fetching a binary from it costs a compile
// of every kernel, so by default prism's cache is left out on PoCL and used on
// other drivers (Oclgrind, GPU drivers) or when PoCL's cache is off.
TEST_CASE("a driver that caches its builds is left to its own cache", "[device][cache]") {
  fs::path folder = fs::temp_directory_path() / ("prism-cache-policy-" + std::to_string(::getpid()));
  fs::remove_all(folder);
  ::setenv("PRISM_CACHE_DIR", folder.c_str(), 1);
  DeviceDescription device = selectDevice("cpu");
  const bool pocl = device.platform_name.find("Portable Computing Language") != std::string::npos;
  CHECK(driverCachesBuilds(device) == pocl);
  {
    Context ctx(device, true);
    CHECK(runTwice(ctx, kPolicySource) == 42.0f);
  }
  CHECK(cacheFiles(folder).size() == (pocl ? 0u : 1u));
  ::setenv("POCL_KERNEL_CACHE", "0", 1);
  CHECK_FALSE(driverCachesBuilds(device));
  ::unsetenv("POCL_KERNEL_CACHE");
  ::unsetenv("PRISM_CACHE_DIR");
  fs::remove_all(folder);
}

TEST_CASE("a kernel that fails to compile reports the compiler's log", "[device][build]") {
  Context ctx(selectDevice("cpu"), false);
  try {
    ctx.kernelFromText("__kernel void broken(__global float* x) { x[0] = undeclared_name; }\n", "broken.cl",
                       "broken");
    FAIL("the build should have failed");
  } catch (const KernelBuildError& e) {
    std::string message = e.what();
    CHECK(message.find("broken.cl") != std::string::npos);
    INFO(message);
    CHECK(message.find("undeclared_name") != std::string::npos);
  }
}

TEST_CASE("kernel sources resolve their includes once each, with #line markers", "[device][source]") {
  std::string text = assembleKernelText(
      "#include \"shared/ray_gpu.h\"\n#include \"shared/ray_gpu.h\"\n#include \"common/math.h\"\nint x;\n", "probe.cl");
  size_t first = text.find("typedef struct RayGpu");
  CHECK(first != std::string::npos);
  CHECK(text.find("typedef struct RayGpu", first + 1) == std::string::npos);
  CHECK(text.find("#line 1 \"shared/ray_gpu.h\"") != std::string::npos);
  CHECK(text.find("#line 4 \"probe.cl\"") != std::string::npos);
  CHECK_THROWS_WITH(assembleKernelText("#include \"no/such/file.h\"\n", "probe.cl"),
                    Catch::Contains("no/such/file.h"));
  // Every embedded entry file assembles.
  for (const char* entry : {"generate.cl", "extend.cl", "shade.cl", "occlude.cl", "count_rays.cl", "scatter_rays.cl",
                            "accumulate.cl"})
    CHECK_NOTHROW(assembleKernelSource(entry));
}

TEST_CASE("device selection by index, type and name, with an error listing the devices", "[device]") {
  auto devices = listDevices();
  REQUIRE(!devices.empty());
  CHECK(selectDevice("0").index == 0);
  CHECK(selectDevice("cpu").type & CL_DEVICE_TYPE_CPU);
  std::string part = devices[0].name.substr(0, 4);
  CHECK(selectDevice(part).name.find(part) != std::string::npos);
  CHECK_THROWS_WITH(selectDevice("99"), Catch::Contains("no device with that index") && Catch::Contains(devices[0].name));
  CHECK_THROWS_WITH(selectDevice("zzz-no-such"), Catch::Contains("zzz-no-such"));
}
