#include "scene/value_check.h"

#include <cmath>

namespace prism {

std::string vectorProblem(const Vec3& v, const char* name) {
  if (!(std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z))) return std::string(name) + " must be finite";
  if (!(std::fabs(v.x) <= kMaxCoordinate && std::fabs(v.y) <= kMaxCoordinate && std::fabs(v.z) <= kMaxCoordinate))
    return std::string(name) + " must have coordinates of at most 1e15 in magnitude";
  return "";
}

}  // namespace prism
