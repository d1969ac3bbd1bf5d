// "Set of normals" bounds (Kay and Kajiya) on the BVH's children: each child's
// diagonal slabs hold every vertex of the triangles below it (checked against
// the geometry, not the builder's own numbers), and on slanted geometry they
// spare node visits that boxes cannot. That the hits stay the same is
// accel_agreement_test's (every scene there also runs with k-DOP bounds).
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <memory>
#include <string>
#include <vector>

#include "accel/accel_scenes.h"
#include "accel/kdop_bounds.h"
#include "kernels/shared/bvh_node_gpu.h"
#include "render/ray_queries.h"
#include "support/shared_context.h"

using namespace prism;
using namespace prism::test;

namespace {

// A square plate of n x n quads in the plane through the origin with normal
// (1, 1, 1): slanted against every axis, so the boxes of its pieces are cubes
// around thin sheets.
TriangleMesh slantedPlate(int n) {
  const double u[3] = {1 / std::sqrt(2.0), -1 / std::sqrt(2.0), 0};
  const double v[3] = {1 / std::sqrt(6.0), 1 / std::sqrt(6.0), -2 / std::sqrt(6.0)};
  TriangleMesh m;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double a = -1 + 2.0 * i / n, b = -1 + 2.0 * j / n;
      for (int k = 0; k < 3; ++k) m.positions.push_back(static_cast<float>(a * u[k] + b * v[k]));
    }
  auto at = [&](int i, int j) { return static_cast<std::uint32_t>(j * (n + 1) + i); };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      m.indices.insert(m.indices.end(),
                       {at(i, j), at(i + 1, j), at(i + 1, j + 1), at(i, j), at(i + 1, j + 1), at(i, j + 1)});
  return m;
}

// Every triangle lane of every leaf under wide node `node`, its vertices
// projected on each diagonal, against the slabs its parent's slot holds.
std::size_t checkLeaves(const DeviceAccel& accel, const std::vector<ObjectGpu>& objects, std::size_t* outside) {
  const float* nodes = accel.nodes[2].v;
  constexpr std::size_t kNodeFloats = (7 + 8) * 8;
  std::size_t checked = 0;
  std::vector<int> stack{0};
  while (!stack.empty()) {
    const float* n = nodes + kNodeFloats * static_cast<std::size_t>(stack.back());
    stack.pop_back();
    for (int slot = 0; slot < BVH_WIDTH; ++slot) {
      int child;
      std::memcpy(&child, n + 48 + slot, sizeof child);
      if (child > 0) stack.push_back(child);
      if (child >= 0) continue;
      const int code = ~child, start = code >> BVH_LEAF_COUNT_BITS, count = (code & (BVH_LEAF_MAX_PACKETS - 1)) + 1;
      for (int p = start; p < start + count; ++p)
        for (int lane = 0; lane < PACKET_LANES; ++lane) {
          const int prim = accel.packets[p].prim[lane];
          if (prim < 0) continue;
          const float* q = objects[prim].p;
          for (int k = 0; k < 3; ++k)
            for (int j = 0; j < BVH_KDOP_DIAGONALS; ++j) {
              const double d = diagonalDot(j, q[3 * k], q[3 * k + 1], q[3 * k + 2]);
              const float* slab = n + 56 + 16 * j;
              *outside += !(slab[slot] <= d && d <= slab[8 + slot]);
              ++checked;
            }
        }
    }
  }
  return checked;
}

}  // namespace

