// The polygon's three point-in-polygon tests (crossing, radial, left-right)
// against CGAL's exact bounded-side test, through the extend kernel: random
// points, every vertex and points exactly on every edge (the polygon is
// closed: those are inside, whichever test runs), on convex and non-convex
// polygons; and the refusals that keep the left-right test to convex ones.
#include <catch2/catch.hpp>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_2.h>

#include <cmath>
#include <random>
#include <string>

#include "render/gpu_scene.h"
#include "render/ray_queries.h"
#include "scene_format/scene_loader.h"
#include "support/scene_errors.h"
#include "support/shared_context.h"

using namespace prism;
using namespace prism::test;

namespace {

using K = CGAL::Exact_predicates_inexact_constructions_kernel;

struct Point2 {
  double x, y;
};

// Polygons in the plane z = 0 with coordinates in 1/16ths, so that every point
// at k/8 along an edge is a float exactly and lies exactly on it.
const std::vector<std::pair<std::string, std::vector<Point2>>>& polygons() {
  static const std::vector<std::pair<std::string, std::vector<Point2>>> p = {
      {"convex hexagon", {{0, -1}, {1.5, -0.5}, {1.5, 0.75}, {0.25, 1.25}, {-1, 0.5}, {-1.125, -0.5}}},
      {"comb (non-convex)", {{-1, -1}, {1, -1}, {1, 1}, {0.5, 1}, {0.5, 0}, {0.25, 0}, {0.25, 1}, {-0.25, 1},
                             {-0.25, 0}, {-0.5, 0}, {-0.5, 1}, {-1, 1}}},
      {"star (non-convex)", {{0, 1.5}, {0.375, 0.5}, {1.5, 0.5}, {0.625, -0.125}, {1, -1.25}, {0, -0.5},
                             {-1, -1.25}, {-0.625, -0.125}, {-1.5, 0.5}, {-0.375, 0.5}}},
      {"triangle", {{-1, -1}, {1, -0.5}, {0, 1}}},
  };
  return p;
}

CGAL::Polygon_2<K> cgalPolygon(const std::vector<Point2>& v) {
  CGAL::Polygon_2<K> poly;
  for (const Point2& p : v) poly.push_back(K::Point_2(p.x, p.y));
  return poly;
}

std::string polygonJson(const std::vector<Point2>& v) {
  std::string out = R"({"type": "polygon", "vertices": [)";
  for (std::size_t i = 0; i < v.size(); ++i)
    out += (i ? ", [" : "[") + std::to_string(v[i].x) + ", " + std::to_string(v[i].y) + ", 0]";
  return out + "]}";
}

// A ray straight down onto (x, y): its hit's projection is (x, y) exactly.
RayGpu downAt(double x, double y) {
  RayGpu r{};
  r.ox = static_cast<float>(x), r.oy = static_cast<float>(y), r.oz = 1;
  r.dz = -1;
  r.tmax = INFINITY;
  r.kind = RAY_KIND_PRIMARY;
  return r;
}

// Distance from p to the polygon's boundary, in double.
double boundaryDistance(const std::vector<Point2>& v, Point2 p) {
  double best = INFINITY;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const Point2 a = v[i], b = v[(i + 1) % v.size()];
    const double dx = b.x - a.x, dy = b.y - a.y;
    const double s = std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / (dx * dx + dy * dy), 0.0, 1.0);
    best = std::min(best, std::hypot(p.x - (a.x + s * dx), p.y - (a.y + s * dy)));
  }
  return best;
}

}  // namespace

TEST_CASE("the crossing, radial and left-right tests agree with CGAL on random, vertex and edge points",
          "[kernels][polygon]") {
  std::mt19937_64 rng(20261203);
  std::uniform_real_distribution<double> u(-1.75, 1.75);
  for (const auto& [name, verts] : polygons()) {
    const auto poly = cgalPolygon(verts);
    REQUIRE(poly.is_simple());
    std::vector<Point2> points, boundary;
    for (int k = 0; k < 3000; ++k) points.push_back({u(rng), u(rng)});
    for (std::size_t i = 0; i < verts.size(); ++i) {
      const Point2 a = verts[i], b = verts[(i + 1) % verts.size()];
      for (int s = 0; s < 8; ++s) boundary.push_back({a.x + (b.x - a.x) * s / 8.0, a.y + (b.y - a.y) * s / 8.0});
    }
    std::vector<RayGpu> rays;
    for (const Point2& p : points) rays.push_back(downAt(p.x, p.y));
    for (const Point2& p : boundary) rays.push_back(downAt(p.x, p.y));
    const std::vector<std::string> tests =
        poly.is_convex() ? std::vector<std::string>{"crossing", "radial", "left-right"}
                         : std::vector<std::string>{"crossing", "radial"};
    for (const std::string& test : tests) {
      Scene scene = parseScene(R"({"render": {"inside_test": ")" + test + R"("}, "objects": [)" +
                                   polygonJson(verts) + "]}",
                               name);
      const std::vector<HitGpu> hits = traceClosest(sharedContext(), scene, rays);
      std::size_t compared = 0, wrong = 0, skipped = 0, boundary_missed = 0, inside = 0;
      for (std::size_t k = 0; k < points.size(); ++k) {
        const Point2 p = {double(rays[k].ox), double(rays[k].oy)};
        if (boundaryDistance(verts, p) < 1e-5) {
          ++skipped;  // too close for float arithmetic to be held to the exact answer
          continue;
        }
        const bool expected = poly.bounded_side(K::Point_2(p.x, p.y)) != CGAL::ON_UNBOUNDED_SIDE;
        inside += expected;
        ++compared;
        wrong += (hits[k].prim == 0) != expected;
      }
      for (std::size_t k = points.size(); k < rays.size(); ++k) {
        REQUIRE(poly.bounded_side(K::Point_2(rays[k].ox, rays[k].oy)) == CGAL::ON_BOUNDARY);
        boundary_missed += hits[k].prim != 0;
      }
      INFO(name << ", " << test << ": " << compared << " random points compared (" << inside << " inside), "
                << skipped << " skipped, " << wrong << " wrong; " << boundary_missed << " of "
                << rays.size() - points.size() << " vertex and edge points missed");
      CHECK(wrong == 0);
      CHECK(boundary_missed == 0);
      CHECK(compared > points.size() * 99 / 100);
      CHECK(inside > compared / 10);
      for (std::size_t k = 0; k < hits.size(); ++k)
        if (hits[k].prim == 0) REQUIRE(hits[k].t == 1.0f);  // the plane z = 0, from z = 1
    }
  }
}

