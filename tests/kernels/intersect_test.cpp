// The kernels' ray-object intersections (sphere, box, plane, triangle, and
// transformed spheres and boxes) against the double-precision reference, through
// the extend kernel, over thousands of random, grazing, inside and near-zero rays.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <random>

#include "render/ray_queries.h"
#include "scene_format/scene_loader.h"
#include "support/reference_geometry.h"
#include "support/shared_context.h"

using namespace prism;
using namespace prism::test;

namespace {

constexpr double kPerturb = 1e-5;  // relative size change that defines "too close to call"

Object sphereObject() {
  Object o;
  o.type = ObjectType::Sphere;
  o.center = {0.3, -0.2, 0.1};
  o.radius = 1.3;
  return o;
}
Object boxObject() {
  Object o;
  o.type = ObjectType::Box;
  o.box_min = {-1, -0.5, -2};
  o.box_max = {1.5, 1, 0.5};
  return o;
}
Object planeObject() {
  Object o;
  o.type = ObjectType::Plane;
  o.point = {0, -1, 0};
  o.normal = normalize(Vec3{0.1, 1, 0.2});
  return o;
}
Object triangleObject() {
  Object o;
  o.type = ObjectType::Triangle;
  o.vertices[0] = {-1, -1, 0};
  o.vertices[1] = {1.5, -0.5, 0.3};
  o.vertices[2] = {0, 1.2, -0.4};
  return o;
}
Object ellipsoidObject() {
  Object o = sphereObject();
  o.center = {0, 0, 0};
  o.radius = 1;
  o.transform = Transform::translate({0.5, 0, -0.3}) * Transform::rotate({1, 2, 0.5}, 35) *
                Transform::scale({2, 1, 0.5});
  return o;
}
Object rotatedBoxObject() {
  Object o = boxObject();
  o.transform = Transform::translate({0, 0.4, 0}) * Transform::rotate({1, 1, 0}, 30);
  return o;
}

// An object as the scene format makes it (the presets' coefficients come from the loader).
Object objectFromJson(const std::string& json) {
  Scene scene = parseScene(R"({"objects": [)" + json + "]}", "test");
  REQUIRE(scene.objects.size() == 1);
  return scene.objects[0];
}

// Q and its gradient at p (object space), in double.
double quadricValue(const Object& o, const Vec3& p) {
  const std::vector<double>& q = o.params;
  return q[0] * p.x * p.x + q[1] * p.y * p.y + q[2] * p.z * p.z + q[3] * p.x * p.y + q[4] * p.x * p.z +
         q[5] * p.y * p.z + q[6] * p.x + q[7] * p.y + q[8] * p.z + q[9];
}
Vec3 quadricGradient(const Object& o, const Vec3& p) {
  const std::vector<double>& q = o.params;
  return {2 * q[0] * p.x + q[3] * p.y + q[4] * p.z + q[6], 2 * q[1] * p.y + q[3] * p.x + q[5] * p.z + q[7],
          2 * q[2] * p.z + q[4] * p.x + q[5] * p.y + q[8]};
}
Vec3 clipMin(const Object& o) { return {o.params[10], o.params[11], o.params[12]}; }
Vec3 clipMax(const Object& o) { return {o.params[13], o.params[14], o.params[15]}; }

struct Sampler {
  std::mt19937_64 rng{20261123};
  double uniform(double a, double b) { return std::uniform_real_distribution<double>(a, b)(rng); }
  Vec3 inCube(double h) { return {uniform(-h, h), uniform(-h, h), uniform(-h, h)}; }
  Vec3 unit() {
    for (;;) {
      Vec3 v = inCube(1);
      double l = length(v);
      if (l > 1e-3 && l <= 1) return v / l;
    }
  }
};

RefRay randomRay(Sampler& s) {
  RefRay r;
  r.o = s.inCube(5);
  r.d = (s.inCube(2) - r.o) * s.uniform(0.2, 3);  // unnormalised on purpose
  return r;
}

Vec3 inBox(Sampler& s, const Vec3& lo, const Vec3& hi, double shrink = 1) {
  Vec3 c = (lo + hi) * 0.5, h = (hi - lo) * (0.5 * shrink);
  return c + Vec3{h.x * s.uniform(-1, 1), h.y * s.uniform(-1, 1), h.z * s.uniform(-1, 1)};
}

// A point of a quadric's surface inside its clip box: a random point of the
// box taken to the surface by Newton steps along the gradient.
bool quadricSurfacePoint(const Object& ob, Sampler& s, Vec3* out) {
  for (int attempt = 0; attempt < 1000; ++attempt) {
    Vec3 p = inBox(s, clipMin(ob), clipMax(ob));
    for (int i = 0; i < 30; ++i) {
      Vec3 g = quadricGradient(ob, p);
      double g2 = dot(g, g);
      if (g2 == 0) break;
      p = p - g * (quadricValue(ob, p) / g2);
    }
    Vec3 lo = clipMin(ob), hi = clipMax(ob);
    if (std::fabs(quadricValue(ob, p)) < 1e-12 && p.x > lo.x && p.y > lo.y && p.z > lo.z && p.x < hi.x &&
        p.y < hi.y && p.z < hi.z) {
      *out = p;
      return true;
    }
  }
  return false;
}

// The largest plane value at p (<= 0: inside the polyhedron), unit normals.
double polyhedronValue(const Object& o, const Vec3& p, std::size_t skip = SIZE_MAX, std::size_t* worst = nullptr) {
  double v = -INFINITY;
  for (std::size_t i = 0; i + 3 < o.params.size(); i += 4) {
    if (i / 4 == skip) continue;
    const Vec3 n{o.params[i], o.params[i + 1], o.params[i + 2]};
    const double x = (dot(n, p) + o.params[i + 3]) / length(n);
    if (x > v) {
      v = x;
      if (worst) *worst = i / 4;
    }
  }
  return v;
}

// A point strictly inside the object (object space), mapped to world space.
Vec3 insidePoint(const Object& ob, Sampler& s) {
  Vec3 p;
  if (ob.type == ObjectType::Polyhedron) {  // the test polyhedra lie in [-1.5, 1.5]^3
    do p = s.inCube(1.5);
    while (!(polyhedronValue(ob, p) < -1e-3));
  } else if (ob.type == ObjectType::Quadric) {  // capped: inside the solid and the box
    do p = inBox(s, clipMin(ob), clipMax(ob), 0.95);
    while (!(quadricValue(ob, p) < -1e-3));
  } else if (ob.type == ObjectType::Sphere) {
    p = ob.center + s.unit() * (ob.radius * s.uniform(0, 0.95));
  } else {
    Vec3 c = (ob.box_min + ob.box_max) * 0.5, h = (ob.box_max - ob.box_min) * 0.5 * 0.95;
    p = c + Vec3{h.x * s.uniform(-1, 1), h.y * s.uniform(-1, 1), h.z * s.uniform(-1, 1)};
  }
  return ob.transform.applyPoint(p);
}

// A ray that skims the surface: tangent at a surface point, pushed in or out by a
// tiny relative amount (many of these are "too close to call" and are skipped).
RefRay grazingRay(const Object& ob, Sampler& s) {
  RefRay r;
  double offset = (s.uniform(0, 1) < 0.5 ? -1 : 1) * std::pow(10.0, s.uniform(-7, -2));
  Vec3 p, n, t;
  switch (ob.type) {
    case ObjectType::Sphere: {
      n = s.unit();
      p = ob.center + n * (ob.radius * (1 + offset));
      t = normalize(cross(n, s.unit()));
      break;
    }
    case ObjectType::Box: {
      int axis = static_cast<int>(s.uniform(0, 3));
      Vec3 lo = ob.box_min, hi = ob.box_max;
      double coords[3] = {s.uniform(lo.x, hi.x), s.uniform(lo.y, hi.y), s.uniform(lo.z, hi.z)};
      double face = s.uniform(0, 1) < 0.5 ? lo[axis] : hi[axis];
      coords[axis] = face + offset * (hi[axis] - lo[axis]);
      p = {coords[0], coords[1], coords[2]};
      double dir[3] = {s.uniform(-1, 1), s.uniform(-1, 1), s.uniform(-1, 1)};
      dir[axis] = 0;  // parallel to the face
      t = normalize(Vec3{dir[0], dir[1], dir[2]});
      break;
    }
    case ObjectType::Plane: {
      n = ob.normal;
      p = ob.point + cross(n, s.unit()) * 2.0 + n * offset;
      t = normalize(cross(n, s.unit()) + n * (offset * s.uniform(-10, 10)));
      break;
    }
    case ObjectType::Polyhedron: {
      // A point inside one face: an inside point pushed onto a random plane,
      // kept when every other plane has it inside.
      for (;;) {
        Vec3 inside;
        do inside = s.inCube(1.5);
        while (!(polyhedronValue(ob, inside) < -1e-3));
        const std::size_t face = static_cast<std::size_t>(s.uniform(0, ob.params.size() / 4.0));
        const double* q = &ob.params[4 * face];
        n = normalize(Vec3{q[0], q[1], q[2]});
        p = inside - n * ((dot(Vec3{q[0], q[1], q[2]}, inside) + q[3]) / length(Vec3{q[0], q[1], q[2]}));
        if (polyhedronValue(ob, p, face) < -1e-4) break;
      }
      p = p + n * offset;
      t = normalize(cross(n, s.unit()));
      break;
    }
    case ObjectType::Quadric: {
      if (!quadricSurfacePoint(ob, s, &p)) FAIL("no surface point found");
      n = normalize(quadricGradient(ob, p));
      p = p + n * (offset * length(clipMax(ob) - clipMin(ob)));
      t = normalize(cross(n, s.unit()));
      break;
    }
    case ObjectType::Triangle: {
      // Through a point near an edge of the triangle, from a random side.
      int e = static_cast<int>(s.uniform(0, 3));
      Vec3 a = ob.vertices[e], b = ob.vertices[(e + 1) % 3], c = ob.vertices[(e + 2) % 3];
      Vec3 on_edge = a + (b - a) * s.uniform(0, 1);
      p = on_edge + (c - on_edge) * offset;  // offset < 0 moves it outside
      Vec3 d = s.unit();
      r.o = p - d * s.uniform(0.5, 4);
      r.d = d;
      return r;
    }
  }
  p = ob.transform.applyPoint(p);
  t = ob.transform.applyVector(t);
  r.o = p - t * s.uniform(1, 4);
  r.d = t;
  return r;
}

// Starts just off the surface and points back at it, so the hit is at t ~ 1e-4..3e-3.
RefRay nearZeroRay(const Object& ob, Sampler& s) {
  RefRay r = randomRay(s);
  for (int attempt = 0; attempt < 100; ++attempt) {
    auto t = referenceIntersect(ob, r);
    if (t) {
      Vec3 d = normalize(r.d);
      Vec3 hit = r.o + r.d * *t;
      double back = std::pow(10.0, s.uniform(-4, -2.5));
      r.o = hit - d * back;
      r.d = d;
      return r;
    }
    r = randomRay(s);
  }
  return r;
}

RayGpu toGpu(const RefRay& r) {
  RayGpu g{};
  g.ox = float(r.o.x), g.oy = float(r.o.y), g.oz = float(r.o.z);
  g.dx = float(r.d.x), g.dy = float(r.d.y), g.dz = float(r.d.z);
  g.tmin = float(r.tmin);
  g.tmax = r.tmax > 1e29 ? INFINITY : float(r.tmax);
  g.kind = RAY_KIND_PRIMARY;
  return g;
}

// The reference sees the same float-rounded ray as the device.
RefRay rounded(const RefRay& r) {
  RayGpu g = toGpu(r);
  RefRay out = r;
  out.o = {g.ox, g.oy, g.oz};
  out.d = {g.dx, g.dy, g.dz};
  return out;
}

struct Tally {
  int compared = 0, skipped = 0, wrong_hit = 0, wrong_t = 0;
  double worst_t_error = 0;
};

Tally compare(const Object& ob, const std::vector<RefRay>& rays) {
  Scene scene;
  scene.materials.push_back(defaultMaterial());
  scene.objects.push_back(ob);
  std::vector<RayGpu> gpu_rays;
  for (const RefRay& r : rays) gpu_rays.push_back(toGpu(r));
  std::vector<HitGpu> hits = traceClosest(sharedContext(), scene, gpu_rays);

  Object grown = scaledAboutCentre(ob, 1 + kPerturb), shrunk = scaledAboutCentre(ob, 1 - kPerturb);
  Tally tally;
  for (size_t i = 0; i < rays.size(); ++i) {
    RefRay r = rounded(rays[i]);
    auto ref = referenceIntersect(ob, r), big = referenceIntersect(grown, r), small = referenceIntersect(shrunk, r);
    double scale = length(r.d);
    bool near_limits = ref && (*ref - r.tmin) * scale < 1e-6;
    // Too close to call: perturbing the object by 1e-4 changes the answer's kind.
    bool ambiguous = big.has_value() != small.has_value() || big.has_value() != ref.has_value() || near_limits;
    if (ambiguous) {
      ++tally.skipped;
      continue;
    }
    ++tally.compared;
    bool gpu_hit = hits[i].prim == 0;
    if (gpu_hit != ref.has_value()) {
      ++tally.wrong_hit;
      continue;
    }
    if (!ref) continue;
    // The float answer must lie within the answers of the perturbed objects,
    // widened by float rounding of the inputs.
    double lo = std::min({*ref, big ? *big : *ref, small ? *small : *ref});
    double hi = std::max({*ref, big ? *big : *ref, small ? *small : *ref});
    double slack = 1e-5 * (1 + *ref + length(r.o) / scale);
    double err = std::max(lo - slack - hits[i].t, hits[i].t - hi - slack);
    if (err > 0) {
      ++tally.wrong_t;
      tally.worst_t_error = std::max(tally.worst_t_error, err);
    }
  }
  return tally;
}

void checkObject(const std::string& name, const Object& ob, bool closed) {
  Sampler s;
  const int n = 2000;
  std::vector<std::pair<std::string, std::vector<RefRay>>> sets;
  std::vector<RefRay> random, grazing, inside, near_zero;
  for (int i = 0; i < n; ++i) {
    random.push_back(randomRay(s));
    grazing.push_back(grazingRay(ob, s));
    near_zero.push_back(nearZeroRay(ob, s));
    if (closed) {
      RefRay r;
      r.o = insidePoint(ob, s);
      r.d = s.unit();
      inside.push_back(r);
    }
  }
  sets = {{"random", random}, {"grazing", grazing}, {"near-zero t", near_zero}};
  if (closed) sets.push_back({"inside", inside});
  for (auto& [set_name, rays] : sets) {
    Tally t = compare(ob, rays);
    INFO(name << ", " << set_name << " rays: compared " << t.compared << ", skipped " << t.skipped
              << ", wrong hit/miss " << t.wrong_hit << ", wrong t " << t.wrong_t << " (worst " << t.worst_t_error
              << ")");
    CHECK(t.wrong_hit == 0);
    CHECK(t.wrong_t == 0);
    // Only grazing rays may be mostly too close to call.
    CHECK(t.compared >= (set_name == "grazing" ? n / 4 : n * 9 / 10));
  }
}

}  // namespace

