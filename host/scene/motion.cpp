#include "scene/motion.h"

#include <algorithm>
#include <cmath>

namespace prism {
namespace {

using Mat3 = double[3][3];

// Shepperd's method: the unit quaternion of rotation matrix r.
void quaternionOf(const Mat3& r, double q[4]) {
  const double trace = r[0][0] + r[1][1] + r[2][2];
  if (trace > 0) {
    double s = std::sqrt(trace + 1.0) * 2;
    q[3] = 0.25 * s;
    q[0] = (r[2][1] - r[1][2]) / s;
    q[1] = (r[0][2] - r[2][0]) / s;
    q[2] = (r[1][0] - r[0][1]) / s;
  } else if (r[0][0] > r[1][1] && r[0][0] > r[2][2]) {
    double s = std::sqrt(1.0 + r[0][0] - r[1][1] - r[2][2]) * 2;
    q[3] = (r[2][1] - r[1][2]) / s;
    q[0] = 0.25 * s;
    q[1] = (r[0][1] + r[1][0]) / s;
    q[2] = (r[0][2] + r[2][0]) / s;
  } else if (r[1][1] > r[2][2]) {
    double s = std::sqrt(1.0 + r[1][1] - r[0][0] - r[2][2]) * 2;
    q[3] = (r[0][2] - r[2][0]) / s;
    q[0] = (r[0][1] + r[1][0]) / s;
    q[1] = 0.25 * s;
    q[2] = (r[1][2] + r[2][1]) / s;
  } else {
    double s = std::sqrt(1.0 + r[2][2] - r[0][0] - r[1][1]) * 2;
    q[3] = (r[1][0] - r[0][1]) / s;
    q[0] = (r[0][2] + r[2][0]) / s;
    q[1] = (r[1][2] + r[2][1]) / s;
    q[2] = 0.25 * s;
  }
  double n = std::sqrt(q[0] * q[0] + q[1] * q[1] + q[2] * q[2] + q[3] * q[3]);
  double sign = q[3] < 0 ? -1 : 1;  // q and -q are one rotation: keep w >= 0
  for (int i = 0; i < 4; ++i) q[i] *= sign / n;
}

void rotationOf(const double q[4], Mat3& r) {
  const double x = q[0], y = q[1], z = q[2], w = q[3];
  r[0][0] = 1 - 2 * (y * y + z * z);
  r[0][1] = 2 * (x * y - z * w);
  r[0][2] = 2 * (x * z + y * w);
  r[1][0] = 2 * (x * y + z * w);
  r[1][1] = 1 - 2 * (x * x + z * z);
  r[1][2] = 2 * (y * z - x * w);
  r[2][0] = 2 * (x * z - y * w);
  r[2][1] = 2 * (y * z + x * w);
  r[2][2] = 1 - 2 * (x * x + y * y);
}

}  // namespace

DecomposedTransform decompose(const Transform& t) {
  DecomposedTransform d;
  d.translate = {t.m[0][3], t.m[1][3], t.m[2][3]};
  Mat3 m, r;
  // A mirror has no rotation quaternion: take -M = (-R) S with det(-R) = +1,
  // and keep the sign in the stretch.
  const double sign = t.determinant() < 0 ? -1 : 1;
  Transform polar;  // its linear part converges to R; no translation
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      m[i][j] = t.m[i][j];
      polar.m[i][j] = sign * t.m[i][j];
    }
  // Polar decomposition by Higham's iteration R <- (R + R^-T) / 2.
  for (int iteration = 0; iteration < 100; ++iteration) {
    const Transform inverse = polar.inverse();
    double change = 0;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) {
        const double next = 0.5 * (polar.m[i][j] + inverse.m[j][i]);  // R^-T: the inverse, transposed
        change = std::max(change, std::fabs(next - polar.m[i][j]));
        r[i][j] = next;
      }
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) polar.m[i][j] = r[i][j];
    if (change < 1e-15) break;
  }
  quaternionOf(r, d.rotate);
  rotationOf(d.rotate, r);
  // S = R^T M (for a mirror, minus the polar stretch), symmetrised against rounding.
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      double s = 0;
      for (int k = 0; k < 3; ++k) s += r[k][i] * m[k][j];
      d.stretch[i][j] = s;
    }
  for (int i = 0; i < 3; ++i)
    for (int j = i + 1; j < 3; ++j) d.stretch[i][j] = d.stretch[j][i] = 0.5 * (d.stretch[i][j] + d.stretch[j][i]);
  return d;
}

double rotationAngle(const DecomposedTransform& a, const DecomposedTransform& b) {
  double c = 0;
  for (int i = 0; i < 4; ++i) c += a.rotate[i] * b.rotate[i];
  return 2 * std::acos(std::min(1.0, std::fabs(c)));
}

Transform interpolate(const DecomposedTransform& a, const DecomposedTransform& b, double s) {
  double qa[4], qb[4], q[4];
  std::copy(a.rotate, a.rotate + 4, qa);
  std::copy(b.rotate, b.rotate + 4, qb);
  double c = 0;
  for (int i = 0; i < 4; ++i) c += qa[i] * qb[i];
  if (c < 0) {
    for (double& x : qb) x = -x;
    c = -c;
  }
  if (c > 0.9995) {
    double n = 0;
    for (int i = 0; i < 4; ++i) {
      q[i] = qa[i] + s * (qb[i] - qa[i]);
      n += q[i] * q[i];
    }
    for (double& x : q) x /= std::sqrt(n);
  } else {
    const double theta = std::acos(c), st = std::sin(theta);
    for (int i = 0; i < 4; ++i) q[i] = (std::sin((1 - s) * theta) * qa[i] + std::sin(s * theta) * qb[i]) / st;
  }
  Mat3 r, st;
  rotationOf(q, r);
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) st[i][j] = a.stretch[i][j] + s * (b.stretch[i][j] - a.stretch[i][j]);
  Transform t;
  const Vec3 tr = a.translate + (b.translate - a.translate) * s;
  const double tv[3] = {tr.x, tr.y, tr.z};
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      double x = 0;
      for (int k = 0; k < 3; ++k) x += r[i][k] * st[k][j];
      t.m[i][j] = x;
    }
    t.m[i][3] = tv[i];
  }
  return t;
}

}  // namespace prism
