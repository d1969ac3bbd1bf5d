#include "firsthit_bench.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <limits>
#include <stdexcept>

#include "bench_data.h"
#include "accel_workloads.h"
#include "accel_bench.h"
#include "accel/prim_ref.h"
#include "device/context.h"
#include "device/device_list.h"
#include "kernels/shared/ray_gpu.h"
#include "mesh/mesh_loader.h"
#include "mesh/plugin_registry.h"
#include "bench_plugins.h"
#include "plot_png.h"
#include "render/firsthit.h"
#include "render/gpu_scene.h"
#include "render/ray_queries.h"
#include "render/sampler.h"
#include "scene/mesh_objects.h"

namespace prism::bench {
namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

template <typename F>
double medianSeconds(int repeats, F run) {
  std::vector<double> t;
  for (int i = 0; i < std::max(1, repeats); ++i) t.push_back(run());
  std::sort(t.begin(), t.end());
  return t[t.size() / 2];
}

std::string fixed(double v, const char* format) {
  char text[64];
  std::snprintf(text, sizeof text, format, v);
  return text;
}

void printHeader() {
  std::printf("%-28s %9s %7s %9s %9s %9s %9s %8s %8s %8s %9s\n", "mesh", "tris", "pairs/p", "setup s", "zbuf s",
              "build s", "trace s", "x faster", "x +setup", "same%", "depth err");
}

double withSetup(const FirstHitRow& r) {
  return (r.build_seconds + r.trace_seconds) / (r.setup_seconds + r.zbuffer_seconds);
}

void printRow(const FirstHitRow& r) {
  std::string scene = r.scene.size() > 28 ? "..." + r.scene.substr(r.scene.size() - 25) : r.scene;
  std::printf("%-28s %9zu %7.2f %9.4f %9.4f %9.4f %9.4f %8.2f %8.2f %8.3f %9.1e\n", scene.c_str(), r.triangles,
              r.pairs_per_prim, r.setup_seconds, r.zbuffer_seconds, r.build_seconds, r.trace_seconds,
              r.trace_seconds / r.zbuffer_seconds, withSetup(r), r.identical, r.max_depth_error);
  std::fflush(stdout);
}

void writeCsv(const std::string& path, const std::vector<FirstHitRow>& rows) {
  std::ofstream f(path);
  if (!f) throw std::runtime_error(path + ": cannot open for writing");
  f << "mesh,triangles,samples,pairs_per_primitive,setup_seconds,zbuffer_seconds,bvh_build_seconds,trace_seconds,"
       "trace_over_zbuffer,with_setup_ratio,agreement_percent,identical_percent,max_depth_error\n";
  for (const FirstHitRow& r : rows)
    f << r.scene << "," << r.triangles << "," << r.samples << "," << fixed(r.pairs_per_prim, "%.4g") << ","
      << fixed(r.setup_seconds, "%.6g") << "," << fixed(r.zbuffer_seconds, "%.6g") << ","
      << fixed(r.build_seconds, "%.6g") << "," << fixed(r.trace_seconds, "%.6g") << ","
      << fixed(r.trace_seconds / r.zbuffer_seconds, "%.4g") << "," << fixed(withSetup(r), "%.4g") << ","
      << fixed(r.agreement, "%.4f") << "," << fixed(r.identical, "%.4f") << "," << fixed(r.max_depth_error, "%.3g")
      << "\n";
}

void writePlot(const std::string& path, const std::vector<FirstHitRow>& rows, int width, int height, int spp) {
  // Kernels alone, and with their set-up; every mesh a marker (short names:
  // the legend is narrow).
  PlotSeries zbuffer{"zbuffer", {}, {}, 0xD55E00};
  PlotSeries trace{"trace (BVH)", {}, {}, 0x0072B2};
  PlotSeries zbuffer_setup{"zbuf+setup", {}, {}, 0xE69F00};
  PlotSeries trace_setup{"trace+build", {}, {}, 0x56B4E9};
  for (const FirstHitRow& r : rows) {
    const double n = static_cast<double>(r.triangles);
    zbuffer.markers.emplace_back(n, r.zbuffer_seconds);
    trace.markers.emplace_back(n, r.trace_seconds);
    zbuffer_setup.markers.emplace_back(n, r.zbuffer_seconds + r.setup_seconds);
    trace_setup.markers.emplace_back(n, r.trace_seconds + r.build_seconds);
  }
  writeLogLogPlot(path,
                  "Primary visibility, " + std::to_string(width) + "x" + std::to_string(height) +
                      (spp == 1 ? " samples" : " pixels at " + std::to_string(spp) + " spp"),
                  "triangles", "seconds", {zbuffer, trace, zbuffer_setup, trace_setup}, {"squares: meshes"});
}

}  // namespace