TEST_CASE("ray-sphere intersection matches the double-precision reference", "[kernels][intersect]") {
  checkObject("sphere", sphereObject(), true);
}

TEST_CASE("ray-box (slab) intersection matches the double-precision reference", "[kernels][intersect]") {
  checkObject("box", boxObject(), true);
}

TEST_CASE("ray-plane intersection matches the double-precision reference", "[kernels][intersect]") {
  checkObject("plane", planeObject(), false);
}

TEST_CASE("ray-triangle intersection matches the double-precision reference", "[kernels][intersect]") {
  checkObject("triangle", triangleObject(), false);
}

TEST_CASE("transformed spheres and boxes are intersected in object space", "[kernels][intersect]") {
  checkObject("ellipsoid (scaled, rotated sphere)", ellipsoidObject(), true);
  checkObject("rotated box", rotatedBoxObject(), true);
}

TEST_CASE("ray-quadric intersection matches the double-precision reference, open and capped", "[kernels][intersect]") {
  const std::vector<std::pair<std::string, bool>> quadrics = {
      {R"({"type": "cylinder", "radius": 0.8, "height": 2, "capped": true})", true},
      {R"({"type": "cylinder", "radius": 0.8, "height": 2, "capped": false})", false},
      {R"({"type": "cone", "radius": 1.2, "height": 1.5})", true},
      {R"({"type": "paraboloid", "radius": 1, "height": 1.5, "capped": false})", false},
      {R"({"type": "ellipsoid", "radii": [1.5, 0.7, 1]})", true},
      {R"({"type": "hyperboloid", "radius": 0.5, "top_radius": 1.2, "height": 1.5})", true},
      {R"({"type": "hyperboloid", "sheets": 2, "vertex": 0.4, "top_radius": 1, "height": 1.5, "capped": false})",
       false},
      // A saddle z = x^2 - y^2, open, and the same general form transformed.
      {R"({"type": "quadric", "coefficients": [1, -1, 0, 0, 0, 0, 0, 0, -1, 0],
           "clip": {"min": [-1, -1, -1.5], "max": [1, 1, 1.5]}})", false},
      {R"({"type": "quadric", "coefficients": [2, 1, 0, 0.5, 0, 0, 0, 0, -1, -0.2], "capped": true,
           "clip": {"min": [-1, -1, -1.5], "max": [1, 1, 1.5]},
           "transform": [{"rotate": {"axis": [1, 2, 0.5], "angle": 35}}, {"translate": [0.3, -0.2, 0.4]}]})", true},
  };
  for (const auto& [json, closed] : quadrics) checkObject(json, objectFromJson(json), closed);
}

