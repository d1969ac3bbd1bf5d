// The C API (include/prism.h). Each function checks its arguments, then runs
// its body inside guarded() (api_boundary.h).
#include <atomic>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <limits>

#include "api/api_boundary.h"
#include "api/api_enums.h"
#include "api/api_handles.h"
#include "api/api_render.h"
#include "device/device_list.h"
#include "render/image_writer.h"
#include "scene/animation.h"
#include "scene_format/scene_loader.h"

using namespace prism;

namespace {

#define PRISM_REQUIRE(cond, message) \
  if (!(cond)) return fail(PRISM_ERROR_INVALID_ARGUMENT, message)

void copyString(char* dst, size_t capacity, const std::string& src) {
  std::strncpy(dst, src.c_str(), capacity - 1);
  dst[capacity - 1] = '\0';
}

PrismDeviceInfo toInfo(const DeviceDescription& d) {
  PrismDeviceInfo info;
  std::memset(&info, 0, sizeof(info));
  info.index = d.index;
  copyString(info.name, sizeof(info.name), d.name);
  copyString(info.vendor, sizeof(info.vendor), d.vendor);
  copyString(info.platform, sizeof(info.platform), d.platform_name);
  copyString(info.driver_version, sizeof(info.driver_version), d.driver_version);
  copyString(info.opencl_c_version, sizeof(info.opencl_c_version), d.opencl_c_version);
  if (d.type & CL_DEVICE_TYPE_GPU)
    info.type = PRISM_DEVICE_GPU;
  else if (d.type & CL_DEVICE_TYPE_CPU)
    info.type = PRISM_DEVICE_CPU;
  else if (d.type & CL_DEVICE_TYPE_ACCELERATOR)
    info.type = PRISM_DEVICE_ACCELERATOR;
  else
    info.type = PRISM_DEVICE_OTHER;
  info.compute_units = d.compute_units;
  info.global_memory_bytes = d.global_memory_bytes;
  return info;
}

static_assert(PRISM_AA_NONE == static_cast<int>(AaMode::None) + 1 && PRISM_AA_GRID == static_cast<int>(AaMode::Grid) + 1 &&
                  PRISM_AA_QUINCUNX == static_cast<int>(AaMode::Quincunx) + 1 &&
                  PRISM_AA_ADAPTIVE == static_cast<int>(AaMode::Adaptive) + 1 &&
                  PRISM_AA_JITTER == static_cast<int>(AaMode::Jitter) + 1 &&
                  PRISM_AA_POISSON == static_cast<int>(AaMode::Poisson) + 1 &&
                  PRISM_AA_RANDOM == static_cast<int>(AaMode::Random) + 1,
              "PrismAa is AaMode + 1");
static_assert(PRISM_INSIDE_CROSSING == static_cast<int>(InsideTest::Crossing) &&
                  PRISM_INSIDE_RADIAL == static_cast<int>(InsideTest::Radial) &&
                  PRISM_INSIDE_LEFT_RIGHT == static_cast<int>(InsideTest::LeftRight),
              "PrismInsideTest is InsideTest");
static_assert(PRISM_FILTER_BOX == static_cast<int>(FilterKind::Box) &&
                  PRISM_FILTER_TENT == static_cast<int>(FilterKind::Tent) &&
                  PRISM_FILTER_GAUSSIAN == static_cast<int>(FilterKind::Gaussian) &&
                  PRISM_FILTER_MITCHELL == static_cast<int>(FilterKind::Mitchell),
              "PrismFilter is FilterKind");

RenderOptions fromC(const PrismRenderOptions& o) {
  // Checked before they narrow to int, so that a refusal names the value given.
  validateCounts(o.width, o.height, o.spp, o.max_depth, o.aa_max_level);
  RenderOptions r;
  r.width = static_cast<int>(o.width);
  r.height = static_cast<int>(o.height);
  r.spp = static_cast<int>(o.spp);
  r.max_depth = static_cast<int>(o.max_depth);
  r.min_weight = o.min_weight;
  r.seed = o.seed;
  const char* accel = accelNameOf(o.accel);
  if (!accel) throw std::invalid_argument("render options: unknown accel value " + std::to_string(o.accel));
  r.accel = parseAccelKind(accel);
  // PrismAa is AaMode + 1, with 0 for the default (none at spp 1, jitter above).
  if (o.aa > PRISM_AA_RANDOM) throw std::invalid_argument("render options: unknown aa value " + std::to_string(o.aa));
  if (o.aa != PRISM_AA_AUTO) r.aa = static_cast<AaMode>(o.aa - 1);
  if (o.filter > PRISM_FILTER_MITCHELL)
    throw std::invalid_argument("render options: unknown filter value " + std::to_string(o.filter));
  r.filter = static_cast<FilterKind>(o.filter);
  const char* first_hit = firstHitNameOf(o.first_hit);
  if (!first_hit)
    throw std::invalid_argument("render options: unknown first_hit value " + std::to_string(o.first_hit));
  r.first_hit = parseFirstHitMode(first_hit);
  const char* inside_test = insideTestNameOf(o.inside_test);
  if (!inside_test || !tryParseInsideTest(inside_test, &r.inside_test))
    throw std::invalid_argument("render options: unknown inside_test value " + std::to_string(o.inside_test));
  const char* shadows = shadowsNameOf(o.shadows);
  if (!shadows) throw std::invalid_argument("render options: unknown shadows value " + std::to_string(o.shadows));
  r.shadows = parseShadowMode(shadows);
  const char* bounds = boundsNameOf(o.bounds);
  if (!bounds || !tryParseBoundsKind(bounds, &r.bounds))
    throw std::invalid_argument("render options: unknown bounds value " + std::to_string(o.bounds));
  r.aa_threshold = o.aa_threshold;
  r.aa_max_level = static_cast<int>(o.aa_max_level);
  r.profile = o.profile != 0;
  r.check_nan = o.check_nan != 0;
  return r;
}

PrismFirstHit toC(FirstHitMode mode) {
  PrismFirstHit out = PRISM_FIRST_HIT_AUTO;
  prismParseFirstHit(firstHitName(mode), &out);
  return out;
}

PrismStatus loadInto(Scene scene, PrismScene* out) {
  *out = new PrismSceneImpl{std::move(scene)};
  return PRISM_OK;
}

}  // namespace

