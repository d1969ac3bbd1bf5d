// Affine transform arithmetic for the host scene model (double precision).
// The renderer converts to float only when it uploads the inverse to the device.
#include "scene/transform.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace prism {

namespace {

// Exact values for whole multiples of 90 degrees, so that rotated axis-aligned
// geometry stays exactly axis-aligned (cos(pi/2) is 6e-17 otherwise).
void sinCosDegrees(double degrees, double* s, double* c) {
  const double quarter = degrees / 90.0;
  if (std::isfinite(quarter) && quarter == std::floor(quarter)) {
    const long long k = static_cast<long long>(std::fmod(quarter, 4.0));
    static const double kSin[4] = {0, 1, 0, -1};
    static const double kCos[4] = {1, 0, -1, 0};
    const int i = static_cast<int>((k % 4 + 4) % 4);
    *s = kSin[i];
    *c = kCos[i];
    return;
  }
  const double radians = degrees * (3.14159265358979323846 / 180.0);
  *s = std::sin(radians);
  *c = std::cos(radians);
}

}  // namespace

Transform Transform::translate(const Vec3& t) {
  Transform r;
  r.m[0][3] = t.x;
  r.m[1][3] = t.y;
  r.m[2][3] = t.z;
  return r;
}

Transform Transform::scale(const Vec3& s) {
  Transform r;
  r.m[0][0] = s.x;
  r.m[1][1] = s.y;
  r.m[2][2] = s.z;
  return r;
}

Transform Transform::rotate(const Vec3& axis, double degrees) {
  // Scaling by the largest component first keeps tiny or huge axes from
  // underflowing or overflowing in the length.
  const double big = std::max({std::fabs(axis.x), std::fabs(axis.y), std::fabs(axis.z)});
  const Vec3 a = normalize(axis / big);
  double s, c;
  sinCosDegrees(degrees, &s, &c);
  const double t = 1 - c;
  // Rodrigues' formula: R = c I + s [a]x + (1 - c) a a^T.
  Transform r;
  r.m[0][0] = c + t * a.x * a.x;
  r.m[0][1] = t * a.x * a.y - s * a.z;
  r.m[0][2] = t * a.x * a.z + s * a.y;
  r.m[1][0] = t * a.y * a.x + s * a.z;
  r.m[1][1] = c + t * a.y * a.y;
  r.m[1][2] = t * a.y * a.z - s * a.x;
  r.m[2][0] = t * a.z * a.x - s * a.y;
  r.m[2][1] = t * a.z * a.y + s * a.x;
  r.m[2][2] = c + t * a.z * a.z;
  return r;
}

bool Transform::isIdentity() const {
  const Transform id;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j)
      if (m[i][j] != id.m[i][j]) return false;
  return true;
}

Transform Transform::operator*(const Transform& o) const {
  Transform r;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 4; ++j) {
      double v = m[i][0] * o.m[0][j] + m[i][1] * o.m[1][j] + m[i][2] * o.m[2][j];
      if (j == 3) v += m[i][3];  // the implicit last row (0 0 0 1) of `o`
      r.m[i][j] = v;
    }
  }
  return r;
}

Vec3 Transform::applyPoint(const Vec3& p) const {
  return {m[0][0] * p.x + m[0][1] * p.y + m[0][2] * p.z + m[0][3],
          m[1][0] * p.x + m[1][1] * p.y + m[1][2] * p.z + m[1][3],
          m[2][0] * p.x + m[2][1] * p.y + m[2][2] * p.z + m[2][3]};
}

Vec3 Transform::applyVector(const Vec3& v) const {
  return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z, m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
          m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
}

double Transform::determinant() const {
  return m[0][0] * (m[1][1] * m[2][2] - m[1][2] * m[2][1]) -
         m[0][1] * (m[1][0] * m[2][2] - m[1][2] * m[2][0]) +
         m[0][2] * (m[1][0] * m[2][1] - m[1][1] * m[2][0]);
}

Transform Transform::inverse() const {
  const double inv_det = 1.0 / determinant();
  Transform r;
  // Linear part: adjugate divided by the determinant.
  r.m[0][0] = (m[1][1] * m[2][2] - m[1][2] * m[2][1]) * inv_det;
  r.m[0][1] = (m[0][2] * m[2][1] - m[0][1] * m[2][2]) * inv_det;
  r.m[0][2] = (m[0][1] * m[1][2] - m[0][2] * m[1][1]) * inv_det;
  r.m[1][0] = (m[1][2] * m[2][0] - m[1][0] * m[2][2]) * inv_det;
  r.m[1][1] = (m[0][0] * m[2][2] - m[0][2] * m[2][0]) * inv_det;
  r.m[1][2] = (m[0][2] * m[1][0] - m[0][0] * m[1][2]) * inv_det;
  r.m[2][0] = (m[1][0] * m[2][1] - m[1][1] * m[2][0]) * inv_det;
  r.m[2][1] = (m[0][1] * m[2][0] - m[0][0] * m[2][1]) * inv_det;
  r.m[2][2] = (m[0][0] * m[1][1] - m[0][1] * m[1][0]) * inv_det;
  // Translation: -R^-1 t.
  for (int i = 0; i < 3; ++i) r.m[i][3] = -(r.m[i][0] * m[0][3] + r.m[i][1] * m[1][3] + r.m[i][2] * m[2][3]);
  return r;
}

namespace {

bool entriesFit(const Transform& t) {
  for (const auto& row : t.m)
    for (double x : row)
      if (!(std::fabs(x) <= kMaxTransformEntry)) return false;  // NaN fails too
  return true;
}

}  // namespace

std::string transformProblem(const Transform& t) {
  if (!entriesFit(t))
    return "expected a transform with finite entries of at most 1e15 in magnitude, got one that overflows";
  double row_norms = 1;
  for (const auto& row : t.m) row_norms *= std::sqrt(row[0] * row[0] + row[1] * row[1] + row[2] * row[2]);
  const double det = t.determinant();
  // |det| <= product of row norms (Hadamard), so this ratio is scale-free.
  if (!(std::fabs(det) > 1e-12 * row_norms)) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", det);
    return std::string("expected an invertible transform, got a singular one (determinant ") + text + ")";
  }
  if (!entriesFit(t.inverse()))
    return "expected a transform whose inverse has entries of at most 1e15 in magnitude, got one too close to "
           "singular";
  return "";
}

}  // namespace prism