TEST_CASE("ray-polyhedron (generalised slab) intersection matches the double-precision reference",
          "[kernels][intersect]") {
  const std::vector<std::string> polyhedra = {
      // An octahedron |x| + |y| + |z| <= 1.
      R"({"type": "polyhedron", "planes": [[1, 1, 1, -1], [1, 1, -1, -1], [1, -1, 1, -1], [1, -1, -1, -1],
          [-1, 1, 1, -1], [-1, 1, -1, -1], [-1, -1, 1, -1], [-1, -1, -1, -1]]})",
      // A tetrahedron with a corner cut off, rotated and moved.
      R"({"type": "polyhedron", "planes": [[0, -1, 0, -0.8], [1, 0.35, 0.6, -1], [-1, 0.35, 0.6, -1],
          [0, 0.35, -1.2, -1], [0, 1, 0, -0.6]],
          "transform": [{"rotate": {"axis": [1, 2, 0.5], "angle": 35}}, {"translate": [0.2, -0.1, 0.3]}]})",
  };
  for (const std::string& json : polyhedra) checkObject(json, objectFromJson(json), true);
}

TEST_CASE("a cube of six planes renders as the box primitive", "[kernels][intersect]") {
  // Two methods, one solid: the same hits (to rounding) on every ray.
  Object cube = objectFromJson(R"({"type": "polyhedron", "planes": [[1, 0, 0, -1.5], [-1, 0, 0, -1], [0, 1, 0, -1],
      [0, -1, 0, -0.5], [0, 0, 1, -0.5], [0, 0, -1, -2]]})");
  Sampler s;
  std::vector<RayGpu> rays;
  for (int i = 0; i < 4000; ++i) rays.push_back(toGpu(randomRay(s)));
  Scene a, b;
  a.materials = b.materials = {defaultMaterial()};
  a.objects = {cube};
  b.objects = {boxObject()};  // min (-1, -0.5, -2), max (1.5, 1, 0.5)
  const std::vector<HitGpu> ha = traceClosest(sharedContext(), a, rays), hb = traceClosest(sharedContext(), b, rays);
  int hits = 0, differ = 0;
  for (std::size_t i = 0; i < rays.size(); ++i) {
    hits += ha[i].prim == 0;
    differ += ha[i].prim != hb[i].prim || std::fabs(ha[i].t - hb[i].t) > 1e-6f * (1 + hb[i].t);
  }
  INFO(hits << " hits, " << differ << " differ");
  CHECK(hits > 200);
  CHECK(differ <= 2);  // a ray through an edge may round either way
}

