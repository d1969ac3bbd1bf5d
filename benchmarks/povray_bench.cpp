#include "povray_bench.h"

#include "bench_process.h"

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <string>
#include <sys/wait.h>
#include <vector>

#include "device/device_list.h"
#include "kernels/shared/ray_gpu.h"
#include "render/image_writer.h"
#include "render/renderer.h"
#include "scene_format/scene_loader.h"

namespace prism::bench {
namespace {

const char* kUsage =
    "usage: prism-bench povray [--device D] [--size WxH] [--max-depth D] [--min-weight X]\n"
    "                          [--repeat N] [--out DIR] [--povray PATH]\n"
    "\n"
    "Renders scenes/whitted.json with prism and benchmarks/povray/whitted.pov (the\n"
    "same scene for POV-Ray 3.7) at --size (default 640x480), --max-depth (default 8\n"
    "reflected/refracted levels) and --min-weight (default 1/255, POV-Ray's\n"
    "adc_bailout), POV-Ray on as many threads as the device has compute units, the\n"
    "two taking turns --repeat times (default 5). Prints POV-Ray's trace time (its\n"
    "own figure, parsing left out) over prism's render time (kernels already built;\n"
    "the structure's build, uploads and tracing counted), and the difference of the\n"
    "two images. Writes prism.png, povray.png and side-by-side.png to --out\n"
    "(default bench-out). Without POV-Ray ('apt install povray') it says so and\n"
    "exits 0.\n";

struct Settings {
  std::string device, out_dir = "bench-out", povray = "povray";
  int width = 640, height = 480, max_depth = 8, repeats = 5;
  double min_weight = 1.0 / 255.0;
};

bool povrayInstalled(const Settings& s) {
  int status = 0;
  capture("command -v " + shellQuote(s.povray), &status);
  return status == 0;
}

// One POV-Ray render; returns its "Trace Time" in seconds.
double runPovray(const Settings& s, const std::string& pov, const std::string& png, int threads) {
  const std::string command = shellQuote(s.povray) + " +I" + shellQuote(pov) + " +O" + shellQuote(png) + " +W" +
                              std::to_string(s.width) + " +H" + std::to_string(s.height) + " -D -A -V +WT" +
                              std::to_string(threads) + " File_Gamma=sRGB Declare=MaxDepth=" +
                              std::to_string(s.max_depth) + " Declare=MinWeight=" + std::to_string(s.min_weight);
  int status = 0;
  const std::string out = capture(command, &status);
  const std::string key = "Trace Time:";
  const size_t at = out.find(key);
  const size_t open = at == std::string::npos ? at : out.find('(', at);
  if (status != 0 || open == std::string::npos)
    throw std::runtime_error("POV-Ray failed (" + command + "):\n" + out.substr(out.size() > 2000 ? out.size() - 2000 : 0));
  return std::stod(out.substr(open + 1));
}

}  // namespace

int povrayMain(const std::vector<std::string>& args) {
  Settings s;
  for (std::size_t i = 1; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= args.size()) throw std::invalid_argument(a + " needs a value");
      return args[++i];
    };
    try {
      if (a == "--help" || a == "-h") {
        std::cout << kUsage;
        return 0;
      } else if (a == "--device") {
        s.device = value();
      } else if (a == "--size") {
        const std::string v = value();
        if (std::sscanf(v.c_str(), "%dx%d", &s.width, &s.height) != 2 || s.width < 1 || s.height < 1)
          throw std::invalid_argument("--size: expected WxH, got '" + v + "'");
      } else if (a == "--max-depth") {
        s.max_depth = std::stoi(value());
        if (s.max_depth < 0 || s.max_depth > 30) throw std::invalid_argument("--max-depth: expected 0 to 30");
      } else if (a == "--min-weight") {
        s.min_weight = std::stod(value());
        if (!(s.min_weight >= 0 && s.min_weight < 1)) throw std::invalid_argument("--min-weight: expected 0 <= X < 1");
      } else if (a == "--repeat") {
        s.repeats = std::max(1, std::stoi(value()));
      } else if (a == "--out") {
        s.out_dir = value();
      } else if (a == "--povray") {
        s.povray = value();
      } else {
        throw std::invalid_argument("unknown option '" + a + "'");
      }
    } catch (const std::exception& e) {
      std::cerr << "prism-bench povray: " << e.what() << "\n\n" << kUsage;
      return 2;
    }
  }
  if (!povrayInstalled(s)) {
    std::cout << "prism-bench povray: skipped: '" << s.povray
              << "' is not on the PATH (Debian: apt install povray; or give --povray PATH)\n";
    return 0;
  }
  try {
    std::setvbuf(stdout, nullptr, _IOLBF, 0);
    std::filesystem::create_directories(s.out_dir);
    const std::string pov = PRISM_SOURCE_DIR "/benchmarks/povray/whitted.pov";
    const std::string pov_png = s.out_dir + "/povray.png", prism_png = s.out_dir + "/prism.png";
    DeviceDescription device = selectDevice(s.device);
    Context context(device, true);
    Renderer renderer(context);
    const int threads = static_cast<int>(std::max(1u, device.compute_units));

    Scene scene = loadSceneFile(PRISM_SOURCE_DIR "/scenes/whitted.json");
    RenderOptions options = RenderOptions::fromScene(scene);
    options.width = s.width;
    options.height = s.height;
    options.max_depth = s.max_depth;
    options.min_weight = s.min_weight;
    options.spp = 1;
    options.aa.reset();

    std::printf("device: %s (%s, %u compute units); POV-Ray on %d threads; %dx%d, depth %d, min weight %.6g;\n"
                "median of %d runs, the two taking turns\n\n",
                device.name.c_str(), device.driver_version.c_str(), device.compute_units, threads, s.width, s.height,
                s.max_depth, s.min_weight, s.repeats);
    RenderResult result = renderer.render(scene, options);  // kernels built, caches warm
    runPovray(s, pov, pov_png, threads);
    std::vector<double> pov_times, prism_times, prism_setup;
    for (int r = 0; r < s.repeats; ++r) {
      pov_times.push_back(runPovray(s, pov, pov_png, threads));
      result = renderer.render(scene, options);
      prism_times.push_back(result.stats.seconds);
      prism_setup.push_back(result.stats.setup_seconds);
    }
    std::vector<float> rgb;
    for (size_t k = 0; k < result.rgba.size(); k += 4) rgb.insert(rgb.end(), &result.rgba[k], &result.rgba[k] + 3);
    writeImage(prism_png, rgb.data(), s.width, s.height, 3);

    // The images as 8-bit sRGB, as both were written.
    OIIO::ImageBuf a(pov_png), b(prism_png);
    OIIO::ImageBufAlgo::CompareResults cmp = OIIO::ImageBufAlgo::compare(a, b, 1.0, 4.5 / 255.0);
    if (cmp.error)
      throw std::runtime_error("cannot compare " + pov_png + " and " + prism_png + ": " + a.geterror() + b.geterror());
    OIIO::ImageBuf side(OIIO::ImageSpec(2 * s.width, s.height, 3, OIIO::TypeDesc::UINT8));
    OIIO::ImageBufAlgo::paste(side, 0, 0, 0, 0, a);
    OIIO::ImageBufAlgo::paste(side, s.width, 0, 0, 0, b);
    side.write(s.out_dir + "/side-by-side.png");

    const double pov_s = median(pov_times), prism_s = median(prism_times), setup_s = median(prism_setup);
    const double pixels = static_cast<double>(s.width) * s.height;
    std::printf("%-10s %12s %12s %12s %12s\n", "", "time s", "set-up s", "Mrays/s", "rays");
    std::printf("%-10s %12.3f %12s %12s %12s\n", "povray", pov_s, "-", "-", "-");
    std::printf("%-10s %12.3f %12.3f %12.2f %12llu\n", "prism", prism_s, setup_s,
                static_cast<double>(result.stats.totalRays()) / prism_s / 1e6,
                static_cast<unsigned long long>(result.stats.totalRays()));
    std::printf("\nPOV-Ray trace time / prism render time: %.2fx (> 1: prism faster)\n", pov_s / prism_s);
    std::printf("images (8-bit sRGB): mean difference %.2f / 255, largest %.0f / 255, %.2f%% of pixels differ "
                "by more than 4 / 255 in some channel\n",
                cmp.meanerror * 255.0, cmp.maxerror * 255.0,
                100.0 * static_cast<double>(cmp.nwarn + cmp.nfail) / pixels);
    std::printf("files: %s, %s, %s/side-by-side.png\n", pov_png.c_str(), prism_png.c_str(), s.out_dir.c_str());
  } catch (const std::exception& e) {
    std::cerr << "prism-bench povray: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

}  // namespace prism::bench