const char* const kFirstHitUsage =
    "usage: prism-bench firsthit [options] [FILES...]\n"
    "\n"
    "Primary visibility two ways on the same samples (every pixel centre of a camera\n"
    "framing the mesh, or --spp per pixel): the first-hit Z-buffer pass (samples sorted by pixel,\n"
    "primitives projected and scan-converted by kernels) against primary rays traced\n"
    "through a BVH. Times the host set-up (FirstHitPass::prepare; BVH build) and the\n"
    "device work apart, and checks that both give the same hits bit for bit. The\n"
    "set-up is the median of --repeat calls on one pass, which keeps its buffers:\n"
    "from 3 repeats on, a frame's after the first, without the first touch of\n"
    "fresh memory. FILES\n"
    "are mesh files; without FILES, the shared benchmark meshes from about 1k to\n"
    "1.1M triangles.\n"
    "\n"
    "options:\n"
    "  --device D     OpenCL device: index, cpu, gpu or a name substring\n"
    "  --size WxH     the film (default 1024x1024)\n"
    "  --spp N        samples per pixel (default 1: its centre), in pixel order as a\n"
    "                 render's per-pixel modes place them: the centres of the cells of\n"
    "                 a ceil(sqrt N)-wide grid over the pixel, the first N of them\n"
    "  --repeat N     timings are the median of N runs (default 3)\n"
    "  --profile      also print each z-buffer kernel's device time (one run)\n"
    "  --out DIR      where firsthit.csv and firsthit.png go (default bench-out)\n"
    "  --data DIR     folder searched first for the ladder's meshes (default: $PRISM_BENCH_DATA)\n";