TEST_CASE("a ray that makes the quadric equation linear gets the linear root", "[kernels][intersect]") {
  // Along a cylinder's axis the t^2 and t terms vanish; parallel to a cone's
  // generator only the t^2 term does. Closed forms for both.
  Object open_cyl = objectFromJson(R"({"type": "cylinder", "radius": 0.6, "height": 1.5, "capped": false})");
  Object capped_cyl = objectFromJson(R"({"type": "cylinder", "radius": 0.6, "height": 1.5})");
  Object cone = objectFromJson(R"({"type": "cone", "radius": 1, "height": 1, "capped": false})");
  Object capped_cone = objectFromJson(R"({"type": "cone", "radius": 1, "height": 1})");
  RefRay axial;
  axial.o = {0.25, -5, 0.125};
  axial.d = {0, 1, 0};
  RefRay generator;  // x^2 = (1 - y)^2 along (-2, 1.5, 0) + t (1, -1, 0): t = 1.25
  generator.o = {-2, 1.5, 0};
  generator.d = {1, -1, 0};
  const struct {
    const Object* object;
    RefRay ray;
    double expected_t;  // 0: a miss
  } cases[] = {{&open_cyl, axial, 0}, {&capped_cyl, axial, 5}, {&cone, generator, 1.25}, {&capped_cone, generator, 1.25}};
  for (const auto& c : cases) {
    Scene scene;
    scene.materials.push_back(defaultMaterial());
    scene.objects.push_back(*c.object);
    std::vector<HitGpu> hits = traceClosest(sharedContext(), scene, {toGpu(c.ray)});
    auto ref = referenceIntersect(*c.object, c.ray);
    INFO("capped " << c.object->capped << ", expected t " << c.expected_t);
    if (c.expected_t == 0) {
      CHECK(hits[0].prim == -1);
      CHECK(!ref);
    } else {
      REQUIRE(hits[0].prim == 0);
      CHECK(hits[0].t == Approx(c.expected_t).epsilon(1e-6));
      REQUIRE(ref);
      CHECK(*ref == Approx(c.expected_t).epsilon(1e-12));
    }
  }
}

