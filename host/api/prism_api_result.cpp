// C API: render results that own their image, AOVs and statistics.
#include <cstring>
#include <memory>
#include <string>

#include "api/api_boundary.h"
#include "api/api_enums.h"
#include "api/api_render.h"

using namespace prism;

struct PrismResultImpl {
  RenderResult result;
  std::vector<float> primid;  // the primid AOV as floats, as prismGetAov gives it
  double kernel_build_seconds = 0;
};

namespace {

#define PRISM_REQUIRE(cond, message) \
  if (!(cond)) return fail(PRISM_ERROR_INVALID_ARGUMENT, message)

}  // namespace

extern "C" {

PRISM_API PrismStatus prismRenderToResult(PrismContext context, PrismScene scene, const PrismRenderOptions* options,
                                          PrismResult* out_result) {
  PRISM_REQUIRE(out_result, "prismRenderToResult: out_result is NULL");
  *out_result = nullptr;
  PRISM_REQUIRE(context && scene, "prismRenderToResult: NULL context or scene");
  PRISM_REQUIRE(!options || options->struct_size >= sizeof(PrismRenderOptions),
                "prismRenderToResult: options->struct_size is too small (fill options with prismGetRenderOptions)");
  return guarded(__func__, [&] {
    auto made = std::make_unique<PrismResultImpl>();
    made->result = renderScene(context, scene, options);
    made->kernel_build_seconds = context->context->takeBuildSeconds();
    made->primid.assign(made->result.primid.begin(), made->result.primid.end());
    *out_result = made.release();
    return PRISM_OK;
  });
}

PRISM_API PrismStatus prismGetResultSize(PrismResult result, uint32_t* width, uint32_t* height) {
  PRISM_REQUIRE(result && width && height, "prismGetResultSize: NULL argument");
  *width = static_cast<uint32_t>(result->result.width);
  *height = static_cast<uint32_t>(result->result.height);
  return PRISM_OK;
}

PRISM_API PrismStatus prismGetResultImage(PrismResult result, const float** rgba) {
  PRISM_REQUIRE(result && rgba, "prismGetResultImage: NULL argument");
  *rgba = result->result.rgba.data();
  return PRISM_OK;
}

PRISM_API PrismStatus prismGetResultAov(PrismResult result, PrismAov aov, const float** data, uint32_t* channels) {
  PRISM_REQUIRE(result && data && channels, "prismGetResultAov: NULL argument");
  const int which = enumValue(aov);
  if (!aovChannelsOf(which, channels))
    return fail(PRISM_ERROR_INVALID_ARGUMENT, "prismGetResultAov: unknown AOV " + std::to_string(which));
  const RenderResult& r = result->result;
  switch (which) {
    case PRISM_AOV_DEPTH: *data = r.depth.data(); break;
    case PRISM_AOV_NORMAL: *data = r.normal.data(); break;
    case PRISM_AOV_ALBEDO: *data = r.albedo.data(); break;
    case PRISM_AOV_PRIMID: *data = result->primid.data(); break;
  }
  return PRISM_OK;
}

PRISM_API PrismStatus prismGetResultStats(PrismResult result, PrismRenderStats* stats) {
  PRISM_REQUIRE(result && stats, "prismGetResultStats: NULL argument");
  PRISM_REQUIRE(stats->struct_size >= sizeof(PrismRenderStats),
                "prismGetResultStats: stats->struct_size must be set to sizeof(PrismRenderStats)");
  fillStats(result->result.stats, result->kernel_build_seconds, stats);
  return PRISM_OK;
}

PRISM_API PrismStatus prismGetResultWarningCount(PrismResult result, uint32_t* count) {
  PRISM_REQUIRE(result && count, "prismGetResultWarningCount: NULL argument");
  *count = static_cast<uint32_t>(result->result.stats.warnings.size());
  return PRISM_OK;
}

PRISM_API PrismStatus prismGetResultWarning(PrismResult result, uint32_t index, const char** message) {
  PRISM_REQUIRE(result && message, "prismGetResultWarning: NULL argument");
  const std::vector<std::string>& warnings = result->result.stats.warnings;
  PRISM_REQUIRE(index < warnings.size(), "prismGetResultWarning: index " + std::to_string(index) +
                                             " is not below the " + std::to_string(warnings.size()) + " warnings");
  *message = warnings[index].c_str();
  return PRISM_OK;
}

PRISM_API void prismReleaseResult(PrismResult result) { delete result; }

}  // extern "C"
