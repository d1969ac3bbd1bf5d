// `prism render`: load the scene, apply the command line's overrides, render on the
// chosen devices, write the colour image or one AOV, and print a summary line;
// for an animation, each frame (--frames) in turn, one file each.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "args.h"
#include "commands.h"
#include "help_text.h"
#include "interrupt.h"
#include "mpi_ranks.h"
#include "prism.h"
#include "progress_bar.h"
#include "render_args.h"

namespace prism_cli {
namespace {

struct SceneDeleter {
  void operator()(PrismSceneImpl* scene) const { prismReleaseScene(scene); }
};
struct ContextDeleter {
  void operator()(PrismContextImpl* context) const { prismReleaseContext(context); }
};
using SceneHandle = std::unique_ptr<PrismSceneImpl, SceneDeleter>;
using ContextHandle = std::unique_ptr<PrismContextImpl, ContextDeleter>;

void printSceneWarnings(PrismScene scene) {
  uint32_t count = 0;
  if (prismGetSceneWarningCount(scene, &count) != PRISM_OK) return;
  for (uint32_t i = 0; i < count; ++i) {
    const char* message = nullptr;
    if (prismGetSceneWarning(scene, i, &message) == PRISM_OK && message) printWarning(message);
  }
}

// A render-option flag given on the command line, and what it does to the options.
struct Override {
  const char* flags;  // as the user wrote them, for messages
  std::function<void(PrismRenderOptions&)> apply;
};

std::vector<Override> overridesOf(const RenderRequest& request) {
  std::vector<Override> out;
  auto add = [&](bool given, const char* flags, std::function<void(PrismRenderOptions&)> apply) {
    if (given) out.push_back({flags, std::move(apply)});
  };
  const RenderRequest& r = request;
  add(r.width.has_value(), "--width", [&r](PrismRenderOptions& o) { o.width = *r.width; });
  add(r.height.has_value(), "--height", [&r](PrismRenderOptions& o) { o.height = *r.height; });
  add(r.spp.has_value(), "--spp", [&r](PrismRenderOptions& o) { o.spp = *r.spp; });
  add(r.max_depth.has_value(), "--max-depth", [&r](PrismRenderOptions& o) { o.max_depth = *r.max_depth; });
  add(r.min_weight.has_value(), "--min-weight", [&r](PrismRenderOptions& o) { o.min_weight = *r.min_weight; });
  add(r.seed.has_value(), "--seed", [&r](PrismRenderOptions& o) { o.seed = *r.seed; });
  add(r.accel.has_value(), "--accel", [&r](PrismRenderOptions& o) { o.accel = *r.accel; });
  add(r.aa.has_value(), "--aa", [&r](PrismRenderOptions& o) {
    o.aa = *r.aa;
    // None, quincunx and adaptive place their own samples: a scene's spp does not
    // apply to them (an explicit --spp does).
    const bool own_samples = *r.aa == PRISM_AA_NONE || *r.aa == PRISM_AA_QUINCUNX || *r.aa == PRISM_AA_ADAPTIVE;
    if (own_samples && !r.spp) o.spp = 1;
  });
  add(r.filter.has_value(), "--filter", [&r](PrismRenderOptions& o) { o.filter = *r.filter; });
  add(r.aa_threshold.has_value(), "--aa-threshold", [&r](PrismRenderOptions& o) { o.aa_threshold = *r.aa_threshold; });
  add(r.aa_max_level.has_value(), "--aa-max-level", [&r](PrismRenderOptions& o) { o.aa_max_level = *r.aa_max_level; });
  add(r.first_hit.has_value(), "--first-hit", [&r](PrismRenderOptions& o) { o.first_hit = *r.first_hit; });
  add(r.inside_test.has_value(), "--inside-test", [&r](PrismRenderOptions& o) { o.inside_test = *r.inside_test; });
  add(r.shadows.has_value(), "--shadows", [&r](PrismRenderOptions& o) { o.shadows = *r.shadows; });
  add(r.bounds.has_value(), "--bounds", [&r](PrismRenderOptions& o) { o.bounds = *r.bounds; });
  add(r.stats, "--stats", [](PrismRenderOptions& o) { o.profile = 1; });
  add(r.check_nan, "--check-nan", [](PrismRenderOptions& o) { o.check_nan = 1; });
  return out;
}

// The scene's options with the command line's flags applied, checked by the
// library (one place for the rules of the scene format, the C API and these
// flags). Options the flags made impossible are a usage error naming the flags
// at fault: those refused alone on the scene's options, else all those given
// (a combination, such as --aa grid with --spp 5). Returns false, with the
// message printed, when the scene's own options are refused.
bool applyOverrides(const RenderRequest& request, PrismRenderOptions& options) {
  const PrismRenderOptions scene_options = options;
  const std::vector<Override> overrides = overridesOf(request);
  for (const Override& o : overrides) o.apply(options);
  if (prismCheckRenderOptions(&options) == PRISM_OK) return true;
  const std::string reason = lastErrorForUser();
  if (overrides.empty()) {
    printError(reason);
    return false;
  }
  std::string culprits;
  for (const Override& o : overrides) {
    PrismRenderOptions alone = scene_options;
    o.apply(alone);
    if (prismCheckRenderOptions(&alone) != PRISM_OK) culprits += (culprits.empty() ? "" : ", ") + std::string(o.flags);
  }
  if (culprits.empty())
    for (const Override& o : overrides) culprits += (culprits.empty() ? "" : ", ") + std::string(o.flags);
  throw UsageError(culprits + ": " + reason);
}

// The sampling in words for the summary: "jitter, box filter", "quincunx (tent)", "adaptive".
std::string samplingText(const PrismRenderOptions& options) {
  PrismAa aa = static_cast<PrismAa>(options.aa);
  if (aa == PRISM_AA_AUTO) aa = options.spp > 1 ? PRISM_AA_JITTER : PRISM_AA_NONE;
  const char* name = prismAaName(aa);
  std::string text = std::string("aa ") + (name ? name : "?");
  if (aa == PRISM_AA_QUINCUNX) return text + " (tent)";
  if (aa == PRISM_AA_ADAPTIVE || aa == PRISM_AA_NONE) return text;
  const char* filter = prismFilterName(static_cast<PrismFilter>(options.filter));
  return text + ", " + (filter ? filter : "?") + " filter";
}

// --camera-pos/--camera-look/--camera-up/--fov/--aperture/--focus-distance
// replace the scene's values; the library checks that the result can form an
// image, and a camera it refuses is a usage error naming the flags given.
bool applyCameraOverrides(const RenderRequest& request, PrismScene scene) {
  if (!request.camera_pos && !request.camera_look && !request.camera_up && !request.fov && !request.aperture &&
      !request.focus_distance)
    return true;
  PrismCamera camera{};
  camera.struct_size = sizeof camera;
  if (prismGetCamera(scene, &camera) != PRISM_OK) return false;
  auto copy = [](float* dst, const std::optional<std::array<float, 3>>& v) {
    if (v) std::copy(v->begin(), v->end(), dst);
  };
  copy(camera.position, request.camera_pos);
  copy(camera.look_at, request.camera_look);
  copy(camera.up, request.camera_up);
  if (request.fov) camera.fov_degrees = *request.fov;
  if (request.aperture) camera.aperture = *request.aperture;
  if (request.focus_distance) camera.focus_distance = *request.focus_distance;
  if (prismSetCamera(scene, &camera) == PRISM_OK) return true;
  std::string flags;
  for (auto [given, flag] : {std::pair{request.camera_pos.has_value(), "--camera-pos"},
                             std::pair{request.camera_look.has_value(), "--camera-look"},
                             std::pair{request.camera_up.has_value(), "--camera-up"},
                             std::pair{request.fov.has_value(), "--fov"},
                             std::pair{request.aperture.has_value(), "--aperture"},
                             std::pair{request.focus_distance.has_value(), "--focus-distance"}})
    if (given) flags += (flags.empty() ? "" : ", ") + std::string(flag);
  throw UsageError(flags + ": " + lastErrorForUser());
}

// Checked before rendering, so a typo in the folder does not cost a render.
bool outputFolderExists(const std::string& output_path) {
  const std::filesystem::path folder = std::filesystem::path(output_path).parent_path();
  std::error_code error;
  return folder.empty() || std::filesystem::is_directory(folder, error);
}

int onProgress(void* user, double fraction_done) {
  static_cast<ProgressBar*>(user)->update(fraction_done);
  return InterruptGuard::requested() ? 1 : 0;
}

// 8-bit PNG cannot hold negative components, so normals go in as n*0.5+0.5. The
// writer sRGB-encodes PNG; decoding first makes the bytes the usual linear
// normal-map code (128 for 0).
void normalsForPng(std::vector<float>& pixels) {
  for (float& v : pixels) {
    const double code = v * 0.5 + 0.5;
    v = static_cast<float>(code <= 0.04045 ? code / 12.92 : std::pow((code + 0.055) / 1.055, 2.4));
  }
}

int writeOutput(const RenderRequest& request, const std::string& output_path, PrismContext context,
                const PrismRenderOptions& options, const std::vector<float>& rgba) {
  const char* path = output_path.c_str();
  if (!request.aov) {
    // The background colour is part of the picture, so 8-bit and RGB-only
    // formats get opaque RGB; .exr and .tif keep alpha (primary-ray coverage)
    // for compositing.
    const std::string ext = lowerExtension(output_path);
    if (ext == ".exr" || ext == ".tif" || ext == ".tiff") {
      if (prismWriteImage(path, rgba.data(), options.width, options.height, 4) != PRISM_OK) return failWithLastError();
      return kExitOk;
    }
    std::vector<float> rgb(static_cast<size_t>(options.width) * options.height * 3);
    for (size_t i = 0; i < rgb.size() / 3; ++i)
      for (int c = 0; c < 3; ++c) rgb[3 * i + c] = rgba[4 * i + c];
    if (prismWriteImage(path, rgb.data(), options.width, options.height, 3) != PRISM_OK) return failWithLastError();
    return kExitOk;
  }
  uint32_t channels = 0;
  if (prismGetAovChannels(*request.aov, &channels) != PRISM_OK) return failWithLastError();
  std::vector<float> pixels(static_cast<size_t>(options.width) * options.height * channels);
  if (prismGetAov(context, *request.aov, pixels.data(), pixels.size()) != PRISM_OK) return failWithLastError();
  if (*request.aov == PRISM_AOV_NORMAL && lowerExtension(output_path) == ".png") normalsForPng(pixels);
  if (prismWriteImage(path, pixels.data(), options.width, options.height, channels) != PRISM_OK) {
    return failWithLastError();
  }
  return kExitOk;
}

// "'name'", or "2 devices ('a', 'b')" for a context over several.
std::string devicesText(PrismContext context) {
  uint32_t count = 0;
  if (prismGetContextDeviceCount(context, &count) != PRISM_OK || count == 0) return "?";
  std::string names;
  for (uint32_t i = 0; i < count; ++i) {
    PrismDeviceInfo info{};
    if (prismGetContextDeviceAt(context, i, &info) != PRISM_OK) return "?";
    names += (i ? ", '" : "'") + std::string(info.name) + "'";
  }
  return count == 1 ? names : std::to_string(count) + " devices (" + names + ")";
}

void printSummary(const std::string& output_path, const PrismRenderOptions& options, const std::string& devices,
                  const PrismRenderStats& stats) {
  const uint64_t total = stats.primary_rays + stats.reflected_rays + stats.refracted_rays + stats.shadow_rays;
  // Throughput over tracing alone: set-up (kernels built on a cold start, the
  // structure, uploads) and the kernels' first launches (compiled there by the
  // driver on a cold start) are reported apart from it.
  const double tracing = std::max(0.0, stats.trace_seconds - stats.first_launch_seconds);
  const double mrays = tracing > 0.0 ? static_cast<double>(total) / tracing / 1e6 : 0.0;
  const char* accel_name = prismAccelName(static_cast<PrismAccel>(stats.accel));
  const std::string accel = !accel_name                                                 ? "?"
                            : stats.accel == PRISM_ACCEL_BVH && options.bounds == PRISM_BOUNDS_KDOP
                                ? std::string(accel_name) + " (k-DOP bounds)"
                                : std::string(accel_name);
  const char* first_hit = prismFirstHitName(static_cast<PrismFirstHit>(stats.first_hit_used));
  const char* shadows = prismShadowsName(static_cast<PrismShadows>(stats.shadows_used));
  std::printf(
      "prism: rendered %ux%u at %u spp on %s with %s (built in %.2f s) in %.2f s (kernels %.2f s, first launches "
      "%.2f s): "
      "%s, %.3f rays/pixel, first hit by %s, shadows by %s, set-up %.2f s, tracing %.2f s; "
      "%llu primary, %llu reflected, %llu refracted, %llu shadow rays, %.2f Mrays/s -> %s\n",
      static_cast<unsigned>(options.width), static_cast<unsigned>(options.height),
      static_cast<unsigned>(options.spp), devices.c_str(), accel.c_str(), stats.accel_build_seconds,
      stats.seconds, stats.kernel_build_seconds, stats.first_launch_seconds, samplingText(options).c_str(),
      stats.rays_per_pixel, first_hit ? first_hit : "?", shadows ? shadows : "?", stats.setup_seconds, tracing,
      static_cast<unsigned long long>(stats.primary_rays),
      static_cast<unsigned long long>(stats.reflected_rays), static_cast<unsigned long long>(stats.refracted_rays),
      static_cast<unsigned long long>(stats.shadow_rays), mrays, output_path.c_str());
}

// --stats: the render's time by stage, each kernel's device time from its
// profiling events, and what is left (host work, waits, transfers).
void printStageTimes(PrismContext context, const PrismRenderStats& stats) {
  std::printf("prism: stages: set-up %.3f s (kernels built or loaded %.3f s, %s built %.3f s), tracing %.3f s "
              "(first launches %.3f s)\n",
              stats.setup_seconds, stats.kernel_build_seconds,
              prismAccelName(static_cast<PrismAccel>(stats.accel)) ? prismAccelName(static_cast<PrismAccel>(stats.accel))
                                                                   : "structure",
              stats.accel_build_seconds, stats.trace_seconds, stats.first_launch_seconds);
  uint32_t count = 0;
  if (prismGetKernelTimeCount(context, &count) != PRISM_OK) return;
  std::printf("  %-16s %10s %12s %10s\n", "kernel", "launches", "device s", "of tracing");
  double device = 0;
  for (uint32_t i = 0; i < count; ++i) {
    const char* name = nullptr;
    double seconds = 0;
    uint64_t launches = 0;
    if (prismGetKernelTime(context, i, &name, &seconds, &launches) != PRISM_OK) return;
    device += seconds;
    std::printf("  %-16s %10llu %12.4f %9.1f%%\n", name, static_cast<unsigned long long>(launches), seconds,
                stats.trace_seconds > 0 ? 100.0 * seconds / stats.trace_seconds : 0.0);
  }
  const double rest = std::max(0.0, stats.trace_seconds - device);
  std::printf("  %-16s %10s %12.4f %9.1f%%  (host work, waits and transfers)\n", "other", "", rest,
              stats.trace_seconds > 0 ? 100.0 * rest / stats.trace_seconds : 0.0);
}

// --stats with several devices (or MPI ranks): how the frame was shared.
void printDeviceShares(PrismContext context) {
  uint32_t count = 0;
  if (prismGetRenderDeviceShareCount(context, &count) != PRISM_OK || count < 2) return;
  std::printf("  %-40s %8s %12s %10s %10s\n", "device", "units", "samples", "busy s", "film MiB");
  for (uint32_t i = 0; i < count; ++i) {
    PrismDeviceShare share{};
    share.struct_size = sizeof share;
    if (prismGetRenderDeviceShare(context, i, &share) != PRISM_OK) return;
    std::printf("  [%u] %-36.36s %8llu %12llu %10.3f %10.1f%s\n", i, share.device,
                static_cast<unsigned long long>(share.units), static_cast<unsigned long long>(share.samples),
                share.busy_seconds, static_cast<double>(share.film_bytes) / (1024.0 * 1024.0),
                share.failed ? "  (failed)" : "");
  }
}

// --check-nan: the first non-finite contribution with its ray, and the first
// pixel of the image that is not finite. Returns whether either was found.
bool reportNotFinite(PrismContext context, const PrismRenderOptions& options, const std::vector<float>& rgba) {
  static const char* const kKinds[] = {"primary", "reflected", "refracted", "shadow"};
  PrismNanReport report{};
  report.struct_size = sizeof report;
  if (prismGetNanReport(context, &report) != PRISM_OK) {
    printError(lastErrorForUser());
    return true;
  }
  if (report.found) {
    const char* kind = report.ray_kind < 4 ? kKinds[report.ray_kind] : "?";
    std::fprintf(stderr,
                 "prism: check-nan: sample %llu (film %.4g, %.4g; pixel %d, %d) got (%g, %g, %g, %g) from a %s ray at "
                 "depth %u, origin (%.9g, %.9g, %.9g), direction (%.9g, %.9g, %.9g)",
                 static_cast<unsigned long long>(report.sample), report.film_x, report.film_y,
                 static_cast<int>(std::floor(report.film_x)), static_cast<int>(std::floor(report.film_y)),
                 report.value[0], report.value[1], report.value[2], report.value[3], kind, report.ray_depth,
                 report.origin[0], report.origin[1], report.origin[2], report.direction[0], report.direction[1],
                 report.direction[2]);
    if (report.primitive >= 0)
      std::fprintf(stderr, ", which hit primitive %d at t = %.9g\n", report.primitive, report.t);
    else
      std::fprintf(stderr, "%s\n", report.ray_kind == 3 ? "" : ", which hit nothing");
  }
  const size_t pixels = static_cast<size_t>(options.width) * options.height;
  for (size_t p = 0; p < pixels; ++p) {
    const float* px = &rgba[4 * p];
    if (std::isfinite(px[0]) && std::isfinite(px[1]) && std::isfinite(px[2]) && std::isfinite(px[3])) continue;
    std::fprintf(stderr, "prism: check-nan: pixel %zu, %zu of the image is (%g, %g, %g, %g)\n", p % options.width,
                 p / options.width, px[0], px[1], px[2], px[3]);
    return true;
  }
  if (!report.found) std::fprintf(stderr, "prism: check-nan: every contribution and pixel is finite\n");
  return report.found != 0;
}

// The frames of the scene to render: all, or --frames (checked against the
// scene's count).
struct FrameRange {
  uint32_t first = 0, last = 0, total = 1;
  uint32_t count() const { return last - first + 1; }
};

FrameRange framesToRender(const RenderRequest& request, PrismScene scene) {
  FrameRange range;
  if (prismGetFrameCount(scene, &range.total) != PRISM_OK || range.total == 0) range.total = 1;
  range.last = range.total - 1;
  if (!request.frames) return range;
  if (request.frames->second >= range.total)
    throw UsageError("--frames: the scene has " +
                     (range.total == 1 ? std::string("one frame (0)")
                                       : std::to_string(range.total) + " frames (0 to " +
                                             std::to_string(range.total - 1) + ")") +
                     ", so " + std::to_string(request.frames->second) + " is not one of them");
  range.first = request.frames->first;
  range.last = request.frames->second;
  return range;
}

// What every frame of a render shares: the request, the options, the devices
// in words, whether this process writes and reports, whether it shows the
// progress bar (one process of a run), and the animation's length (for the
// output's name).
struct FrameOutput {
  const RenderRequest& request;
  const PrismRenderOptions& options;
  const std::string& devices;
  bool speaks;
  bool progress;
  uint32_t frames;
  bool shared_part = false;  // the frame is shared by a group of ranks (sharedPartRendered once rendered)
};

// Renders one frame and, where this process reports, writes it and prints its
// summary. Returns an exit code (kExitNotFinite: written, with a --check-nan finding).
int renderFrame(const FrameOutput& out, PrismContext context, PrismScene scene, uint32_t frame) {
  const RenderRequest& request = out.request;
  const PrismRenderOptions& options = out.options;
  std::vector<float> rgba(static_cast<size_t>(options.width) * options.height * 4);
  PrismRenderStats stats{};
  stats.struct_size = sizeof stats;
  PrismStatus status;
  {
    ProgressBar bar(!request.quiet && out.progress && stderrIsTerminal());
    if (prismSetProgressCallback(context, onProgress, &bar) != PRISM_OK) return failWithLastError();
    status = prismRender(context, scene, &options, rgba.data(), &stats);
    prismSetProgressCallback(context, nullptr, nullptr);
    bar.finish();
    if (status != PRISM_OK && InterruptGuard::requested()) {
      if (out.frames > 1)
        std::fprintf(stderr, "prism: interrupted; frame %u not written\n", static_cast<unsigned>(frame));
      else
        std::fprintf(stderr, "prism: interrupted; nothing written\n");
      return kExitInterrupted;
    }
  }
  if (status != PRISM_OK) return failWithLastError();
  frameRendered();
  if (out.shared_part) sharedPartRendered();
  if (!out.speaks) return kExitOk;
  uint32_t warnings = 0;
  prismGetRenderWarningCount(context, &warnings);
  for (uint32_t i = 0; i < warnings; ++i) {
    const char* message = nullptr;
    if (prismGetRenderWarning(context, i, &message) == PRISM_OK) std::fprintf(stderr, "prism: warning: %s\n", message);
  }

  const std::string path = frameOutputPath(request.output_path, frame, out.frames);
  const int written = writeOutput(request, path, context, options, rgba);
  if (written != kExitOk) return written;
  if (!request.quiet) printSummary(path, options, out.devices, stats);
  if (request.stats) {
    printStageTimes(context, stats);
    printDeviceShares(context);
  }
  if (request.check_nan && reportNotFinite(context, options, rgba)) return kExitNotFinite;
  return kExitOk;
}

}  // namespace

int runRender(const std::vector<std::string>& args) {
  const RenderRequest request = parseRenderArgs(args);
  if (request.help) {
    std::fputs(kRenderHelp, stdout);
    return kExitOk;
  }
  const Ranks ranks = startRanks();
  // Under mpirun, rank 0 alone writes and speaks; the others render their part.
  const bool speaks = ranks.rank == 0;
  if (speaks && !outputFolderExists(request.output_path)) {
    printError("cannot write '" + request.output_path + "': folder '" +
               std::filesystem::path(request.output_path).parent_path().string() + "' does not exist");
    return kExitFailure;
  }
  const std::string ext = lowerExtension(request.output_path);
  if (speaks && request.aov && ext == ".hdr" && (*request.aov == PRISM_AOV_DEPTH || *request.aov == PRISM_AOV_PRIMID)) {
    printWarning("'" + request.output_path + "': .hdr stores no +inf or negative values, so misses will not " +
                 "read back as +inf (depth) or -1 (primid); .exr keeps them");
  }

  {
    // The flags checked first against the default options, so that a mistake in
    // them costs no scene loading; combinations with the scene's own values are
    // checked again once it is read.
    PrismScene raw_defaults = nullptr;
    if (prismNewScene(&raw_defaults) != PRISM_OK) return failWithLastError();
    const SceneHandle defaults(raw_defaults);
    PrismRenderOptions default_options{};
    default_options.struct_size = sizeof default_options;
    if (prismGetRenderOptions(defaults.get(), &default_options) != PRISM_OK) return failWithLastError();
    if (!applyOverrides(request, default_options)) return kExitFailure;
  }

  PrismScene raw_scene = nullptr;
  // A .json file is a scene; anything else is a mesh file shown on its own.
  const bool is_scene = lowerExtension(request.scene_path) == ".json";
  const PrismStatus loaded = is_scene ? prismLoadScene(request.scene_path.c_str(), &raw_scene)
                                      : prismLoadMeshAsScene(request.scene_path.c_str(), &raw_scene);
  if (loaded != PRISM_OK) return failWithLastError();
  const SceneHandle scene(raw_scene);
  if (speaks) printSceneWarnings(scene.get());

  PrismRenderOptions options{};
  options.struct_size = sizeof options;
  if (prismGetRenderOptions(scene.get(), &options) != PRISM_OK) return failWithLastError();
  // Checked before the image is allocated (32768 x 32768 would take 16 GiB first).
  if (!applyOverrides(request, options)) return kExitFailure;
  if (!applyCameraOverrides(request, scene.get())) return failWithLastError();
  const FrameRange frames = framesToRender(request, scene.get());

  PrismContextOptions context_options{};
  prismDefaultContextOptions(&context_options);
  context_options.use_kernel_cache = request.use_kernel_cache ? 1 : 0;
  PrismContext raw_context = nullptr;
  // --device, else the scene's render.device, else the default.
  const char* scene_device = nullptr;
  if (prismGetSceneDevice(scene.get(), &scene_device) != PRISM_OK) return failWithLastError();
  const char* selector = !request.device.empty() ? request.device.c_str()
                         : scene_device && *scene_device ? scene_device
                                                         : nullptr;
  if (prismCreateContext(selector, &context_options, &raw_context) != PRISM_OK) return failWithLastError();
  const ContextHandle context(raw_context);
  std::string devices = devicesText(context.get());

  // Under mpirun, an animation's frames are dealt to the ranks (frame_deal.h):
  // whole frames in turns, each rank writing its own, then the frames left
  // over each shared by a group of ranks, its first rank writing it; a single
  // frame is shared by all the ranks and written by rank 0.
  const bool deal_frames = ranks.shared() && frames.count() > 1;
  const FrameDeal deal = dealFrames(frames.count(), deal_frames ? ranks.rank : 0, deal_frames ? ranks.size : 1);
  PrismFrameParts group_parts{};
  std::string group_devices;
  if (deal_frames) {
    ranksWorkAlone();
    if (frames.count() % ranks.size != 0) group_parts = groupFrameParts(deal);  // every rank, before any frame
    const std::string alone =
        "MPI rank " + std::to_string(ranks.rank) + " of " + std::to_string(ranks.size) + " (" + devices + ")";
    group_devices = deal.group_parts > 1 ? std::to_string(deal.group_parts) + " MPI ranks (rank " +
                                               std::to_string(ranks.rank) + " on " + devices +
                                               (group_parts.compare_swap ? "; units dealt as devices come free)"
                                                                         : "; a stretch of units each)")
                                         : alone;
    devices = alone;
  } else if (ranks.shared()) {
    // Every rank renders its part of the frame; rank 0 writes it and reports.
    const PrismFrameParts parts = frameParts(ranks);
    if (prismSetFrameParts(context.get(), &parts) != PRISM_OK) return failWithLastError();
    devices = std::to_string(ranks.size) + " MPI ranks (rank 0 on " + devices +
              (parts.compare_swap ? "; units dealt as devices come free)" : "; a stretch of units each)");
  }

  // Each rank that writes frames checks where they go (rank 0 did).
  const bool writes = !deal.whole.empty() || (deal.shares && deal.group_part == 0);
  if (deal_frames && !speaks && writes && !outputFolderExists(request.output_path)) {
    printError("cannot write '" + request.output_path + "': folder '" +
               std::filesystem::path(request.output_path).parent_path().string() + "' does not exist on rank " +
               std::to_string(ranks.rank));
    return kExitFailure;
  }

  const FrameOutput output{request, options, devices, deal_frames || speaks, speaks, frames.total};
  // One guard for all frames: a Ctrl-C between two frames stops the next.
  const InterruptGuard interrupt;
  int outcome = kExitOk;
  auto render = [&](const FrameOutput& out, uint32_t frame) {
    if (InterruptGuard::requested()) {
      std::fprintf(stderr, "prism: interrupted; frame %u and those after it not written\n",
                   static_cast<unsigned>(frame));
      return kExitInterrupted;
    }
    SceneHandle frame_scene;
    if (frames.total > 1) {
      PrismScene raw_frame = nullptr;
      if (prismGetFrameScene(scene.get(), frame, &raw_frame) != PRISM_OK) return failWithLastError();
      frame_scene.reset(raw_frame);
    }
    const int code = renderFrame(out, context.get(), frame_scene ? frame_scene.get() : scene.get(), frame);
    if (code == kExitNotFinite) {
      outcome = code;  // the image is written; the other frames still are
      return kExitOk;
    }
    return code;
  };
  for (uint32_t k : deal.whole)
    if (const int code = render(output, frames.first + k); code != kExitOk) return code;
  if (deal.shares) {
    // The group's first rank writes and reports the frame; the others render their part.
    if (prismSetFrameParts(context.get(), &group_parts) != PRISM_OK) return failWithLastError();
    const FrameOutput shared{request, options, group_devices, deal.group_part == 0, speaks, frames.total, true};
    if (const int code = render(shared, frames.first + deal.shared_frame); code != kExitOk) return code;
  }
  return outcome;
}

}  // namespace prism_cli