TEST_CASE("closest hit picks the nearest of several objects", "[kernels][intersect]") {
  Scene scene;
  scene.materials.push_back(defaultMaterial());
  scene.objects = {sphereObject(), boxObject(), triangleObject(), ellipsoidObject()};
  scene.objects[1].transform = Transform::translate({0.5, 2.5, 0});
  scene.objects[3].transform = Transform::translate({0, -2.5, 1}) * scene.objects[3].transform;
  Sampler s;
  std::vector<RefRay> rays;
  std::vector<RayGpu> gpu;
  for (int i = 0; i < 4000; ++i) {
    rays.push_back(rounded(randomRay(s)));
    gpu.push_back(toGpu(rays.back()));
  }
  std::vector<HitGpu> hits = traceClosest(sharedContext(), scene, gpu);
  int checked = 0, wrong = 0;
  for (size_t i = 0; i < rays.size(); ++i) {
    double best = INFINITY, second = INFINITY;
    int best_index = -1;
    for (size_t k = 0; k < scene.objects.size(); ++k) {
      auto t = referenceIntersect(scene.objects[k], rays[i]);
      if (!t) continue;
      if (*t < best) {
        second = best;
        best = *t;
        best_index = static_cast<int>(k);
      } else {
        second = std::min(second, *t);
      }
    }
    if (second - best < 1e-3 * (1 + best)) continue;  // a near tie
    ++checked;
    if (hits[i].prim != best_index) ++wrong;
  }
  INFO("checked " << checked << ", wrong " << wrong);
  CHECK(wrong <= checked / 1000);  // only edge-grazing rays may disagree
  CHECK(checked > 3000);
}
