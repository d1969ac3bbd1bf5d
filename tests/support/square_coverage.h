// Exact area of a unit square on one side of a straight edge: the closed-form
// reference for anti-aliasing tests.
#pragma once

#include <cmath>
#include <utility>
#include <vector>

namespace prism::test {

// Area of [x0, x0+1] x [y0, y0+1] on the side n.(p - q) >= 0 of the line through
// q with normal n, by clipping the square (Sutherland-Hodgman) and the shoelace formula.
inline double squareCoverage(double x0, double y0, double qx, double qy, double nx, double ny) {
  std::vector<std::pair<double, double>> poly = {{x0, y0}, {x0 + 1, y0}, {x0 + 1, y0 + 1}, {x0, y0 + 1}}, out;
  auto side = [&](const std::pair<double, double>& p) { return nx * (p.first - qx) + ny * (p.second - qy); };
  for (size_t k = 0; k < poly.size(); ++k) {
    auto a = poly[k], b = poly[(k + 1) % poly.size()];
    double sa = side(a), sb = side(b);
    if (sa >= 0) out.push_back(a);
    if ((sa >= 0) != (sb >= 0)) {
      double t = sa / (sa - sb);
      out.push_back({a.first + t * (b.first - a.first), a.second + t * (b.second - a.second)});
    }
  }
  double area = 0;
  for (size_t k = 0; k < out.size(); ++k) {
    auto a = out[k], b = out[(k + 1) % out.size()];
    area += a.first * b.second - b.first * a.second;
  }
  return std::fabs(area) / 2;
}

}  // namespace prism::test
