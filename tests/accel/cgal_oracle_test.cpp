// CGAL's AABB tree as the independent oracle for triangle meshes: its
// first_intersection (closest hit, double precision) and do_intersect on
// segments (occlusion) against every prism structure, with camera and random
// rays. Float and double may call a ray through an edge or along a surface
// either way, so pairs within 1e-5 (relative) of an edge, or nearly parallel,
// or two triangles within 1e-5 in t, are counted as unclear and must be rare.
#include <catch2/catch.hpp>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Simple_cartesian.h>

#include <cmath>
#include <vector>

#include "accel/accel_scenes.h"
#include "render/ray_queries.h"
#include "support/shared_context.h"

using namespace prism;
using namespace prism::test;

namespace {

using K = CGAL::Simple_cartesian<double>;
using Triangles = std::vector<K::Triangle_3>;
using Primitive = CGAL::AABB_triangle_primitive<K, Triangles::const_iterator>;
using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;

struct Oracle {
  Triangles triangles;
  std::vector<int> ids;  // prism primitive id of triangles[i] (degenerate ones are left out)
  Tree tree;

  explicit Oracle(const std::vector<ObjectGpu>& objects) {
    for (std::size_t i = 0; i < objects.size(); ++i) {
      const float* p = objects[i].p;
      K::Triangle_3 t(K::Point_3(p[0], p[1], p[2]), K::Point_3(p[3], p[4], p[5]), K::Point_3(p[6], p[7], p[8]));
      if (t.is_degenerate()) continue;
      triangles.push_back(t);
      ids.push_back(static_cast<int>(i));
    }
    tree.insert(triangles.begin(), triangles.end());
    tree.build();
  }

  // Closest hit: (prim id, t), or (-1, inf).
  std::pair<int, double> closest(const QueryRay& r) const {
    K::Ray_3 ray(K::Point_3(r.ox, r.oy, r.oz), K::Vector_3(r.dx, r.dy, r.dz));
    auto hit = tree.first_intersection(ray);
    if (!hit) return {-1, INFINITY};
    const K::Point_3* point = boost::get<K::Point_3>(&hit->first);
    int id = ids[hit->second - triangles.begin()];
    if (!point) return {id, 0.0};  // a segment: the ray runs in the triangle's plane
    K::Vector_3 d(r.dx, r.dy, r.dz);
    return {id, ((*point - ray.source()) * d) / (d * d)};
  }

  bool occluded(const QueryRay& r) const {
    K::Point_3 o(r.ox, r.oy, r.oz);
    K::Vector_3 d(r.dx, r.dy, r.dz);
    return tree.do_intersect(K::Segment_3(o + double(r.tmin) * d, o + double(r.tmax) * d));
  }
};

// Within 1e-5 (relative) of an edge of the triangle, or nearly parallel to it.
bool nearEdge(const QueryRay& r, const ObjectGpu& ob) {
  const float* p = ob.p;
  K::Point_3 v0(p[0], p[1], p[2]), v1(p[3], p[4], p[5]), v2(p[6], p[7], p[8]);
  K::Vector_3 e1 = v1 - v0, e2 = v2 - v0, d(r.dx, r.dy, r.dz);
  K::Vector_3 n = CGAL::cross_product(e1, e2);
  double nl = std::sqrt(n * n), dl = std::sqrt(d * d);
  if (!(nl > 0) || std::fabs(n * d) < 1e-4 * nl * dl) return true;
  K::Vector_3 pv = CGAL::cross_product(d, e2), tv = K::Point_3(r.ox, r.oy, r.oz) - v0;
  double det = e1 * pv, u = (tv * pv) / det;
  K::Vector_3 qv = CGAL::cross_product(tv, e1);
  double v = (d * qv) / det;
  return std::fabs(std::min({u, v, 1 - u - v})) < 1e-5;
}

void checkAgainstOracle(const AccelScene& scene, int camera, std::size_t random) {
  Oracle oracle(scene.objects);
  const Aabb box = boundsOf(scene.objects);
  std::vector<QueryRay> rays = cameraRays(box, camera, camera);
  std::vector<QueryRay> extra = randomRays(box, random, 17);
  rays.insert(rays.end(), extra.begin(), extra.end());
  std::vector<std::pair<int, double>> expected;
  for (const QueryRay& r : rays) expected.push_back(oracle.closest(r));

  for (AccelKind kind : {AccelKind::Bvh, AccelKind::Octree, AccelKind::Bsp}) {
    RayQueryEngine engine(sharedContext(), scene.objects, kind);
    std::vector<HitGpu> hits = engine.intersect(rays);
    std::size_t agree = 0, unclear = 0, wrong = 0, hits_seen = 0;
    std::string first;
    for (std::size_t i = 0; i < rays.size(); ++i) {
      auto [id, t] = expected[i];
      const HitGpu& h = hits[i];
      hits_seen += h.prim >= 0;
      if (id == h.prim && (id < 0 || std::fabs(h.t - t) <= 1e-4 * std::max(1.0, t))) {
        ++agree;
        continue;
      }
      bool ambiguous = (id >= 0 && nearEdge(rays[i], scene.objects[id])) ||
                       (h.prim >= 0 && nearEdge(rays[i], scene.objects[h.prim])) ||
                       (id >= 0 && h.prim >= 0 && std::fabs(h.t - t) <= 1e-5 * std::max(1.0, t));
      if (ambiguous) {
        ++unclear;
      } else if (wrong++ == 0) {
        first = "ray " + std::to_string(i) + ": CGAL prim " + std::to_string(id) + " t " + std::to_string(t) +
                ", prism prim " + std::to_string(h.prim) + " t " + std::to_string(h.t);
      }
    }
    INFO(scene.name << " " << accelName(kind) << ": " << agree << " agree, " << unclear << " unclear, " << wrong
                    << " wrong of " << rays.size() << " (" << hits_seen << " hits); " << first);
    CHECK(hits_seen > rays.size() / 10);
    CHECK(wrong == 0);
    CHECK(unclear <= rays.size() / 500 + 2);

    // Occlusion of shadow segments from the hits towards a light.
    const float light[3] = {box.hi[0] + 1, box.hi[1] + 1, box.hi[2] + 1};
    std::vector<QueryRay> shadows = shadowRays(rays, hits, light);
    std::vector<std::uint8_t> occluded = engine.occluded(shadows);
    std::size_t differ = 0, blocked = 0;
    for (std::size_t i = 0; i < shadows.size(); ++i) {
      blocked += occluded[i];
      differ += (occluded[i] != 0) != oracle.occluded(shadows[i]);
    }
    INFO(shadows.size() << " shadow rays, " << blocked << " blocked, " << differ << " differ from CGAL");
    CHECK(blocked > 0);
    CHECK(differ <= shadows.size() / 500 + 2);
  }
}

}  // namespace

TEST_CASE("prism's structures match CGAL's AABB tree on real meshes", "[accel][cgal]") {
  for (const char* file : {"bunny/bun_zipper_res2.ply", "spot/spot.obj", "suzanne/suzanne.obj"}) {
    SharedMesh mesh = loadTestMesh(file);
    checkAgainstOracle(meshScene(file, *mesh), 96, 10000);
  }
}

TEST_CASE("prism's structures match CGAL's AABB tree on generated meshes", "[accel][cgal]") {
  checkAgainstOracle(meshScene("icosphere4", icosphere(4, 0.1f, -0.2f, 0.3f, 2.0f)), 96, 10000);
  checkAgainstOracle(meshScene("torus", bumpyTorus(30000)), 96, 10000);
}
