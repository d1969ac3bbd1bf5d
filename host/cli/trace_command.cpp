// `prism trace SCENE_OR_MESH --rays IN --hits OUT`: prism as a ray-query engine
// for other programs, through prismIntersect / prismOccluded.
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include "args.h"
#include "commands.h"
#include "help_text.h"
#include "prism.h"
#include "render_args.h"

namespace prism_cli {
namespace {

const std::vector<OptionSpec> kTraceOptions = {
    {"--rays", "", true},  {"--hits", "", true},      {"--accel", "", true}, {"--device", "", true},
    {"--occluded", "", false}, {"--no-cache", "", false}, {"--quiet", "", false}, {"--help", "-h", false},
};

struct SceneDeleter {
  void operator()(PrismSceneImpl* s) const { prismReleaseScene(s); }
};
struct ContextDeleter {
  void operator()(PrismContextImpl* c) const { prismReleaseContext(c); }
};

// The whole file; a size that is not a whole number of 32-byte rays is an error.
bool readRays(const std::string& path, std::vector<PrismRay>& rays) {
  std::ifstream in(path, std::ios::binary | std::ios::ate);
  if (!in) {
    printError("cannot read rays from '" + path + "'");
    return false;
  }
  const std::streamoff size = in.tellg();
  if (size % static_cast<std::streamoff>(sizeof(PrismRay)) != 0) {
    printError("'" + path + "' holds " + std::to_string(size) +
               " bytes, not a whole number of 32-byte rays (float ox, oy, oz, tmin, dx, dy, dz, tmax)");
    return false;
  }
  rays.resize(static_cast<size_t>(size) / sizeof(PrismRay));
  in.seekg(0);
  if (!rays.empty() && !in.read(reinterpret_cast<char*>(rays.data()), size)) {
    printError("cannot read rays from '" + path + "'");
    return false;
  }
  return true;
}

// Every byte written and the file closed, or false with errno's reason.
bool writeAll(std::FILE* f, const std::vector<PrismHit>& hits, std::string* reason) {
  const std::size_t n = hits.size();
  bool ok = std::fwrite(hits.data(), sizeof(PrismHit), n, f) == n && std::fflush(f) == 0;
  int err = ok ? 0 : errno;  // the first failure's reason
  if (std::fclose(f) != 0 && ok) {
    ok = false;
    err = errno;
  }
  if (!ok) *reason = std::strerror(err);
  return ok;
}

// A regular file (or a new one) is written under a temporary name beside it and
// renamed, so a failure leaves no half file; through a symbolic link, beside
// the file it names. A pipe or a device (/dev/stdout) is written in place: a
// rename would replace the device node with a file. Any short write (a full
// disk: /dev/full) is an error.
bool writeHits(const std::string& path, const std::vector<PrismHit>& hits) {
  namespace fs = std::filesystem;
  std::error_code ec;
  std::string reason;
  const fs::file_status st = fs::status(path, ec);  // through symbolic links
  if (fs::exists(st) && !fs::is_regular_file(st) && !fs::is_directory(st)) {
    std::FILE* f = std::fopen(path.c_str(), "wb");
    if (f && writeAll(f, hits, &reason)) return true;
    printError("cannot write hits to '" + path + "': " + (f ? reason : std::string(std::strerror(errno))));
    return false;
  }
  fs::path target(path);
  for (int links = 0; links < 40 && fs::is_symlink(target, ec); ++links) {
    const fs::path next = fs::read_symlink(target, ec);
    target = next.is_absolute() ? next : target.parent_path() / next;
  }
  const std::string tmp = target.string() + ".tmp";
  std::FILE* f = std::fopen(tmp.c_str(), "wb");
  if (f && writeAll(f, hits, &reason) && std::rename(tmp.c_str(), target.c_str()) == 0) return true;
  if (reason.empty()) reason = std::strerror(errno);
  std::remove(tmp.c_str());
  printError("cannot write hits to '" + path + "': " + reason);
  return false;
}

}  // namespace

int runTrace(const std::vector<std::string>& args) {
  const ParsedArgs parsed = parseArgs(args, kTraceOptions, "prism trace");
  if (parsed.has("--help")) {
    std::fputs(kTraceHelp, stdout);
    return kExitOk;
  }
  if (parsed.positionals().size() != 1) throw UsageError("expected one scene or mesh file");
  const std::string input = parsed.positionals()[0];
  const auto rays_path = parsed.text("--rays");
  const auto hits_path = parsed.text("--hits");
  if (!rays_path) throw UsageError("missing --rays IN, the binary file of rays to trace");
  if (!hits_path) throw UsageError("missing --hits OUT, the file to write the hits to");
  PrismAccel accel = PRISM_ACCEL_BVH;
  if (const auto name = parsed.text("--accel"))
    if (prismParseAccel(name->c_str(), &accel) != PRISM_OK)
      throw UsageError("--accel: unknown structure '" + *name + "' (expected auto, bvh, octree, bsp or none)");
  const bool occlusion = parsed.has("--occluded");

  std::vector<PrismRay> rays;
  if (!readRays(*rays_path, rays)) return kExitFailure;

  PrismScene raw_scene = nullptr;
  const bool is_scene = lowerExtension(input) == ".json";
  if ((is_scene ? prismLoadScene(input.c_str(), &raw_scene) : prismLoadMeshAsScene(input.c_str(), &raw_scene)) !=
      PRISM_OK)
    return failWithLastError();
  std::unique_ptr<PrismSceneImpl, SceneDeleter> scene(raw_scene);

  PrismContextOptions context_options;
  prismDefaultContextOptions(&context_options);
  context_options.use_kernel_cache = parsed.has("--no-cache") ? 0 : 1;
  PrismContext raw_context = nullptr;
  const auto device = parsed.text("--device");
  if (prismCreateContext(device ? device->c_str() : nullptr, &context_options, &raw_context) != PRISM_OK)
    return failWithLastError();
  std::unique_ptr<PrismContextImpl, ContextDeleter> context(raw_context);

  std::vector<PrismHit> hits(rays.size());
  double seconds = 0;
  if (occlusion) {
    std::vector<uint8_t> blocked(rays.size());
    if (prismOccluded(context.get(), scene.get(), accel, rays.data(), blocked.data(), rays.size(), &seconds) !=
        PRISM_OK)
      return failWithLastError();
    for (size_t i = 0; i < rays.size(); ++i)
      hits[i] = PrismHit{blocked[i] ? 0.0f : std::numeric_limits<float>::infinity(), -1, 0.0f, 0.0f};
  } else if (prismIntersect(context.get(), scene.get(), accel, rays.data(), hits.data(), rays.size(), &seconds) !=
             PRISM_OK) {
    return failWithLastError();
  }
  if (!writeHits(*hits_path, hits)) return kExitFailure;
  if (!parsed.has("--quiet")) {
    PrismDeviceInfo info{};
    prismGetContextDevice(context.get(), &info);
    std::printf("prism: traced %zu rays (%s) with %s on '%s' in %.4f s: %.2f Mrays/s -> %s\n", rays.size(),
                occlusion ? "any hit" : "closest hit", prismAccelName(accel), info.name, seconds,
                seconds > 0 ? static_cast<double>(rays.size()) / seconds / 1e6 : 0.0, hits_path->c_str());
  }
  return kExitOk;
}

}  // namespace prism_cli