TEST_CASE("k-DOP slabs hold every vertex below them, and cut node visits on slanted geometry", "[accel][kdop]") {
  AccelBuildOptions kdop_options;
  kdop_options.kdop_objects = kdop_options.kdop_bvh = true;
  for (const char* name : {"bunny", "plate"}) {
    INFO(name);
    const TriangleMesh mesh =
        std::string(name) == "bunny" ? *loadTestMesh("bunny/bun_zipper_res2.ply") : slantedPlate(120);
    const std::vector<ObjectGpu> objects = trianglesFromMesh(mesh);
    RayQueryEngine boxes(sharedContext(), objects, AccelKind::Bvh);
    RayQueryEngine kdop(sharedContext(), objects, AccelKind::Bvh, {}, kdop_options);
    std::size_t outside = 0;
    CHECK(checkLeaves(kdop.accel(), objects, &outside) == 3 * BVH_KDOP_DIAGONALS * mesh.triangleCount());
    CHECK(outside == 0);

    const Aabb box = boundsOf(objects);
    std::vector<QueryRay> rays = randomRays(box, 4000, 21);
    const std::vector<HitGpu> hits = boxes.intersect(rays);
    REQUIRE(kdop.intersect(rays).size() == hits.size());
    const BvhVisits by_box = bvhNodeVisits(boxes.accel(), rays, hits);
    const BvhVisits by_kdop = bvhNodeVisits(kdop.accel(), rays, hits);
    INFO("visits per ray, inner + leaves: boxes " << by_box.inner << " + " << by_box.leaves << ", k-DOP "
                                                  << by_kdop.inner << " + " << by_kdop.leaves);
    CHECK(by_kdop.inner <= by_box.inner);
    CHECK(by_kdop.leaves <= by_box.leaves);
    // Each piece of the plate is a sheet across a cube: the slab along (1, 1, 1)
    // is nearly flat where the box is not, so most rays that meet a box miss
    // it. (Below the root, which every ray visits.)
    if (std::string(name) == "plate")
      CHECK(by_kdop.inner - 1 + by_kdop.leaves < 0.5 * (by_box.inner - 1 + by_box.leaves));
  }
}

TEST_CASE("every hit on an analytic object lies within the slabs its leaf lane keeps for it", "[accel][kdop]") {
  // The scene of every kind (quadrics, polygons, polyhedra, patch pieces,
  // transformed and moving objects); hits from brute force, which uses no slabs.
  AccelScene scene = mixedScene(300);
  AccelBuildOptions kdop;
  kdop.kdop_objects = true;
  RayQueryEngine none(sharedContext(), scene.objects, AccelKind::None);
  const std::unique_ptr<DeviceAccel> bvh = buildAccel(AccelKind::Bvh, scene.objects, kdop);
  REQUIRE(bvh->kernel_options.find("-DPRISM_OBJECT_KDOP") != std::string::npos);
  struct Lane {
    const TriPacketGpu* packet;
    int k;
  };
  std::vector<Lane> lane_of(scene.objects.size(), Lane{nullptr, 0});
  for (const TriPacketGpu& p : bvh->packets)
    for (int k = 0; k < PACKET_LANES; ++k)
      if (p.prim[k] <= -2) lane_of[-p.prim[k] - 2] = Lane{&p, k};
  const Aabb box = boundsOf(scene.objects);
  std::vector<QueryRay> rays = randomRays(box, 20000, 8);
  const std::vector<QueryRay> camera = cameraRays(box, 96, 96);
  rays.insert(rays.end(), camera.begin(), camera.end());
  const std::vector<HitGpu> hits = none.intersect(rays);
  std::size_t checked = 0, outside = 0;
  for (std::size_t r = 0; r < rays.size(); ++r) {
    if (hits[r].prim < 0 || !lane_of[hits[r].prim].packet) continue;
    const Lane& lane = lane_of[hits[r].prim];
    const float* f = lane.packet->v0x;
    const QueryRay& q = rays[r];
    const double o[3] = {q.ox, q.oy, q.oz}, d[3] = {q.dx, q.dy, q.dz};
    const double t = hits[r].t;
    for (int j = 0; j < BVH_KDOP_DIAGONALS; ++j) {
      // Where the hit point projects, against the slab the kernel tests
      // (packet_lane_slabs_meet), without its per-ray slack.
      const double p = diagonalDot(j, o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2]);
      const double lo = f[8 * j + lane.k], hi = f[8 * j + 4 + lane.k];
      const double tolerance = 1e-6 * (std::fabs(lo) + std::fabs(hi) + std::fabs(o[0]) + std::fabs(o[1]) + std::fabs(o[2]));
      outside += p < lo - tolerance || p > hi + tolerance;
    }
    ++checked;
  }
  INFO(checked << " hits on analytic objects checked");
  CHECK(checked > 500);
  CHECK(outside == 0);
}