TEST_CASE("a polygon's normal follows its winding, and transformed polygons land where the transform puts them",
          "[kernels][polygon]") {
  // Counterclockwise seen from +z: the normal is +z; moved up by 0.5 and tilted,
  // a ray down the tilted normal still meets it at the centre.
  Scene scene = parseScene(R"({"objects": [{"type": "polygon", "vertices": [[-1, -1, 0], [1, -1, 0], [1, 1, 0], [-1, 1, 0]],
      "transform": [{"rotate": {"axis": [1, 0, 0], "angle": 30}}, {"translate": [0, 0, 0.5]}]}]})",
                           "tilted");
  const Vec3 n{0, -std::sin(M_PI / 6), std::cos(M_PI / 6)};
  RayGpu r{};
  r.ox = static_cast<float>(3 * n.x), r.oy = static_cast<float>(3 * n.y), r.oz = static_cast<float>(0.5 + 3 * n.z);
  r.dx = static_cast<float>(-n.x), r.dy = static_cast<float>(-n.y), r.dz = static_cast<float>(-n.z);
  r.tmax = INFINITY;
  r.kind = RAY_KIND_PRIMARY;
  const std::vector<HitGpu> hits = traceClosest(sharedContext(), scene, {r});
  REQUIRE(hits[0].prim == 0);
  CHECK(hits[0].t == Approx(3).epsilon(1e-6));
  const GpuScene gpu = flattenScene(scene, RenderOptions::fromScene(scene));
  CHECK(gpu.objects[0].p[0] == Approx(n.x).margin(1e-6));
  CHECK(gpu.objects[0].p[1] == Approx(n.y).epsilon(1e-6));
  CHECK(gpu.objects[0].p[2] == Approx(n.z).epsilon(1e-6));
}

TEST_CASE("left-right is refused for a non-convex polygon, by the polygon's key and by the render setting",
          "[kernels][polygon][scene]") {
  const std::string comb = polygonJson(polygons()[1].second);
  const std::string named = comb.substr(0, comb.size() - 1) + R"(, "inside_test": "left-right"})";
  try {
    parseScene(R"({"objects": [)" + named + "]}", "bad.json");
    FAIL("accepted");
  } catch (const SceneError& e) {
    CHECK(std::string(e.what()) ==
          "bad.json: objects[0].inside_test: 'left-right' needs a convex polygon and this one is not (use crossing "
          "or radial)");
  }
  Scene scene = parseScene(R"({"render": {"inside_test": "left-right"}, "objects": [)" +
                               polygonJson(polygons()[0].second) + ", " + comb + "]}",
                           "setting.json");
  try {
    flattenScene(scene, RenderOptions::fromScene(scene));
    FAIL("accepted");
  } catch (const std::invalid_argument& e) {
    CHECK(std::string(e.what()) ==
          "objects[1]: inside test 'left-right' needs a convex polygon and this one is not (use crossing or radial)");
  }
  const struct {
    const char* object;
    const char* message;
  } bad[] = {
      {R"({"type": "polygon", "vertices": [[0, 0, 0], [1, 0, 0]]})", "expected an array of at least 3 points"},
      {R"({"type": "polygon", "vertices": [[0, 0, 0], [1, 0, 0], [2, 0, 0]]})", "expected a polygon of non-zero area"},
      {R"({"type": "polygon", "vertices": [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0.5]]})",
       "]: expected the polygon to be planar"},
      {R"({"type": "polygon", "vertices": [[0, 0, 0], [3, 0, 0], [3, 2, 0], [1, -1, 0], [0, 2, 0]]})",
       "expected a simple polygon: two of its edges cross"},
      {R"({"type": "polygon", "vertices": [[0, 0, 0], [1, 0, 0], [1, 1, 0]], "inside_test": "winding"})",
       "unknown inside test 'winding' (expected crossing, radial, left-right)"},
  };
  for (const auto& c : bad) {
    INFO(c.object);
    CHECK_THAT(errorOf(std::string(R"({"objects": [)") + c.object + "]}"), Catch::Contains(c.message));
  }
}