int firstHitMain(const std::vector<std::string>& args) {
  FirstHitBenchOptions options;
  options.command = "prism-bench";
  for (const std::string& a : args) options.command += " " + a;
  auto usage = [](const std::string& message) {
    std::cerr << "prism-bench firsthit: " << message << "\n\n" << kFirstHitUsage;
    return 2;
  };
  auto positive = [](const std::string& text, int* out) {
    try {
      size_t used = 0;
      int v = std::stoi(text, &used);
      if (used != text.size() || v < 1) return false;
      *out = v;
      return true;
    } catch (const std::exception&) {
      return false;
    }
  };
  for (size_t i = 1; i < args.size(); ++i) {
    const std::string& a = args[i];
    const bool has_value = i + 1 < args.size();
    if (a == "--help" || a == "-h") {
      std::cout << kFirstHitUsage;
      return 0;
    } else if (a == "--profile") {
      options.profile = true;
    } else if (a == "--device" || a == "--size" || a == "--spp" || a == "--repeat" || a == "--out" || a == "--data") {
      if (!has_value) return usage(a + " needs a value");
      const std::string v = args[++i];
      if (a == "--device") {
        options.device = v;
      } else if (a == "--out") {
        options.out_dir = v;
      } else if (a == "--data") {
        options.data_dir = v;
      } else if (a == "--spp") {
        if (!positive(v, &options.spp)) return usage("--spp: expected a positive count, got '" + v + "'");
      } else if (a == "--repeat") {
        if (!positive(v, &options.repeats)) return usage("--repeat: expected a positive count, got '" + v + "'");
      } else {
        const size_t x = v.find('x');
        if (x == std::string::npos || !positive(v.substr(0, x), &options.width) ||
            !positive(v.substr(x + 1), &options.height))
          return usage("--size: expected WxH, e.g. 1024x1024, got '" + v + "'");
      }
    } else if (!a.empty() && a[0] == '-') {
      return usage("unknown option '" + a + "'");
    } else {
      options.files.push_back(a);
    }
  }
  try {
    runFirstHitBench(options);
  } catch (const std::exception& e) {
    std::cerr << "prism-bench firsthit: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

std::vector<FirstHitRow> runFirstHitBench(const FirstHitBenchOptions& options) {
  if (options.width < 1 || options.height < 1 || options.spp < 1)
    throw std::invalid_argument("--size and --spp must be positive");
  DeviceDescription device = selectDevice(options.device);
  Context context(device, true);
  std::filesystem::create_directories(options.out_dir);
  std::vector<std::string> inputs = options.files;
  if (inputs.empty()) {
    BenchLadder ladder = benchLadder(options.data_dir);
    for (const std::string& note : ladder.notes) std::cout << "ladder: " << note << "\n";
    inputs = ladder.files;
  }
  std::cout << "device: " << device.name << " (" << device.platform_name << ", driver " << device.driver_version << ", "
            << device.compute_units << " compute units)\n"
            << "samples: " << options.width << "x" << options.height
            << (options.spp == 1 ? " pixel centres" : " pixels at " + std::to_string(options.spp) + " spp (a grid in each)")
            << ", camera framing each mesh; median of " << options.repeats << " runs\n"
            << "zbuffer: host set-up (setup s) + every kernel of the pass (zbuf s: sort, bound, raster, resolve);\n"
               "trace: BVH build (build s) + extend kernel (trace s);\n"
               "x faster = trace s / zbuf s; x +setup = (build s + trace s) / (setup s + zbuf s); same% = hits "
               "identical bit for bit\n\n";
  printHeader();

  cl_kernel generate = context.kernel(kRenderLoopProgram, "generate");
  std::vector<FirstHitRow> rows;
  for (const std::string& path : inputs) {
    SharedMesh mesh = loadMeshFile(path, benchPlugins());
    Scene scene = sceneForMesh(mesh);
    RenderOptions render_options = RenderOptions::fromScene(scene);
    render_options.width = options.width;
    render_options.height = options.height;
    const GpuScene gpu = flattenScene(scene, render_options);  // the mesh's compact triangles and the camera

    FirstHitRow row;
    row.scene = std::filesystem::path(path).filename().string();
    row.triangles = gpu.primitive_count;

    // The same samples both ways, in pixel order: every pixel's centre, or
    // the centres of a grid's first spp cells over it.
    const size_t spp = static_cast<size_t>(options.spp);
    const size_t count = static_cast<size_t>(options.width) * options.height * spp;
    if (count > static_cast<size_t>(std::numeric_limits<std::int32_t>::max()))
      throw std::invalid_argument("--size and --spp make " + std::to_string(count) +
                                  " samples; one batch holds at most 2^31 - 1");
    row.samples = count;
    const int grid = static_cast<int>(std::ceil(std::sqrt(static_cast<double>(spp))));
    std::vector<float> xy(2 * count);
    for (size_t k = 0; k < count; ++k) {
      const size_t pixel = k / spp, cell = k % spp;
      xy[2 * k] = static_cast<float>(pixel % options.width) + (static_cast<float>(cell % grid) + 0.5f) / grid;
      xy[2 * k + 1] = static_cast<float>(pixel / options.width) + (static_cast<float>(cell / grid) + 0.5f) / grid;
    }
    Buffer xy_buffer(context, xy.size() * sizeof(float));
    xy_buffer.writeVector(xy);
    GeometryBuffers objects(context, gpu);
    Buffer hit_buffer(context, count * sizeof(HitGpu));

    // Z-buffer: the host's set-up, then the pass (one untimed run first: PoCL
    // finishes compiling at the first launch of a work-group size).
    FirstHitPass pass(context);
    // A render has them from the structure's build (DeviceAccel::primitive_options).
    const std::string kinds = primitiveKernelOptions(gpu.objects);
    row.setup_seconds = medianSeconds(options.repeats, [&] {
      auto start = Clock::now();
      pass.prepare(gpu, kinds);
      context.finish();
      return secondsSince(start);
    });
    pass.run(objects, xy_buffer, count, hit_buffer, options.spp);  // in pixel order
    context.finish();
    row.pairs_per_prim = static_cast<double>(pass.stats().pairs) / std::max<size_t>(1, gpu.primitive_count);
    row.zbuffer_seconds = medianSeconds(options.repeats, [&] {
      auto start = Clock::now();
      pass.run(objects, xy_buffer, count, hit_buffer, options.spp);
      context.finish();
      return secondsSince(start);
    });
    if (options.profile) {
      context.profile().start();
      pass.run(objects, xy_buffer, count, hit_buffer, options.spp);
      std::printf("  z-buffer kernels, one run:");
      for (const KernelTime& k : context.profile().stop()) std::printf(" %s %.4f s", k.name.c_str(), k.seconds);
      std::printf("\n");
    }
    std::vector<HitGpu> zhits = hit_buffer.readVector<HitGpu>(count);

    // Trace: the primary rays of the same samples (generate.cl, the renderer's
    // arithmetic) through a BVH.
    Buffer camera(context, sizeof(CameraGpu)), aov(context, count * sizeof(std::int32_t)),
        rays(context, count * sizeof(RayGpu));
    camera.write(&gpu.camera, sizeof(CameraGpu));
    aov.writeVector(std::vector<std::int32_t>(count, -1));
    context.launch(generate)
        .arg(camera)
        .arg(xy_buffer)
        .arg(aov)
        .arg(static_cast<cl_int>(0))   // first key
        .arg(static_cast<cl_int>(options.spp))
        .arg(static_cast<cl_long>(0))  // strata group base
        .arg(static_cast<cl_int>(1))   // strata
        .arg(static_cast<cl_int>(count))
        .arg(static_cast<cl_int>(0))  // a pinhole
        .arg(rays)
        .run((count + kGenerateLanes - 1) / kGenerateLanes);
    std::vector<RayGpu> primary = rays.readVector<RayGpu>(count);
    RayQueryEngine engine(context, SceneGeometry(gpu), AccelKind::Bvh);
    row.build_seconds = engine.accel().stats.build_seconds;
    // Camera rays in sample order: in packets where the renderer would trace them so.
    std::vector<HitGpu> thits = engine.intersect(primary, nullptr, RayCoherence::Coherent);  // warm-up at this size
    row.trace_seconds = medianSeconds(options.repeats, [&] {
      double s = 0;
      thits = engine.intersect(primary, &s, RayCoherence::Coherent);
      return s;
    });

    size_t same = 0, identical = 0;
    for (size_t k = 0; k < count; ++k) {
      if (zhits[k].prim != thits[k].prim) continue;
      ++same;
      if (std::memcmp(&zhits[k], &thits[k], sizeof(HitGpu)) == 0) ++identical;
      if (zhits[k].prim >= 0)
        row.max_depth_error =
            std::max(row.max_depth_error, std::fabs(double(zhits[k].t) - thits[k].t) / std::fabs(double(thits[k].t)));
    }
    row.agreement = 100.0 * same / count;
    row.identical = 100.0 * identical / count;
    printRow(row);
    rows.push_back(row);
  }
  writeCsv(options.out_dir + "/firsthit.csv", rows);
  writePlot(options.out_dir + "/firsthit.png", rows, options.width, options.height, options.spp);
  std::cout << "\nwrote " << options.out_dir << "/firsthit.csv and " << options.out_dir << "/firsthit.png\n";
  return rows;
}

}  // namespace prism::bench
