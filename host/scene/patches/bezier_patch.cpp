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

// The control points of the cubic c restricted to [a, b] (0 <= a < b <= 1).
void subCurve(const Vec3 c[4], double a, double b, Vec3 out[4]) {
  // Cut at b, keep [0, b]; then cut that at a / b and keep its second part.
  Vec3 l[4];
  {
    Vec3 p01 = lerp(c[0], c[1], b), p12 = lerp(c[1], c[2], b), p23 = lerp(c[2], c[3], b);
    Vec3 p012 = lerp(p01, p12, b), p123 = lerp(p12, p23, b);
    l[0] = c[0], l[1] = p01, l[2] = p012, l[3] = b == 1 ? c[3] : lerp(p012, p123, b);
  }
  if (a == 0) {
    std::copy(l, l + 4, out);
    return;
  }
  const double s = a / b;
  Vec3 p01 = lerp(l[0], l[1], s), p12 = lerp(l[1], l[2], s), p23 = lerp(l[2], l[3], s);
  Vec3 p012 = lerp(p01, p12, s), p123 = lerp(p12, p23, s);
  out[0] = lerp(p012, p123, s), out[1] = p123, out[2] = p23, out[3] = l[3];
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
  Vec3 p01 = lerp(c[0], c[1], t), p12 = lerp(c[1], c[2], t), p23 = lerp(c[2], c[3], t);
  if (t == 0) return c[0];
  if (t == 1) return c[3];
  return lerp(lerp(p01, p12, t), lerp(p12, p23, t), t);
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
    Vec3 c[4];
    for (int m = 0; m < 4; ++m) c[m] = along_u ? patch.at(m, k) : patch.at(k, m);
    Vec3 p01 = lerp(c[0], c[1], 0.5), p12 = lerp(c[1], c[2], 0.5), p23 = lerp(c[2], c[3], 0.5);
    Vec3 p012 = lerp(p01, p12, 0.5), p123 = lerp(p12, p23, 0.5), mid = lerp(p012, p123, 0.5);
    const Vec3 a[4] = {c[0], p01, p012, mid}, b[4] = {mid, p123, p23, c[3]};
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
