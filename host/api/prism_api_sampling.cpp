// The C API's names of the anti-aliasing modes, reconstruction filters and
// first-hit modes and the polygons' inside tests (include/prism.h).
#include <cstring>
#include <string>

#include "api/api_boundary.h"
#include "api/api_enums.h"
#include "prism.h"

using namespace prism;

namespace {

template <typename E>
struct Named {
  const char* name;
  E value;
};

const Named<PrismAa> kAaNames[] = {{"auto", PRISM_AA_AUTO},         {"none", PRISM_AA_NONE},
                                   {"grid", PRISM_AA_GRID},         {"quincunx", PRISM_AA_QUINCUNX},
                                   {"adaptive", PRISM_AA_ADAPTIVE}, {"jitter", PRISM_AA_JITTER},
                                   {"poisson", PRISM_AA_POISSON},   {"random", PRISM_AA_RANDOM}};
const Named<PrismFilter> kFilterNames[] = {{"box", PRISM_FILTER_BOX},
                                           {"tent", PRISM_FILTER_TENT},
                                           {"gaussian", PRISM_FILTER_GAUSSIAN},
                                           {"mitchell", PRISM_FILTER_MITCHELL}};
const Named<PrismFirstHit> kFirstHitNames[] = {
    {"auto", PRISM_FIRST_HIT_AUTO}, {"zbuffer", PRISM_FIRST_HIT_ZBUFFER}, {"trace", PRISM_FIRST_HIT_TRACE}};
const Named<PrismShadows> kShadowsNames[] = {
    {"auto", PRISM_SHADOWS_AUTO}, {"accel", PRISM_SHADOWS_ACCEL}, {"lightbuffer", PRISM_SHADOWS_LIGHTBUFFER}};
const Named<PrismBounds> kBoundsNames[] = {{"aabb", PRISM_BOUNDS_AABB}, {"kdop", PRISM_BOUNDS_KDOP}};
const Named<PrismInsideTest> kInsideTestTable[] = {
    {"crossing", PRISM_INSIDE_CROSSING}, {"radial", PRISM_INSIDE_RADIAL}, {"left-right", PRISM_INSIDE_LEFT_RIGHT}};

template <typename E, size_t N>
PrismStatus parse(const Named<E> (&table)[N], const char* function, const char* what, const char* name, E* out) {
  if (!name || !out) return fail(PRISM_ERROR_INVALID_ARGUMENT, std::string(function) + ": NULL argument");
  std::string valid;
  for (const Named<E>& entry : table) {
    if (std::strcmp(name, entry.name) == 0) {
      *out = entry.value;
      return PRISM_OK;
    }
    valid += (valid.empty() ? "" : ", ") + std::string(entry.name);
  }
  return fail(PRISM_ERROR_INVALID_ARGUMENT, std::string("unknown ") + what + " '" + name + "' (expected " + valid + ")");
}

template <typename E, size_t N>
const char* nameOf(const Named<E> (&table)[N], std::int64_t value) {
  for (const Named<E>& entry : table)
    if (static_cast<std::int64_t>(entry.value) == value) return entry.name;
  return nullptr;
}

}  // namespace

const char* aaNameOf(std::int64_t value) { return nameOf(kAaNames, value); }
const char* filterNameOf(std::int64_t value) { return nameOf(kFilterNames, value); }
const char* firstHitNameOf(std::int64_t value) { return nameOf(kFirstHitNames, value); }
const char* insideTestNameOf(std::int64_t value) { return nameOf(kInsideTestTable, value); }
const char* shadowsNameOf(std::int64_t value) { return nameOf(kShadowsNames, value); }
const char* boundsNameOf(std::int64_t value) { return nameOf(kBoundsNames, value); }

extern "C" {

PRISM_API PrismStatus prismParseAa(const char* name, PrismAa* aa) {
  return parse(kAaNames, "prismParseAa", "anti-aliasing mode", name, aa);
}
PRISM_API const char* prismAaName(PrismAa aa) { return aaNameOf(enumValue(aa)); }

PRISM_API PrismStatus prismParseFilter(const char* name, PrismFilter* filter) {
  return parse(kFilterNames, "prismParseFilter", "filter", name, filter);
}
PRISM_API const char* prismFilterName(PrismFilter filter) { return filterNameOf(enumValue(filter)); }

PRISM_API PrismStatus prismParseFirstHit(const char* name, PrismFirstHit* first_hit) {
  return parse(kFirstHitNames, "prismParseFirstHit", "first-hit mode", name, first_hit);
}
PRISM_API const char* prismFirstHitName(PrismFirstHit first_hit) { return firstHitNameOf(enumValue(first_hit)); }

PRISM_API PrismStatus prismParseInsideTest(const char* name, PrismInsideTest* inside_test) {
  return parse(kInsideTestTable, "prismParseInsideTest", "inside test", name, inside_test);
}
PRISM_API const char* prismInsideTestName(PrismInsideTest inside_test) {
  return insideTestNameOf(enumValue(inside_test));
}
PRISM_API PrismStatus prismParseShadows(const char* name, PrismShadows* shadows) {
  return parse(kShadowsNames, "prismParseShadows", "shadow mode", name, shadows);
}
PRISM_API const char* prismShadowsName(PrismShadows shadows) { return shadowsNameOf(enumValue(shadows)); }
PRISM_API PrismStatus prismParseBounds(const char* name, PrismBounds* bounds) {
  return parse(kBoundsNames, "prismParseBounds", "bounds", name, bounds);
}
PRISM_API const char* prismBoundsName(PrismBounds bounds) { return boundsNameOf(enumValue(bounds)); }

}  // extern "C"
