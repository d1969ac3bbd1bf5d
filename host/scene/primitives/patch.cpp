// Bicubic Bezier patches from a .bpt file (Newell's teapot and any other) or
// given inline (16 control points each, as the C API and Python pass them), by
// either method the classic literature names (scene/patches/patch_subdivision.h):
//   "subdivision"  successive subdivision to a flatness tolerance: the object
//                  becomes a mesh of triangles with normals and texture
//                  coordinates from the patch (as a polyhedron given by faces
//                  becomes a mesh of polygons);
//   "analytic"     the object stays patches, cut into pieces that bend little,
//                  each a primitive that the kernel intersects by Newton
//                  iteration to the tolerance (kernels/geometry/patch.h).
// The tolerance is in the file's units (before the object's transform): how
// far the triangles may lie from the surface (default: a thousandth of the
// patches' size), or Newton's hit from the ray (default: as close as float
// can tell; a coarser one makes shadow acne).
// Static transforms are baked into the control points (Bezier patches are
// affine invariant).
#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>

#include "scene/patches/bpt_file.h"
#include "scene/patches/patch_subdivision.h"
#include "scene/primitives/primitive_kind.h"
#include "scene/value_check.h"

namespace prism {
namespace {

// The default tolerance of subdivision and the least one (the analytic
// method's default), as fractions of the patches' size (the diagonal of their
// control points' box): below a millionth, float cannot tell the difference.
constexpr double kDefaultTolerance = 1e-3, kLeastTolerance = 1e-6;
constexpr std::size_t kMaxTriangles = std::size_t(1) << 24;

const JsonReader::Check kPositive = [](double x) { return x > 0; };

// Inline patches: an array of patches, each an array of 16 points.
std::vector<BezierPatch> inlinePatches(const JsonReader& r, const Json& v, const std::string& at) {
  if (!v.is_array() || v.empty()) r.expected(at, "an array of patches, each 16 points", v);
  if (v.size() > kMaxPatchesPerFile)
    r.fail(at, "more than " + std::to_string(kMaxPatchesPerFile) + " patches (" + std::to_string(v.size()) + ")");
  std::vector<BezierPatch> patches(v.size());
  for (std::size_t k = 0; k < v.size(); ++k) {
    const std::string pk = element(at, k);
    if (!v[k].is_array() || v[k].size() != 16) r.expected(pk, "16 control points (4 rows of 4)", v[k]);
    for (std::size_t i = 0; i < 16; ++i) {
      const std::string pi = element(pk, i);
      patches[k].p[i] = r.vec3(v[k][i], pi);
      const std::string problem = vectorProblem(patches[k].p[i], pi.c_str());
      if (!problem.empty()) r.fail(pi, problem);
    }
  }
  return patches;
}

void parse(const JsonReader& r, const Json& v, const std::string& path, const std::string&, Object& o) {
  r.checkObject(v, path, objectKeys({"file", "patches", "method", "tolerance"}));
  const Json* inline_patches = JsonReader::find(v, "patches");
  if (inline_patches && JsonReader::find(v, "file"))
    r.fail(path, "give the control points either in a file or as 'patches', not both");
  const std::string file_at = member(path, inline_patches ? "patches" : "file");
  std::string file = "patches";  // (the mesh's name, for inline patches)
  std::vector<BezierPatch> patches;
  if (inline_patches) {
    patches = inlinePatches(r, *inline_patches, file_at);
  } else {
    file = r.filePath(r.string(r.require(v, path, "file"), file_at, "a patch file name (.bpt)"));
    try {
      patches = readBptFile(file);
    } catch (const PatchFileError& e) {
      r.fail(file_at, e.what());
    }
  }
  std::string method = "subdivision";
  if (const Json* m = JsonReader::find(v, "method")) {
    const std::string at = member(path, "method");
    method = r.string(*m, at, "subdivision or analytic");
    if (method != "subdivision" && method != "analytic")
      r.fail(at, "unknown method '" + method + "' (expected subdivision or analytic)");
  }
  const double size = patchSetSize(patches);
  if (!(size > 0)) r.fail(file_at, "every control point is the same point: nothing to render");
  const std::string tol_at = member(path, "tolerance");
  double tolerance = (method == "subdivision" ? kDefaultTolerance : kLeastTolerance) * size;
  if (const Json* t = JsonReader::find(v, "tolerance")) {
    tolerance = r.number(*t, tol_at, "a positive number", kPositive);
    if (tolerance < kLeastTolerance * size)
      r.fail(tol_at, "expected at least " + formatNumber(kLeastTolerance * size) + " (a millionth of the patches' size, " +
                         formatNumber(size) + "; float cannot resolve less), got " + formatNumber(tolerance));
  }
  if (method == "subdivision") {
    try {
      const std::vector<PatchGrid> plan = planSubdivision(patches, tolerance, kMaxTriangles);
      o.mesh = tessellatePatches(patches, plan, file);
    } catch (const std::length_error& e) {
      r.fail(tol_at, e.what());
    }
    o.type = ObjectType::Mesh;
    o.smooth = true;  // normals from the patch's derivatives
    return;
  }
  o.pieces = std::make_shared<const std::vector<PatchPiece>>(patchPieces(patches));
  o.params = {tolerance};
}

std::string problem(const Object& o) {
  if (!o.pieces || o.pieces->empty()) return "patches: no patch to render";
  if (o.params.size() != 1 || !(o.params[0] > 0) || !std::isfinite(o.params[0]))
    return "tolerance must be a positive number";
  for (const PatchPiece& piece : *o.pieces)
    for (const Vec3& c : piece.patch.p) {
      const std::string p = vectorProblem(c, "control points");
      if (!p.empty()) return p;
    }
  return "";
}

// Control points map by the transform; the tolerance grows with its largest stretch.
void bake(Object& o) {
  auto pieces = std::make_shared<std::vector<PatchPiece>>(*o.pieces);
  for (PatchPiece& piece : *pieces)
    for (Vec3& c : piece.patch.p) c = o.transform.applyPoint(c);
  double stretch = 0;
  for (int c = 0; c < 3; ++c)
    stretch = std::max(stretch, length(Vec3{o.transform.m[0][c], o.transform.m[1][c], o.transform.m[2][c]}));
  o.params[0] *= stretch;
  o.pieces = pieces;
}

// The normal cone the kernel's one-crossing test rests on. Every normal
// S_u x S_v is a positive combination of the products (u difference) x
// (v difference) of the control net; when each lies within angle g of `axis`,
// a ray d with |d . axis| > sin(g) |d| has det(d, S_u, S_v) of one sign over
// the piece. Returns sin(g) (rounded up), or 1 — no promise — when the
// products spread over more than a half-space.
double normalConeSine(const BezierPatch& p, Vec3* axis) {
  std::vector<Vec3> normals;
  Vec3 sum{0, 0, 0};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j)
      for (int k = 0; k < 4; ++k)
        for (int l = 0; l < 3; ++l) {
          const Vec3 m = cross(p.at(i + 1, j) - p.at(i, j), p.at(k, l + 1) - p.at(k, l));
          const double len = length(m);
          if (len == 0) continue;  // (a collapsed edge)
          normals.push_back(m / len);
          sum = sum + m / len;
        }
  *axis = {0, 0, 1};
  if (normals.empty() || length(sum) == 0) return 1;
  *axis = normalize(sum);
  double least_cos = 1;
  for (const Vec3& m : normals) least_cos = std::min(least_cos, dot(m, *axis));
  if (least_cos <= 0) return 1;
  // d at angle a to the axis meets every m (within angle g of it) with d.m > 0
  // when a + g < 90 degrees: |cos a| > sin g.
  return std::min(1.0, std::sqrt(std::max(0.0, 1 - least_cos * least_cos)) * (1 + 1e-6) + 1e-6);
}

void flatten(const Object& o, std::size_t part, const FlattenSettings&, ObjectGpu& g, std::vector<float>& side) {
  const PatchPiece& piece = o.pieces->at(part);
  const double range[4] = {piece.u0, piece.u1, piece.v0, piece.v1};
  for (int i = 0; i < 4; ++i) g.p[i] = static_cast<float>(range[i]);
  Vec3 lo, hi;
  patchBounds(piece.patch, lo, hi);
  for (int a = 0; a < 3; ++a) {
    g.p[4 + a] = roundDown(lo[a]);
    g.p[7 + a] = roundUp(hi[a]);
  }
  g.p[10] = static_cast<float>(o.params[0]);
  side.clear();
  for (const Vec3& c : piece.patch.p) side.insert(side.end(), {float(c.x), float(c.y), float(c.z)});
  Vec3 axis;
  const double sine = normalConeSine(piece.patch, &axis);
  side.insert(side.end(), {float(axis.x), float(axis.y), float(axis.z), roundUp(sine)});
}

// The box of the control points (rounded outwards): the piece lies in their hull.
bool localBounds(const ObjectGpu& g, const float*, double lo[3], double hi[3]) {
  for (int a = 0; a < 3; ++a) {
    if (!std::isfinite(g.p[4 + a]) || !std::isfinite(g.p[7 + a])) return false;
    lo[a] = g.p[4 + a];
    hi[a] = g.p[7 + a];
  }
  return true;
}

// Ray against a box in double, padded by `pad`: whether they meet in (tmin, tmax).
bool rayMeetsBox(const Vec3& o, const Vec3& d, double tmin, double tmax, const Vec3& lo, const Vec3& hi, double pad) {
  double t0 = tmin, t1 = tmax;
  for (int a = 0; a < 3; ++a) {
    const double l = lo[a] - pad, h = hi[a] + pad;
    if (d[a] == 0) {
      if (o[a] < l || o[a] > h) return false;
      continue;
    }
    double ta = (l - o[a]) / d[a], tb = (h - o[a]) / d[a];
    if (ta > tb) std::swap(ta, tb);
    t0 = std::max(t0, ta);
    t1 = std::min(t1, tb);
    if (t0 > t1) return false;
  }
  return true;
}

// A corner triangle of a piece, met by the triangle kind's own reference
// (edges included).
std::optional<double> cornerTriangle(const Vec3& o, const Vec3& d, const Vec3& a, const Vec3& b, const Vec3& c,
                                     double tmin, double tmax) {
  Object triangle;
  triangle.type = ObjectType::Triangle;
  triangle.vertices[0] = a, triangle.vertices[1] = b, triangle.vertices[2] = c;
  return kTriangleKind.reference(triangle, o, d, tmin, tmax);
}

// Successive subdivision per ray, in double (the kernel solves by Newton in
// float instead): halves whose control-point box the ray meets are cut again
// until they are smaller than `least`, where their corner triangles stand for
// them.
std::optional<double> subdivideAlongRay(const BezierPatch& p, const Vec3& o, const Vec3& d, double tmin,
                                        double tmax, double least, int depth) {
  Vec3 lo, hi;
  patchBounds(p, lo, hi);
  const double size = length(hi - lo);
  if (!rayMeetsBox(o, d, tmin, tmax, lo, hi, 1e-9 * size + least * 1e-3)) return std::nullopt;
  if (size <= least || depth >= 64) {
    std::optional<double> a = cornerTriangle(o, d, p.at(0, 0), p.at(3, 0), p.at(3, 3), tmin, tmax);
    std::optional<double> b = cornerTriangle(o, d, p.at(0, 0), p.at(3, 3), p.at(0, 3), tmin, tmax);
    if (a && b) return std::min(*a, *b);
    return a ? a : b;
  }
  const double lu = length(p.at(3, 0) - p.at(0, 0)) + length(p.at(3, 3) - p.at(0, 3));
  const double lv = length(p.at(0, 3) - p.at(0, 0)) + length(p.at(3, 3) - p.at(3, 0));
  BezierPatch first, second;
  splitPatch(p, lu >= lv, first, second);
  std::optional<double> a = subdivideAlongRay(first, o, d, tmin, tmax, least, depth + 1);
  std::optional<double> b = subdivideAlongRay(second, o, d, tmin, a ? *a : tmax, least, depth + 1);
  return b ? b : a;
}

std::optional<double> reference(const Object& o, const Vec3& org, const Vec3& dir, double tmin, double tmax) {
  std::optional<double> best;
  for (const PatchPiece& piece : *o.pieces) {
    Vec3 lo, hi;
    patchBounds(piece.patch, lo, hi);
    const double least = 1e-7 * std::max(length(hi - lo), 1e-300);
    if (auto t = subdivideAlongRay(piece.patch, org, dir, tmin, best ? *best : tmax, least, 0)) best = t;
  }
  return best;
}

}  // namespace

const PrimitiveKind kPatchKind = {ObjectType::Patches, OBJECT_PATCH, {"patches"}, true, parse, problem, bake,
                                  flatten, localBounds, nullptr, nullptr, reference};

}  // namespace prism
