#include "scene/patches/bezier_patch.h"

#include <algorithm>
#include <cmath>

namespace prism {
namespace {

// Bernstein cubics and their derivatives at t.
void bernstein(double t, double b[4], double db[4]) {
  const double s = 1 - t;
  b[0] = s * s * s;
  b[1] = 3 * t * s * s;
  b[2] = 3 * t * t * s;
  b[3] = t * t * t;
  db[0] = -3 * s * s;
  db[1] = 3 * s * s - 6 * t * s;
  db[2] = 6 * t * s - 3 * t * t;
  db[3] = 3 * t * t;
}

Vec3 lerp(const Vec3& a, const Vec3& b, double t) { return a + (b - a) * t; }

// De Casteljau's step: the cubic c cut at t into its parts over [0, t] and
// [t, 1] (either may be null). They share the cut point; each keeps its end
// control point exactly.
void casteljau(const Vec3 c[4], double t, Vec3 left[4], Vec3 right[4]) {
  const Vec3 p01 = lerp(c[0], c[1], t), p12 = lerp(c[1], c[2], t), p23 = lerp(c[2], c[3], t);
  const Vec3 p012 = lerp(p01, p12, t), p123 = lerp(p12, p23, t), mid = lerp(p012, p123, t);
  if (left) left[0] = c[0], left[1] = p01, left[2] = p012, left[3] = mid;
  if (right) right[0] = mid, right[1] = p123, right[2] = p23, right[3] = c[3];
}

// The control points of the cubic c restricted to [a, b] (0 <= a < b <= 1).
void subCurve(const Vec3 c[4], double a, double b, Vec3 out[4]) {
  // Cut at b, keep [0, b]; then cut that at a / b and keep its second part.
  Vec3 l[4];
  casteljau(c, b, l, nullptr);
  if (b == 1) l[3] = c[3];  // (the cut at 1 rounds; the end is the end)
  if (a == 0) {
    std::copy(l, l + 4, out);
    return;
  }
  casteljau(l, a / b, nullptr, out);
}

double distance(const Vec3& a, const Vec3& b) { return length(a - b); }

}  // namespace

PatchPoint evaluate(const BezierPatch& patch, double u, double v) {
  double bu[4], dbu[4], bv[4], dbv[4];
  bernstein(u, bu, dbu);
  bernstein(v, bv, dbv);
  PatchPoint out{{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      const Vec3& c = patch.at(i, j);
      out.p = out.p + c * (bu[i] * bv[j]);
      out.du = out.du + c * (dbu[i] * bv[j]);
      out.dv = out.dv + c * (bu[i] * dbv[j]);
    }
  return out;
}

Vec3 patchNormal(const BezierPatch& patch, double u, double v) {
  for (double step : {0.0, 1e-6, 1e-4, 1e-2}) {
    const double uu = u + (0.5 - u) * step, vv = v + (0.5 - v) * step;
    const PatchPoint s = evaluate(patch, uu, vv);
    const Vec3 n = cross(s.du, s.dv);
    const double len = length(n);
    if (len > 0 && std::isfinite(len)) return n / len;
  }
  return {0, 0, 0};
}

Vec3 curvePoint(const Vec3 c[4], double t) {
  if (t == 0) return c[0];
  if (t == 1) return c[3];
  Vec3 left[4];
  casteljau(c, t, left, nullptr);
  return left[3];
}

BezierPatch subPatch(const BezierPatch& patch, double u0, double u1, double v0, double v1) {
  BezierPatch rows;  // cut along u first, column by column
  for (int j = 0; j < 4; ++j) {
    const Vec3 c[4] = {patch.at(0, j), patch.at(1, j), patch.at(2, j), patch.at(3, j)};
    Vec3 out[4];
    subCurve(c, u0, u1, out);
    for (int i = 0; i < 4; ++i) rows.at(i, j) = out[i];
  }
  BezierPatch result;
  for (int i = 0; i < 4; ++i) {
    const Vec3 c[4] = {rows.at(i, 0), rows.at(i, 1), rows.at(i, 2), rows.at(i, 3)};
    Vec3 out[4];
    subCurve(c, v0, v1, out);
    for (int j = 0; j < 4; ++j) result.at(i, j) = out[j];
  }
  return result;
}

void splitPatch(const BezierPatch& patch, bool along_u, BezierPatch& first, BezierPatch& second) {
  for (int k = 0; k < 4; ++k) {
    Vec3 c[4], a[4], b[4];
    for (int m = 0; m < 4; ++m) c[m] = along_u ? patch.at(m, k) : patch.at(k, m);
    casteljau(c, 0.5, a, b);
    for (int m = 0; m < 4; ++m) {
      (along_u ? first.at(m, k) : first.at(k, m)) = a[m];
      (along_u ? second.at(m, k) : second.at(k, m)) = b[m];
    }
  }
}

double flatnessBound(const BezierPatch& patch) {
  const Vec3 &a = patch.at(0, 0), &b = patch.at(3, 0), &c = patch.at(0, 3), &d = patch.at(3, 3);
  double worst = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = 0; j < 4; ++j) {
      const double u = i / 3.0, v = j / 3.0;
      const Vec3 bilinear = a * ((1 - u) * (1 - v)) + b * (u * (1 - v)) + c * ((1 - u) * v) + d * (u * v);
      worst = std::max(worst, distance(patch.at(i, j), bilinear));
    }
  return worst + 0.25 * length(a - b - c + d);
}

double bendAlongU(const BezierPatch& patch) {
  double worst = 0;
  for (int j = 0; j < 4; ++j)
    for (int i = 1; i < 3; ++i)
      worst = std::max(worst, length(patch.at(i - 1, j) - patch.at(i, j) * 2.0 + patch.at(i + 1, j)));
  return worst;
}

double bendAlongV(const BezierPatch& patch) {
  double worst = 0;
  for (int i = 0; i < 4; ++i)
    for (int j = 1; j < 3; ++j)
      worst = std::max(worst, length(patch.at(i, j - 1) - patch.at(i, j) * 2.0 + patch.at(i, j + 1)));
  return worst;
}

void patchBounds(const BezierPatch& patch, Vec3& lo, Vec3& hi) {
  lo = hi = patch.p[0];
  for (const Vec3& c : patch.p) {
    lo = {std::min(lo.x, c.x), std::min(lo.y, c.y), std::min(lo.z, c.z)};
    hi = {std::max(hi.x, c.x), std::max(hi.y, c.y), std::max(hi.z, c.z)};
  }
}

}  // namespace prism
