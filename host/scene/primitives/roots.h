// The double-precision helpers the kinds' reference intersections share.
#pragma once

#include <optional>
#include <utility>

namespace prism {

// The nearer of two ray parameters inside (tmin, tmax), if either is.
inline std::optional<double> nearestInside(double t0, double t1, double tmin, double tmax) {
  if (t0 > t1) std::swap(t0, t1);
  if (t0 > tmin && t0 < tmax) return t0;
  if (t1 > tmin && t1 < tmax) return t1;
  return std::nullopt;
}

}  // namespace prism