RenderResult renderScene(PrismContext context, PrismScene scene, const PrismRenderOptions* options) {
  RenderOptions opts = options ? fromC(*options) : RenderOptions::fromScene(scene->scene);
  opts.validate();
  if (!context->renderer) {
    std::vector<Context*> devices{context->context.get()};
    for (auto& c : context->more) devices.push_back(c.get());
    context->renderer = std::make_unique<Renderer>(devices);
  }
  context->renderer->setFrameParts(context->parts);
  ProgressFn progress;
  if (context->progress) progress = [context](double f) { return context->progress(context->progress_user, f) == 0; };
  // FilmTooLarge: guarded() says OUT_OF_MEMORY.
  return withFirstFrame(scene->scene,
                        [&](const Scene& frame) { return context->renderer->render(frame, opts, progress); });
}

void fillStats(const RenderStats& from, double kernel_build_seconds, PrismRenderStats* stats) {
  size_t size = stats->struct_size;
  std::memset(stats, 0, size);
  stats->struct_size = size;
  stats->seconds = from.seconds;
  stats->kernel_build_seconds = kernel_build_seconds;
  stats->primary_rays = from.rays_by_kind[0];
  stats->reflected_rays = from.rays_by_kind[1];
  stats->refracted_rays = from.rays_by_kind[2];
  stats->shadow_rays = from.rays_by_kind[3];
  stats->waves = static_cast<uint32_t>(from.waves);
  for (int d = 0; d < 32; ++d) stats->rays_per_depth[d] = from.rays_per_depth[d];
  PrismAccel accel = PRISM_ACCEL_BVH;
  prismParseAccel(accelName(from.accel), &accel);
  stats->accel = accel;
  stats->accel_build_seconds = from.accel_stats.build_seconds;
  stats->rays_per_pixel = from.rays_per_pixel;
  stats->first_hit_used = toC(from.first_hit);
  stats->setup_seconds = from.setup_seconds;
  stats->trace_seconds = from.seconds - from.setup_seconds;
  stats->first_launch_seconds = from.first_launch_seconds;
  prismParseShadows(shadowModeName(from.shadows), reinterpret_cast<PrismShadows*>(&stats->shadows_used));
}

