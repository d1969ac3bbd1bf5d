// The general quadric A x^2 + B y^2 + C z^2 + D xy + E xz + F yz + G x + H y +
// I z + J = 0 clipped to a box, open or capped, and its named presets (each a
// quadric in a canonical place, put where it belongs by the object's
// transform). Intersected in object space. Kernel: kernels/geometry/quadric.h.
//
// Presets (docs/scene-format.md), all with the y axis as their axis:
//   cylinder    x^2 + z^2 = r^2, 0 <= y <= height
//   cone        x^2 + z^2 = (r/height)^2 (height - y)^2, 0 <= y <= height (apex at the top)
//   paraboloid  x^2 + z^2 = (r^2/height) y, 0 <= y <= height
//   ellipsoid   x^2/a^2 + y^2/b^2 + z^2/c^2 = 1
//   hyperboloid one sheet: waist radius r at y = 0, top_radius at |y| = height;
//               two sheets: tips at |y| = vertex, top_radius at |y| = height.
// The solid is {Q <= 0}: inside the cylinder, cone, paraboloid, ellipsoid, the
// one-sheet hyperboloid's waist and the two-sheet one's bowls.
#include <algorithm>
#include <cfloat>
#include <cmath>

#include "scene/primitives/primitive_kind.h"
#include "scene/value_check.h"

