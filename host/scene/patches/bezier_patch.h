// Bicubic Bezier patches: evaluation with derivatives, cutting out the piece
// over a parameter rectangle (de Casteljau), and the bounds that decide when a
// piece is flat enough. The math both patch methods share: successive
// subdivision into triangles (patch_subdivision.h) and the pieces the kernel
// intersects by Newton iteration (scene/primitives/patch.cpp).
#pragma once

#include <array>

#include "scene/vec3.h"

namespace prism {

// Control points p[4 * i + j]: i runs along u, j along v (the order of a .bpt file).
struct BezierPatch {
  std::array<Vec3, 16> p;
  const Vec3& at(int i, int j) const { return p[4 * i + j]; }
  Vec3& at(int i, int j) { return p[4 * i + j]; }
};

// A piece of a file's patch: its own control points, and where it lies in the
// patch it was cut from (for texture coordinates).
struct PatchPiece {
  BezierPatch patch;
  double u0 = 0, u1 = 1, v0 = 0, v1 = 1;
};

struct PatchPoint {
  Vec3 p, du, dv;  // S(u, v) and its partial derivatives
};

PatchPoint evaluate(const BezierPatch& patch, double u, double v);
// The unit normal du x dv; where it vanishes (a collapsed edge, such as the
// teapot lid's apex) the normal a little way towards the patch's centre.
Vec3 patchNormal(const BezierPatch& patch, double u, double v);

// The cubic with control points c at t (de Casteljau: exact at t = 0 and 1).
Vec3 curvePoint(const Vec3 c[4], double t);
// The patch restricted to [u0, u1] x [v0, v1], as a patch over [0, 1]^2.
BezierPatch subPatch(const BezierPatch& patch, double u0, double u1, double v0, double v1);
// The halves of a patch cut at u = 1/2 (along_u) or v = 1/2; they share the
// cut's control points exactly.
void splitPatch(const BezierPatch& patch, bool along_u, BezierPatch& first, BezierPatch& second);

// A bound on the distance between S(u, v) and the point at (u, v) of the two
// triangles (p00, p30, p33) and (p00, p33, p03): the control net's distance
// from the bilinear patch of the corners (linear precision and the convex hull
// property) plus the bilinear patch's distance from its two triangles (a
// quarter of the twist).
double flatnessBound(const BezierPatch& patch);
// How much the patch bends along u and along v: the largest second
// differences of the control net in each direction (where to cut next).
double bendAlongU(const BezierPatch& patch);
double bendAlongV(const BezierPatch& patch);

// The box of the control points, which holds the patch (convex hull property).
void patchBounds(const BezierPatch& patch, Vec3& lo, Vec3& hi);

}  // namespace prism