bool aovChannelsOf(std::int64_t value, std::uint32_t* channels) {
  switch (value) {
    case PRISM_AOV_DEPTH:
    case PRISM_AOV_PRIMID:
      *channels = 1;
      return true;
    case PRISM_AOV_NORMAL:
    case PRISM_AOV_ALBEDO:
      *channels = 3;
      return true;
  }
  return false;
}

unsigned long long nextSceneRevision() {
  static std::atomic<unsigned long long> next{1};
  return next.fetch_add(1, std::memory_order_relaxed);
}

extern "C" {

PRISM_API uint32_t prismGetVersion(void) {
  return (PRISM_VERSION_MAJOR << 16) | (PRISM_VERSION_MINOR << 8) | PRISM_VERSION_PATCH;
}

PRISM_API const char* prismGetVersionString(void) { return PRISM_VERSION_STRING; }

PRISM_API const char* prismGetLastError(void) { return lastError(); }

PRISM_API const char* prismStatusName(PrismStatus status) {
  switch (enumValue(status)) {
    case PRISM_OK: return "PRISM_OK";
    case PRISM_ERROR_INVALID_ARGUMENT: return "PRISM_ERROR_INVALID_ARGUMENT";
    case PRISM_ERROR_IO: return "PRISM_ERROR_IO";
    case PRISM_ERROR_PARSE: return "PRISM_ERROR_PARSE";
    case PRISM_ERROR_DEVICE: return "PRISM_ERROR_DEVICE";
    case PRISM_ERROR_KERNEL_BUILD: return "PRISM_ERROR_KERNEL_BUILD";
    case PRISM_ERROR_OUT_OF_MEMORY: return "PRISM_ERROR_OUT_OF_MEMORY";
    case PRISM_ERROR_INVALID_OPERATION: return "PRISM_ERROR_INVALID_OPERATION";
    case PRISM_ERROR_UNKNOWN: return "PRISM_ERROR_UNKNOWN";
  }
  return "PRISM_ERROR_UNKNOWN";
}

PRISM_API PrismStatus prismGetDeviceCount(uint32_t* count) {
  PRISM_REQUIRE(count, "prismGetDeviceCount: count is NULL");
  return guarded(__func__, [&] {
    *count = static_cast<uint32_t>(listDevices().size());
    return PRISM_OK;
  });
}

PRISM_API PrismStatus prismGetDeviceInfo(uint32_t index, PrismDeviceInfo* info) {
  PRISM_REQUIRE(info, "prismGetDeviceInfo: info is NULL");
  return guarded(__func__, [&] {
    auto devices = listDevices();
    if (index >= devices.size())
      return fail(PRISM_ERROR_INVALID_ARGUMENT, "prismGetDeviceInfo: no device " + std::to_string(index) + " (there are " +
                                                    std::to_string(devices.size()) + ")");
    *info = toInfo(devices[index]);
    return PRISM_OK;
  });
}

PRISM_API void prismDefaultContextOptions(PrismContextOptions* options) {
  if (!options) return;
  options->struct_size = sizeof(PrismContextOptions);
  options->use_kernel_cache = 1;
}

PRISM_API PrismStatus prismCreateContext(const char* selector, const PrismContextOptions* options,
                                         PrismContext* out_context) {
  PRISM_REQUIRE(out_context, "prismCreateContext: out_context is NULL");
  *out_context = nullptr;
  PRISM_REQUIRE(!options || options->struct_size >= sizeof(PrismContextOptions),
                "prismCreateContext: options->struct_size is too small (call prismDefaultContextOptions)");
  return guarded(__func__, [&] {
    bool use_cache = options ? options->use_kernel_cache != 0 : true;
    auto impl = std::make_unique<PrismContextImpl>();
    std::vector<DeviceDescription> devices = selectDevices(selector ? selector : "");
    impl->context = std::make_unique<Context>(devices.front(), use_cache);
    for (size_t i = 1; i < devices.size(); ++i) impl->more.push_back(std::make_unique<Context>(devices[i], use_cache));
    *out_context = impl.release();
    return PRISM_OK;
  });
}

PRISM_API void prismReleaseContext(PrismContext context) { delete context; }

PRISM_API PrismStatus prismGetContextDevice(PrismContext context, PrismDeviceInfo* info) {
  PRISM_REQUIRE(context && info, "prismGetContextDevice: NULL argument");
  *info = toInfo(context->context->device());
  return PRISM_OK;
}

PRISM_API PrismStatus prismGetContextDeviceCount(PrismContext context, uint32_t* count) {
  PRISM_REQUIRE(context && count, "prismGetContextDeviceCount: NULL argument");
  *count = static_cast<uint32_t>(1 + context->more.size());
  return PRISM_OK;
}

PRISM_API PrismStatus prismGetContextDeviceAt(PrismContext context, uint32_t position, PrismDeviceInfo* info) {
  PRISM_REQUIRE(context && info, "prismGetContextDeviceAt: NULL argument");
  PRISM_REQUIRE(position <= context->more.size(),
                "prismGetContextDeviceAt: position is not below prismGetContextDeviceCount's count");
  *info = toInfo(position == 0 ? context->context->device() : context->more[position - 1]->device());
  return PRISM_OK;
}

PRISM_API PrismStatus prismSetProgressCallback(PrismContext context, PrismProgressFn fn, void* user) {
  PRISM_REQUIRE(context, "prismSetProgressCallback: context is NULL");
  context->progress = fn;
  context->progress_user = user;
  return PRISM_OK;
}

PRISM_API PrismStatus prismSetFrameParts(PrismContext context, const PrismFrameParts* parts) {
  PRISM_REQUIRE(context, "prismSetFrameParts: context is NULL");
  if (!parts) {
    context->parts = FrameParts{};
    return PRISM_OK;
  }
  // A caller built before compare_swap existed passes a struct without it.
  PRISM_REQUIRE(parts->struct_size >= offsetof(PrismFrameParts, compare_swap),
                "prismSetFrameParts: parts->struct_size is too small (set it to sizeof(PrismFrameParts))");
  const PrismCompareSwapFn compare_swap = parts->struct_size >= sizeof(PrismFrameParts) ? parts->compare_swap : nullptr;
  PRISM_REQUIRE(parts->parts >= 1 && parts->part < parts->parts,
                "prismSetFrameParts: part " + std::to_string(parts->part) + " is not below parts " +
                    std::to_string(parts->parts) + " (parts counts the processes, at least 1)");
  PRISM_REQUIRE(parts->parts == 1 || parts->exchange, "prismSetFrameParts: exchange is NULL and parts > 1");
  FrameParts f;
  f.part = parts->part;
  f.parts = parts->parts;
  if (f.shared()) {
    // Field by field: a struct from before compare_swap is shorter.
    struct {
      std::uint32_t parts;
      PrismExchangeFn exchange;
      void* user;
    } const c{parts->parts, parts->exchange, parts->user};
    f.exchange = [c](bool to_all, const Bytes& mine) {
      struct Received {
        std::vector<Bytes> parts;
        bool out_of_memory = false;  // nothing may be thrown through the caller's C code
      } got;
      got.parts.resize(c.parts);
      const PrismReceiveFn receive = [](void* receiver, uint32_t part, const void* data, uint64_t size) {
        auto& into = *static_cast<Received*>(receiver);
        const auto* bytes = static_cast<const std::uint8_t*>(data);
        try {
          if (part < into.parts.size() && (bytes || size == 0)) into.parts[part].assign(bytes, bytes + size);
        } catch (const std::bad_alloc&) {
          into.out_of_memory = true;
        }
      };
      const int rc = c.exchange(c.user, to_all ? 1 : 0, mine.data(), mine.size(), receive, &got);
      if (rc != 0)
        throw std::runtime_error("the frame parts' exchange failed (PrismFrameParts.exchange returned " +
                                 std::to_string(rc) + ")");
      if (got.out_of_memory) throw std::bad_alloc();
      return std::move(got.parts);
    };
    if (compare_swap) {
      f.compare_swap = [compare_swap, user = c.user](std::uint32_t word, std::uint64_t expected,
                                                     std::uint64_t desired) {
        std::uint64_t found = 0;
        if (const int rc = compare_swap(user, word, expected, desired, &found); rc != 0)
          throw std::runtime_error("the frame parts' compare-and-swap failed (PrismFrameParts.compare_swap returned " +
                                   std::to_string(rc) + ")");
        return found;
      };
    }
  }
  context->parts = std::move(f);
  return PRISM_OK;
}

PRISM_API PrismStatus prismLoadScene(const char* path, PrismScene* out_scene) {
  PRISM_REQUIRE(out_scene, "prismLoadScene: out_scene is NULL");
  *out_scene = nullptr;
  PRISM_REQUIRE(path, "prismLoadScene: path is NULL");
  return guarded(__func__, [&] { return loadInto(loadSceneFile(path), out_scene); });
}

PRISM_API PrismStatus prismLoadSceneFromString(const char* json, const char* name, PrismScene* out_scene) {
  PRISM_REQUIRE(out_scene, "prismLoadSceneFromString: out_scene is NULL");
  *out_scene = nullptr;
  PRISM_REQUIRE(json, "prismLoadSceneFromString: json is NULL");
  return guarded(__func__, [&] { return loadInto(parseScene(json, name ? name : "<string>"), out_scene); });
}

PRISM_API void prismReleaseScene(PrismScene scene) { delete scene; }

PRISM_API PrismStatus prismGetSceneWarningCount(PrismScene scene, uint32_t* count) {
  PRISM_REQUIRE(scene && count, "prismGetSceneWarningCount: NULL argument");
  *count = static_cast<uint32_t>(scene->scene.warnings.size());
  return PRISM_OK;
}

PRISM_API PrismStatus prismGetSceneDevice(PrismScene scene, const char** selector) {
  PRISM_REQUIRE(scene && selector, "prismGetSceneDevice: NULL argument");
  *selector = scene->scene.render.device.c_str();
  return PRISM_OK;
}

PRISM_API PrismStatus prismGetFrameCount(PrismScene scene, uint32_t* count) {
  PRISM_REQUIRE(scene && count, "prismGetFrameCount: NULL argument");
  *count = static_cast<uint32_t>(scene->scene.animation.frames);
  return PRISM_OK;
}

PRISM_API PrismStatus prismGetFrameScene(PrismScene scene, uint32_t frame, PrismScene* out_scene) {
  PRISM_REQUIRE(out_scene, "prismGetFrameScene: out_scene is NULL");
  *out_scene = nullptr;
  PRISM_REQUIRE(scene, "prismGetFrameScene: scene is NULL");
  return guarded(__func__, [&] {
    return loadInto(sceneAtFrame(scene->scene, frame), out_scene);
  });
}

PRISM_API PrismStatus prismGetSceneObjectCount(PrismScene scene, uint32_t* count) {
  PRISM_REQUIRE(scene && count, "prismGetSceneObjectCount: NULL argument");
  *count = static_cast<uint32_t>(scene->scene.objects.size());
  return PRISM_OK;
}

PRISM_API PrismStatus prismGetSceneWarning(PrismScene scene, uint32_t index, const char** message) {
  PRISM_REQUIRE(scene && message, "prismGetSceneWarning: NULL argument");
  PRISM_REQUIRE(index < scene->scene.warnings.size(), "prismGetSceneWarning: index out of range");
  *message = scene->scene.warnings[index].c_str();
  return PRISM_OK;
}

PRISM_API PrismStatus prismGetRenderOptions(PrismScene scene, PrismRenderOptions* options) {
  PRISM_REQUIRE(scene && options, "prismGetRenderOptions: NULL argument");
  RenderOptions r = RenderOptions::fromScene(scene->scene);
  options->struct_size = sizeof(PrismRenderOptions);
  options->width = static_cast<uint32_t>(r.width);
  options->height = static_cast<uint32_t>(r.height);
  options->spp = static_cast<uint32_t>(r.spp);
  options->max_depth = static_cast<uint32_t>(r.max_depth);
  options->min_weight = static_cast<float>(r.min_weight);
  options->seed = r.seed;
  PrismAccel accel = PRISM_ACCEL_BVH;
  prismParseAccel(accelName(r.accel), &accel);
  options->accel = accel;
  options->aa = r.aa ? static_cast<uint32_t>(*r.aa) + 1 : static_cast<uint32_t>(PRISM_AA_AUTO);
  options->filter = static_cast<uint32_t>(r.filter);
  options->first_hit = toC(r.first_hit);
  options->inside_test = static_cast<uint32_t>(r.inside_test);
  PrismShadows shadows = PRISM_SHADOWS_AUTO;
  prismParseShadows(shadowModeName(r.shadows), &shadows);
  options->shadows = shadows;
  PrismBounds bounds = PRISM_BOUNDS_AABB;
  prismParseBounds(boundsKindName(r.bounds), &bounds);
  options->bounds = bounds;
  options->aa_threshold = static_cast<float>(r.aa_threshold);
  options->aa_max_level = static_cast<uint32_t>(r.aa_max_level);
  options->check_nan = r.check_nan ? 1u : 0u;
  return PRISM_OK;
}

PRISM_API PrismStatus prismCheckRenderOptions(const PrismRenderOptions* options) {
  PRISM_REQUIRE(options, "prismCheckRenderOptions: options is NULL");
  PRISM_REQUIRE(options->struct_size >= sizeof(PrismRenderOptions),
                "prismCheckRenderOptions: options->struct_size is too small (fill options with prismGetRenderOptions)");
  return guarded(__func__, [&] {
    fromC(*options).validate();
    return PRISM_OK;
  });
}

PRISM_API PrismStatus prismRender(PrismContext context, PrismScene scene, const PrismRenderOptions* options,
                                  float* rgba, PrismRenderStats* stats) {
  PRISM_REQUIRE(context && scene && rgba, "prismRender: NULL context, scene or rgba buffer");
  PRISM_REQUIRE(!options || options->struct_size >= sizeof(PrismRenderOptions),
                "prismRender: options->struct_size is too small (fill options with prismGetRenderOptions)");
  PRISM_REQUIRE(!stats || stats->struct_size >= sizeof(PrismRenderStats),
                "prismRender: stats->struct_size must be set to sizeof(PrismRenderStats)");
  return guarded(__func__, [&] {
    context->has_render = false;
    context->last = renderScene(context, scene, options);
    context->has_render = true;
    context->last_check_nan = options && options->check_nan != 0;
    const RenderResult& r = context->last;
    std::memcpy(rgba, r.rgba.data(), r.rgba.size() * sizeof(float));
    if (stats) fillStats(r.stats, context->context->takeBuildSeconds(), stats);
    return PRISM_OK;
  });
}

PRISM_API PrismStatus prismGetNanReport(PrismContext context, PrismNanReport* report) {
  PRISM_REQUIRE(context && report, "prismGetNanReport: NULL argument");
  PRISM_REQUIRE(report->struct_size >= sizeof(PrismNanReport),
                "prismGetNanReport: report->struct_size must be set to sizeof(PrismNanReport)");
  if (!context->has_render || !context->last_check_nan)
    return fail(PRISM_ERROR_INVALID_OPERATION, "prismGetNanReport: no render with check_nan yet (set PrismRenderOptions.check_nan)");
  const size_t size = report->struct_size;
  std::memset(report, 0, size);
  report->struct_size = size;
  report->primitive = -1;
  const std::optional<NanFinding>& nan = context->last.stats.nan;
  if (!nan) return PRISM_OK;
  report->found = 1;
  report->sample = nan->sample;
  report->film_x = nan->film_x;
  report->film_y = nan->film_y;
  report->ray_kind = static_cast<uint32_t>(nan->ray_kind);
  report->ray_depth = static_cast<uint32_t>(nan->depth);
  for (int i = 0; i < 3; ++i) {
    report->origin[i] = nan->origin[i];
    report->direction[i] = nan->direction[i];
  }
  report->primitive = nan->prim;
  report->t = nan->t;
  for (int i = 0; i < 4; ++i) report->value[i] = nan->value[i];
  return PRISM_OK;
}

PRISM_API PrismStatus prismGetKernelTimeCount(PrismContext context, uint32_t* count) {
  PRISM_REQUIRE(context && count, "prismGetKernelTimeCount: NULL argument");
  if (!context->has_render || context->last.stats.kernels.empty())
    return fail(PRISM_ERROR_INVALID_OPERATION, "prismGetKernelTimeCount: no profiled render yet (set PrismRenderOptions.profile)");
  *count = static_cast<uint32_t>(context->last.stats.kernels.size());
  return PRISM_OK;
}

PRISM_API PrismStatus prismGetKernelTime(PrismContext context, uint32_t index, const char** name, double* seconds,
                                         uint64_t* launches) {
  PRISM_REQUIRE(context && name && seconds && launches, "prismGetKernelTime: NULL argument");
  if (!context->has_render || context->last.stats.kernels.empty())
    return fail(PRISM_ERROR_INVALID_OPERATION, "prismGetKernelTime: no profiled render yet (set PrismRenderOptions.profile)");
  const std::vector<KernelTime>& kernels = context->last.stats.kernels;
  PRISM_REQUIRE(index < kernels.size(), "prismGetKernelTime: index " + std::to_string(index) + " is not below the " +
                                            std::to_string(kernels.size()) + " kernels timed");
  *name = kernels[index].name.c_str();
  *seconds = kernels[index].seconds;
  *launches = kernels[index].launches;
  return PRISM_OK;
}

PRISM_API PrismStatus prismGetRenderDeviceShareCount(PrismContext context, uint32_t* count) {
  PRISM_REQUIRE(context && count, "prismGetRenderDeviceShareCount: NULL argument");
  if (!context->has_render) return fail(PRISM_ERROR_INVALID_OPERATION, "prismGetRenderDeviceShareCount: no render yet");
  *count = static_cast<uint32_t>(context->last.stats.devices.size());
  return PRISM_OK;
}

PRISM_API PrismStatus prismGetRenderDeviceShare(PrismContext context, uint32_t position, PrismDeviceShare* share) {
  PRISM_REQUIRE(context && share, "prismGetRenderDeviceShare: NULL argument");
  // A struct from before film_bytes ends where film_bytes begins.
  PRISM_REQUIRE(share->struct_size >= offsetof(PrismDeviceShare, film_bytes),
                "prismGetRenderDeviceShare: share->struct_size is too small (set it to sizeof(PrismDeviceShare))");
  if (!context->has_render)
    return fail(PRISM_ERROR_INVALID_OPERATION, "prismGetRenderDeviceShare: no render yet");
  const std::vector<DeviceShare>& devices = context->last.stats.devices;
  PRISM_REQUIRE(position < devices.size(), "prismGetRenderDeviceShare: position " + std::to_string(position) +
                                               " is not below the " + std::to_string(devices.size()) +
                                               " devices of the render");
  const DeviceShare& d = devices[position];
  share->units = d.units;
  share->samples = d.samples;
  share->busy_seconds = d.busy_seconds;
  share->failed = d.failed ? 1 : 0;
  share->failure = d.failure.c_str();
  share->device = d.device.c_str();
  if (share->struct_size >= offsetof(PrismDeviceShare, film_bytes) + sizeof share->film_bytes)
    share->film_bytes = d.film_bytes;
  return PRISM_OK;
}

PRISM_API PrismStatus prismGetRenderWarningCount(PrismContext context, uint32_t* count) {
  PRISM_REQUIRE(context && count, "prismGetRenderWarningCount: NULL argument");
  if (!context->has_render) return fail(PRISM_ERROR_INVALID_OPERATION, "prismGetRenderWarningCount: no render yet");
  *count = static_cast<uint32_t>(context->last.stats.warnings.size());
  return PRISM_OK;
}

PRISM_API PrismStatus prismGetRenderWarning(PrismContext context, uint32_t index, const char** message) {
  PRISM_REQUIRE(context && message, "prismGetRenderWarning: NULL argument");
  if (!context->has_render) return fail(PRISM_ERROR_INVALID_OPERATION, "prismGetRenderWarning: no render yet");
  const std::vector<std::string>& warnings = context->last.stats.warnings;
  PRISM_REQUIRE(index < warnings.size(), "prismGetRenderWarning: index " + std::to_string(index) +
                                             " is not below the " + std::to_string(warnings.size()) + " warnings");
  *message = warnings[index].c_str();
  return PRISM_OK;
}

PRISM_API PrismStatus prismGetAovChannels(PrismAov aov, uint32_t* channels) {
  PRISM_REQUIRE(channels, "prismGetAovChannels: channels is NULL");
  if (aovChannelsOf(enumValue(aov), channels)) return PRISM_OK;
  return fail(PRISM_ERROR_INVALID_ARGUMENT, "prismGetAovChannels: unknown AOV " + std::to_string(enumValue(aov)));
}

PRISM_API PrismStatus prismParseAov(const char* name, PrismAov* aov) {
  PRISM_REQUIRE(name && aov, "prismParseAov: NULL argument");
  static const struct {
    const char* name;
    PrismAov aov;
  } table[] = {{"depth", PRISM_AOV_DEPTH}, {"normal", PRISM_AOV_NORMAL}, {"primid", PRISM_AOV_PRIMID},
               {"albedo", PRISM_AOV_ALBEDO}};
  for (const auto& entry : table)
    if (std::strcmp(name, entry.name) == 0) {
      *aov = entry.aov;
      return PRISM_OK;
    }
  return fail(PRISM_ERROR_INVALID_ARGUMENT,
              std::string("unknown AOV '") + name + "' (expected depth, normal, primid or albedo)");
}

PRISM_API PrismStatus prismGetAov(PrismContext context, PrismAov aov, float* out, size_t count) {
  PRISM_REQUIRE(context && out, "prismGetAov: NULL argument");
  if (!context->has_render) return fail(PRISM_ERROR_INVALID_OPERATION, "prismGetAov: nothing has been rendered yet");
  const int which = enumValue(aov);
  uint32_t channels = 0;
  PRISM_REQUIRE(aovChannelsOf(which, &channels), "prismGetAov: unknown AOV " + std::to_string(which));
  const RenderResult& r = context->last;
  size_t needed = static_cast<size_t>(r.width) * r.height * channels;
  PRISM_REQUIRE(count >= needed, "prismGetAov: buffer holds " + std::to_string(count) + " floats, the AOV needs " +
                                     std::to_string(needed));
  switch (which) {
    case PRISM_AOV_DEPTH: std::memcpy(out, r.depth.data(), needed * sizeof(float)); break;
    case PRISM_AOV_NORMAL: std::memcpy(out, r.normal.data(), needed * sizeof(float)); break;
    case PRISM_AOV_ALBEDO: std::memcpy(out, r.albedo.data(), needed * sizeof(float)); break;
    case PRISM_AOV_PRIMID:
      for (size_t i = 0; i < needed; ++i) out[i] = static_cast<float>(r.primid[i]);
      break;
  }
  return PRISM_OK;
}

PRISM_API PrismStatus prismWriteImage(const char* path, const float* pixels, uint32_t width, uint32_t height,
                                      uint32_t channels) {
  PRISM_REQUIRE(path && pixels, "prismWriteImage: NULL path or pixels");
  PRISM_REQUIRE(width > 0 && height > 0, "prismWriteImage: empty image");
  PRISM_REQUIRE(channels == 1 || channels == 3 || channels == 4, "prismWriteImage: channels must be 1, 3 or 4");
  return guarded(__func__, [&] {
    writeImage(path, pixels, static_cast<int>(width), static_cast<int>(height), static_cast<int>(channels));
    return PRISM_OK;
  });
}

}  // extern "C"