namespace prism {
namespace {

constexpr int kCoefficients = 10;

using Check = JsonReader::Check;
// A preset's sizes are lengths: they bound its clip box, which must lie within 1e15.
const Check kLength = [](double x) { return x > 0 && x <= kMaxCoordinate; };
constexpr const char* kLengthWanted = "a positive number of at most 1e15";

double length(const JsonReader& r, const Json& v, const std::string& path, const char* key, double fallback) {
  const Json* p = JsonReader::find(v, key);
  return p ? r.number(*p, member(path, key), kLengthWanted, kLength) : fallback;
}

bool flag(const JsonReader& r, const Json& v, const std::string& path, const char* key, bool fallback) {
  const Json* p = JsonReader::find(v, key);
  if (!p) return fallback;
  if (!p->is_boolean()) r.expected(member(path, key), "true or false", *p);
  return p->get<bool>();
}

// params: A..J, then clip min, clip max.
void setQuadric(Object& o, std::initializer_list<double> coefficients, const Vec3& lo, const Vec3& hi) {
  o.params.assign(coefficients);
  o.params.insert(o.params.end(), {lo.x, lo.y, lo.z, hi.x, hi.y, hi.z});
}

void parseGeneral(const JsonReader& r, const Json& v, const std::string& path, Object& o) {
  r.checkObject(v, path, objectKeys({"coefficients", "clip", "capped"}));
  o.params = r.numbers(r.require(v, path, "coefficients"), member(path, "coefficients"), kCoefficients);
  const std::string at = member(path, "clip");
  const Json& clip = r.require(v, path, "clip");
  r.checkObject(clip, at, {"min", "max"});
  const Vec3 lo = r.vec3(r.require(clip, at, "min"), member(at, "min"));
  const Vec3 hi = r.vec3(r.require(clip, at, "max"), member(at, "max"));
  if (!(lo.x < hi.x && lo.y < hi.y && lo.z < hi.z))
    r.fail(member(at, "max"), "expected max > min on every axis, got max " + formatVec(hi) + " and min " + formatVec(lo));
  o.params.insert(o.params.end(), {lo.x, lo.y, lo.z, hi.x, hi.y, hi.z});
  o.capped = flag(r, v, path, "capped", false);
}

std::string problem(const Object& o);

// A preset's sizes are each within bounds, but together they may make
// coefficients float cannot keep: say so in the preset's own terms.
void checkPreset(const JsonReader& r, const std::string& path, const Object& o, const std::string& sizes) {
  if (const std::string p = problem(o); !p.empty()) r.fail(path, "the sizes " + sizes + " make a quadric prism cannot hold: " + p);
}

void parse(const JsonReader& r, const Json& v, const std::string& path, const std::string& name, Object& o) {
  if (name == "quadric") return parseGeneral(r, v, path, o);
  o.capped = flag(r, v, path, "capped", true);
  if (name == "ellipsoid") {
    r.checkObject(v, path, objectKeys({"radii", "capped"}));
    const Vec3 a = r.vec3(r.require(v, path, "radii"), member(path, "radii"), kLengthWanted, kLength);
    setQuadric(o, {1 / (a.x * a.x), 1 / (a.y * a.y), 1 / (a.z * a.z), 0, 0, 0, 0, 0, 0, -1}, a * -1.0, a);
    return checkPreset(r, path, o, "radii " + formatVec(a));
  }
  if (name == "hyperboloid") {
    r.checkObject(v, path, objectKeys({"sheets", "radius", "vertex", "top_radius", "height", "capped"}));
    const Json* s = JsonReader::find(v, "sheets");
    const long long sheets = s ? r.integer(*s, member(path, "sheets"), 1, 2) : 1;
    const double h = length(r, v, path, "height", 1), top = length(r, v, path, "top_radius", 2);
    const Vec3 lo{-top, -h, -top}, hi{top, h, top};
    if (sheets == 1) {
      const double a = length(r, v, path, "radius", 1);
      if (!(top > a)) r.fail(member(path, "top_radius"), "expected more than radius (" + formatNumber(a) + ")");
      setQuadric(o, {1, -(top * top - a * a) / (h * h), 1, 0, 0, 0, 0, 0, 0, -a * a}, lo, hi);
      return checkPreset(r, path, o,
                         "radius " + formatNumber(a) + ", top_radius " + formatNumber(top) + ", height " + formatNumber(h));
    } else {
      const double tip = length(r, v, path, "vertex", 0.5);
      if (!(h > tip)) r.fail(member(path, "height"), "expected more than vertex (" + formatNumber(tip) + ")");
      const double s2 = top * top / (h * h / (tip * tip) - 1);  // squared radius scale of the sheets
      setQuadric(o, {1, -s2 / (tip * tip), 1, 0, 0, 0, 0, 0, 0, s2}, lo, hi);
      return checkPreset(r, path, o,
                         "vertex " + formatNumber(tip) + ", top_radius " + formatNumber(top) + ", height " + formatNumber(h));
    }
  }
  r.checkObject(v, path, objectKeys({"radius", "height", "capped"}));
  const double rad = length(r, v, path, "radius", 1), h = length(r, v, path, "height", 1);
  const Vec3 lo{-rad, 0, -rad}, hi{rad, h, rad};
  if (name == "cylinder") {
    setQuadric(o, {1, 0, 1, 0, 0, 0, 0, 0, 0, -rad * rad}, lo, hi);
  } else if (name == "cone") {
    const double k2 = rad * rad / (h * h);
    setQuadric(o, {1, -k2, 1, 0, 0, 0, 0, 2 * k2 * h, 0, -rad * rad}, lo, hi);
  } else {  // paraboloid
    setQuadric(o, {1, 0, 1, 0, 0, 0, 0, -rad * rad / h, 0, 0}, lo, hi);
  }
  checkPreset(r, path, o, "radius " + formatNumber(rad) + ", height " + formatNumber(h));
}

// The kernel holds the coefficients scaled to a largest magnitude of 1
// (flatten, below). One that falls below float's smallest normal there is
// subnormal or zero, and OpenCL 1.2 lets a device flush subnormals to zero:
// the kernel could solve another equation than the file's.
std::string coefficientRangeProblem(const std::vector<double>& q) {
  double largest = 0;
  for (int i = 0; i < kCoefficients; ++i) largest = std::max(largest, std::fabs(q[i]));
  for (int i = 0; i < kCoefficients; ++i)
    if (q[i] != 0 && std::fabs(q[i]) / largest < FLT_MIN)
      return "coefficients span more than float holds: " + formatNumber(q[i]) + " beside " + formatNumber(largest) +
             " (the kernel keeps them scaled to a largest magnitude of 1, and " + formatNumber(q[i] / largest) +
             " is below float's smallest normal number, which a device may flush to zero)";
  return "";
}

Vec3 clipMin(const Object& o) { return {o.params[10], o.params[11], o.params[12]}; }
Vec3 clipMax(const Object& o) { return {o.params[13], o.params[14], o.params[15]}; }

std::string problem(const Object& o) {
  if (o.params.size() != kCoefficients + 6) return "a quadric needs 10 coefficients and a clip box";
  bool surface = false;  // some of A..I non-zero: Q is not a constant
  for (int i = 0; i < kCoefficients; ++i) {
    if (!std::isfinite(o.params[i])) return "coefficients must be finite";
    surface = surface || (i < 9 && o.params[i] != 0);
  }
  if (!surface) return "coefficients: one of the first nine must be non-zero (with A..I all 0 there is no surface)";
  if (const std::string p = coefficientRangeProblem(o.params); !p.empty()) return p;
  std::string p = vectorProblem(clipMin(o), "clip.min");
  return p.empty() ? vectorProblem(clipMax(o), "clip.max") : p;
}

// Coefficients scaled to a largest magnitude of 1 (the same surface and the
// same inside), so the kernel's products stay far from float's limits.
void flatten(const Object& o, std::size_t, const FlattenSettings&, ObjectGpu& g, std::vector<float>& side) {
  double scale = 0;
  for (int i = 0; i < kCoefficients; ++i) scale = std::max(scale, std::fabs(o.params[i]));
  for (int i = 0; i < kCoefficients; ++i) g.p[i] = static_cast<float>(o.params[i] / scale);
  const Vec3 lo = clipMin(o), hi = clipMax(o);
  side = {roundDown(lo.x), roundDown(lo.y), roundDown(lo.z), roundUp(hi.x), roundUp(hi.y), roundUp(hi.z)};
  if (o.capped) g.flags |= OBJECT_FLAG_CAPPED;
}

// The clip box: every hit lies in it.
bool localBounds(const ObjectGpu&, const float* side, double lo[3], double hi[3]) {
  for (int a = 0; a < 3; ++a) {
    if (!std::isfinite(side[a]) || !std::isfinite(side[3 + a])) return false;
    lo[a] = side[a];
    hi[a] = side[3 + a];
  }
  return true;
}

// Q at p, in long double.
long double quadricAt(const std::vector<double>& q, const long double p[3]) {
  return q[0] * p[0] * p[0] + q[1] * p[1] * p[1] + q[2] * p[2] * p[2] + q[3] * p[0] * p[1] + q[4] * p[0] * p[2] +
         q[5] * p[1] * p[2] + q[6] * p[0] + q[7] * p[1] + q[8] * p[2] + q[9];
}

// Independent of the kernel's interval method: every point where the ray
// crosses the surface inside the clip box (the textbook quadratic formula, or
// the linear root), and, capped, every point where it crosses a face of the
// box inside the solid; the nearest in (tmin, tmax).
std::optional<double> reference(const Object& o, const Vec3& org, const Vec3& dir, double tmin, double tmax) {
  const std::vector<double>& q = o.params;
  const long double O[3] = {org.x, org.y, org.z}, D[3] = {dir.x, dir.y, dir.z};
  const double lo[3] = {q[10], q[11], q[12]}, hi[3] = {q[13], q[14], q[15]};
  auto at = [&](long double t, long double p[3]) {
    for (int k = 0; k < 3; ++k) p[k] = O[k] + t * D[k];
  };
  auto inBox = [&](const long double p[3], int skip) {
    for (int k = 0; k < 3; ++k)
      if (k != skip && (p[k] < lo[k] || p[k] > hi[k])) return false;
    return true;
  };
  std::optional<double> best;
  auto offer = [&](long double t) {
    if (t > tmin && t < tmax && (!best || t < *best)) best = static_cast<double>(t);
  };
  // Q(O + t D) = a t^2 + b t + c, expanded term by term.
  const long double a = q[0] * D[0] * D[0] + q[1] * D[1] * D[1] + q[2] * D[2] * D[2] + q[3] * D[0] * D[1] +
                        q[4] * D[0] * D[2] + q[5] * D[1] * D[2];
  const long double b = 2 * (q[0] * O[0] * D[0] + q[1] * O[1] * D[1] + q[2] * O[2] * D[2]) +
                        q[3] * (O[0] * D[1] + O[1] * D[0]) + q[4] * (O[0] * D[2] + O[2] * D[0]) +
                        q[5] * (O[1] * D[2] + O[2] * D[1]) + q[6] * D[0] + q[7] * D[1] + q[8] * D[2];
  const long double c = quadricAt(q, O);
  std::vector<long double> roots;
  if (a != 0) {
    const long double disc = b * b - 4 * a * c;
    if (disc >= 0) {
      roots.push_back((-b - std::sqrt(disc)) / (2 * a));
      roots.push_back((-b + std::sqrt(disc)) / (2 * a));
    }
  } else if (b != 0) {
    roots.push_back(-c / b);
  }
  for (long double t : roots) {
    long double p[3];
    at(t, p);
    if (inBox(p, -1)) offer(t);
  }
  if (o.capped) {
    for (int axis = 0; axis < 3; ++axis) {
      if (D[axis] == 0) continue;
      for (double face : {lo[axis], hi[axis]}) {
        const long double t = (face - O[axis]) / D[axis];
        long double p[3];
        at(t, p);
        p[axis] = face;
        if (inBox(p, axis) && quadricAt(q, p) <= 0) offer(t);
      }
    }
  }
  return best;
}

}  // namespace

const PrimitiveKind kQuadricKind = {ObjectType::Quadric,
                                    OBJECT_QUADRIC,
                                    {"quadric", "cylinder", "cone", "ellipsoid", "paraboloid", "hyperboloid"},
                                    true,
                                    parse,
                                    problem,
                                    nullptr,
                                    flatten,
                                    localBounds,
                                    nullptr,
                                    nullptr,
                                    reference};

}  // namespace prism
