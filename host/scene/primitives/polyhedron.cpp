// Polyhedra. Convex ones as an intersection of half-spaces (this kind's own
// record), or any closed one by its faces (which becomes a mesh of polygons,
// parseFaces). The convex polyhedron: the points where
// a x + b y + c z + d <= 0 for every plane [a, b, c, d]. The kernel clips the
// ray's parameter interval by every plane (t_near: the latest entering plane,
// t_far: the earliest leaving one), Kay and Kajiya's slab test generalised
// (kernels/geometry/polyhedron.h). Kept in object space, so transforms place it.
// CGAL's exact linear-programming solver says whether the half-spaces enclose
// a bounded, non-empty region, and gives its box.
#include <CGAL/Gmpzf.h>
#include <CGAL/QP_functions.h>
#include <CGAL/QP_models.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <memory>

#include "scene/mesh_objects.h"
#include "scene/primitives/polygon_shape.h"
#include "scene/primitives/primitive_kind.h"
#include "scene/value_check.h"

namespace prism {
namespace {

constexpr std::size_t kMaxPlanes = 4096;

enum class Extent { Bounded, Empty, Unbounded };

// The box of {x : n_i . x + d_i <= 0 for all i}, exactly (up to the final
// rounding to double), by six linear programs.
Extent extentOf(const double* planes, std::size_t count, double lo[3], double hi[3]) {
  using Program = CGAL::Quadratic_program<double>;
  for (int axis = 0; axis < 3; ++axis)
    for (int side = 0; side < 2; ++side) {
      Program lp(CGAL::SMALLER, false, 0, false, 0);  // A x <= b, every variable free
      for (std::size_t i = 0; i < count; ++i) {
        for (int k = 0; k < 3; ++k) lp.set_a(k, static_cast<int>(i), planes[4 * i + k]);
        lp.set_b(static_cast<int>(i), -planes[4 * i + 3]);
      }
      lp.set_c(axis, side ? -1 : 1);  // minimise x_axis, then -x_axis
      const auto s = CGAL::solve_linear_program(lp, CGAL::Gmpzf());
      if (s.is_infeasible()) return Extent::Empty;
      if (s.is_unbounded()) return Extent::Unbounded;
      const double v = CGAL::to_double(s.objective_value());
      (side ? hi : lo)[axis] = side ? -v : v;
    }
  return Extent::Bounded;
}

// A closed polyhedron given by its faces: it becomes a mesh whose faces stay
// polygons. Every edge must join exactly two faces, which run along it in
// opposite directions (a closed, consistently oriented surface); faces turning
// inwards (negative volume) are all turned round.
void parseFaces(const JsonReader& r, const Json& v, const std::string& path, Object& o) {
  r.checkObject(v, path, objectKeys({"vertices", "faces"}));
  auto mesh = std::make_shared<TriangleMesh>();
  mesh->source = path;
  const std::string vat = member(path, "vertices"), fat = member(path, "faces");
  const Json& vs = r.require(v, path, "vertices");
  if (!vs.is_array() || vs.size() < 4) r.expected(vat, "an array of at least 4 points", vs);
  std::vector<Vec3> points;
  for (std::size_t k = 0; k < vs.size(); ++k) {
    points.push_back(r.vec3(vs[k], element(vat, k)));
    const std::string p = vectorProblem(points.back(), "vertex");
    if (!p.empty()) r.fail(element(vat, k), p);
  }
  const Json& fs = r.require(v, path, "faces");
  if (!fs.is_array() || fs.size() < 4) r.expected(fat, "an array of at least 4 faces", fs);
  std::vector<std::vector<std::uint32_t>> faces;
  for (std::size_t f = 0; f < fs.size(); ++f) {
    const Json& face = fs[f];
    if (!face.is_array() || face.size() < 3) r.expected(element(fat, f), "a face: an array of at least 3 vertex indices", face);
    std::vector<std::uint32_t> ids;
    std::vector<Vec3> verts;
    for (std::size_t k = 0; k < face.size(); ++k) {
      ids.push_back(static_cast<std::uint32_t>(
          r.integer(face[k], element(element(fat, f), k), 0, static_cast<long long>(points.size()) - 1)));
      verts.push_back(points[ids.back()]);
    }
    const PolygonCheck check = checkPolygon(verts);
    if (!check.problem.empty()) r.fail(element(fat, f), check.problem);
    faces.push_back(std::move(ids));
  }
  std::map<std::pair<std::uint32_t, std::uint32_t>, int> edges;  // directed edge -> uses
  for (const auto& face : faces)
    for (std::size_t k = 0; k < face.size(); ++k) ++edges[{face[k], face[(k + 1) % face.size()]}];
  for (const auto& [edge, uses] : edges) {
    const auto back = edges.find({edge.second, edge.first});
    if (uses != 1 || back == edges.end() || back->second != 1)
      r.fail(fat, "expected a closed polyhedron whose faces all turn the same way: the edge from vertex " +
                      std::to_string(edge.first) + " to vertex " + std::to_string(edge.second) +
                      (uses != 1 ? " runs the same way in " + std::to_string(uses) + " faces"
                                 : back == edges.end() ? " belongs to one face only" : " is shared by more than two faces"));
  }
  double volume = 0;  // six times, by the divergence theorem over the fans
  for (const auto& face : faces)
    for (std::size_t k = 1; k + 1 < face.size(); ++k)
      volume += dot(points[face[0]], cross(points[face[k]], points[face[k + 1]]));
  if (volume < 0)
    for (auto& face : faces) std::reverse(face.begin(), face.end());
  for (const Vec3& p : points) mesh->positions.insert(mesh->positions.end(), {float(p.x), float(p.y), float(p.z)});
  for (const auto& face : faces) {
    for (std::size_t k = 1; k + 1 < face.size(); ++k) {
      mesh->indices.insert(mesh->indices.end(), {face[0], face[k], face[k + 1]});
      mesh->triangle_materials.push_back(-1);
    }
    mesh->face_corners.push_back(static_cast<std::uint32_t>(face.size()));
  }
  mesh->face_count = faces.size();
  std::size_t kept = 0;
  o.type = ObjectType::Mesh;
  o.polygon_faces = polygonFacePlan(*mesh, &kept);  // every face passed: kept == 0
  o.mesh = std::move(mesh);
}

void parse(const JsonReader& r, const Json& v, const std::string& path, const std::string&, Object& o) {
  if (JsonReader::find(v, "faces")) return parseFaces(r, v, path, o);
  r.checkObject(v, path, objectKeys({"planes"}));
  const std::string at = member(path, "planes");
  const Json& ps = r.require(v, path, "planes");
  if (!ps.is_array() || ps.size() < 4 || ps.size() > kMaxPlanes)
    r.expected(at, "an array of 4 to " + std::to_string(kMaxPlanes) + " planes [a, b, c, d]", ps);
  for (std::size_t i = 0; i < ps.size(); ++i) {
    const std::vector<double> p = r.numbers(ps[i], element(at, i), 4);
    if (p[0] == 0 && p[1] == 0 && p[2] == 0) r.expected(element(at, i), "a plane with a non-zero normal [a, b, c]", ps[i]);
    o.params.insert(o.params.end(), p.begin(), p.end());
  }
  double lo[3], hi[3];
  switch (extentOf(o.params.data(), ps.size(), lo, hi)) {
    case Extent::Empty:
      r.fail(at, "the half-spaces have no point in common");
    case Extent::Unbounded:
      r.fail(at, "the half-spaces do not enclose a bounded region (a direction leaves them all; add planes that close it)");
    case Extent::Bounded:
      break;
  }
  for (int a = 0; a < 3; ++a)
    if (!(hi[a] > lo[a])) r.fail(at, "the half-spaces enclose no volume (flat on the " + std::string(1, "xyz"[a]) + " axis)");
}

std::string problem(const Object& o) {
  for (std::size_t i = 0; i + 3 < o.params.size(); i += 4) {
    const Vec3 n{o.params[i], o.params[i + 1], o.params[i + 2]};
    // Unit normals in the kernel: the offset, in units of the normal's length, is a coordinate.
    const double offset = o.params[i + 3] / length(n);
    if (!(std::fabs(offset) <= kMaxCoordinate)) return "planes: every plane's distance from the origin must be at most 1e15";
  }
  return "";
}

// Planes with unit normals, so the kernel's plane values are distances; after
// them, the box of those (float) planes, solved once here rather than at every
// bounds query (six linear programs), rounded outward.
void flatten(const Object& o, std::size_t, const FlattenSettings&, ObjectGpu& g, std::vector<float>& side) {
  const std::size_t count = o.params.size() / 4;
  for (std::size_t i = 0; i < count; ++i) {
    const double* p = &o.params[4 * i];
    const double len = length(Vec3{p[0], p[1], p[2]});
    for (int k = 0; k < 4; ++k) side.push_back(static_cast<float>(p[k] / len));
  }
  const std::vector<double> planes(side.begin(), side.end());
  double lo[3], hi[3];
  if (extentOf(planes.data(), count, lo, hi) != Extent::Bounded)  // rounding the planes opened them
    throw std::invalid_argument("polyhedron: its planes, rounded to float, no longer enclose a bounded region");
  for (int a = 0; a < 3; ++a) side.push_back(roundDown(lo[a]));
  for (int a = 0; a < 3; ++a) side.push_back(roundUp(hi[a]));
  g.p[0] = static_cast<float>(count);
}

// The box flatten stored after the planes.
bool localBounds(const ObjectGpu& g, const float* side, double lo[3], double hi[3]) {
  const float* box = side + 4 * static_cast<std::size_t>(g.p[0]);
  for (int a = 0; a < 3; ++a) {
    if (!std::isfinite(box[a]) || !std::isfinite(box[3 + a])) return false;
    lo[a] = box[a];
    hi[a] = box[3 + a];
  }
  return true;
}

// Independent of the kernel's interval clipping: every point where the ray
// meets a plane and no other plane has it outside (to a relative 1e-9), the
// nearest in (tmin, tmax).
std::optional<double> reference(const Object& o, const Vec3& org, const Vec3& dir, double tmin, double tmax) {
  const std::size_t count = o.params.size() / 4;
  std::vector<Vec3> n(count);
  std::vector<double> w(count);
  for (std::size_t i = 0; i < count; ++i) {
    const double* p = &o.params[4 * i];
    const double len = length(Vec3{p[0], p[1], p[2]});
    n[i] = Vec3{p[0], p[1], p[2]} / len;
    w[i] = p[3] / len;
  }
  std::optional<double> best;
  for (std::size_t i = 0; i < count; ++i) {
    const double dn = dot(n[i], dir);
    if (dn == 0) continue;
    const double t = -(dot(n[i], org) + w[i]) / dn;
    if (!(t > tmin && t < tmax) || (best && t >= *best)) continue;
    const Vec3 x = org + dir * t;
    const double tolerance = 1e-9 * (1 + length(x));
    bool on_face = true;
    for (std::size_t j = 0; j < count && on_face; ++j) on_face = j == i || dot(n[j], x) + w[j] <= tolerance;
    if (on_face) best = t;
  }
  return best;
}

}  // namespace

const PrimitiveKind kPolyhedronKind = {ObjectType::Polyhedron, OBJECT_POLYHEDRON, {"polyhedron"}, true, parse,
                                       problem, nullptr, flatten, localBounds, nullptr, nullptr, reference};

}  // namespace prism
