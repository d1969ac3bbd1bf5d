// The builders' output, read back from the device layouts: every primitive
// that meets an octree or BSP cell (decided by brute force over all
// primitives) is in that cell's leaf, no primitive is lost in an octant or
// side that was not stored, the BVH holds each primitive exactly once inside
// its boxes; names, statistics, determinism across thread counts, and
// triangles lying exactly on the octree's splitting planes.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <functional>
#include <limits>
#include <random>
#include <set>

#include "accel/accel_scenes.h"
#include "accel/exact_predicates.h"
#include "kernels/shared/bsp_node_gpu.h"
#include "kernels/shared/bvh_node_gpu.h"
#include "kernels/shared/octree_node_gpu.h"
#include "render/gpu_scene.h"
#include "render/ray_queries.h"
#include "render/render_options.h"
#include "scene_format/scene_loader.h"
#include "support/shared_context.h"

using namespace prism;
using namespace prism::test;

namespace {

CellBox headerBox(const DeviceAccel& a) {
  return {{a.nodes[0].v[0], a.nodes[0].v[1], a.nodes[0].v[2]}, {a.nodes[1].v[0], a.nodes[1].v[1], a.nodes[1].v[2]}};
}

std::set<int> packetPrims(const DeviceAccel& a, std::size_t start, std::size_t count) {
  std::set<int> ids;
  for (std::size_t p = start; p < start + count; ++p)
    for (int k = 0; k < PACKET_LANES; ++k) {
      int id = a.packets[p].prim[k];
      if (id >= 0) ids.insert(id & ~PACKET_MOVING);
      if (id <= -2) ids.insert(-id - 2);
    }
  return ids;
}

struct Cells {
  std::vector<std::pair<CellBox, std::set<int>>> leaves;  // stored cells and their primitives
  std::vector<CellBox> missing;                           // octants / sides with nothing stored
  std::vector<CellBox> content;                           // octree: leaves[i]'s content box
  std::size_t boxes_outside_parent = 0;                   // octree: content boxes not inside their parent's
};

CellBox contentBox(const OctreeNodeGpu& n) {
  return {{n.lo_x, n.lo_y, n.lo_z}, {n.hi_x, n.hi_y, n.hi_z}};
}

bool inside(const CellBox& a, const CellBox& b) {
  for (int axis = 0; axis < 3; ++axis)
    if (a.lo[axis] < b.lo[axis] || a.hi[axis] > b.hi[axis]) return false;
  return true;
}

Cells octreeCells(const DeviceAccel& a) {
  Cells out;
  const OctreeNodeGpu* nodes = nodesOf<OctreeNodeGpu>(a);
  std::function<void(int, CellBox, CellBox)> walk = [&](int index, CellBox box, CellBox parent_content) {
    const OctreeNodeGpu& n = nodes[index];
    if (!inside(contentBox(n), parent_content)) ++out.boxes_outside_parent;
    if (!n.child_mask) {
      out.leaves.push_back({box, packetPrims(a, n.first, n.packet_count)});
      out.content.push_back(contentBox(n));
      return;
    }
    const float c[3] = {n.cx, n.cy, n.cz};
    int child = n.first;
    for (int k = 0; k < 8; ++k) {
      CellBox o = box;
      for (int axis = 0; axis < 3; ++axis) (k >> axis & 1 ? o.lo[axis] : o.hi[axis]) = c[axis];
      if (n.child_mask >> k & 1)
        walk(child++, o, contentBox(n));
      else
        out.missing.push_back(o);
    }
  };
  walk(0, headerBox(a), headerBox(a));
  return out;
}

Cells bspCells(const DeviceAccel& a) {
  Cells out;
  const BspNodeGpu* nodes = nodesOf<BspNodeGpu>(a);
  std::function<void(int, CellBox)> walk = [&](int index, CellBox box) {
    const BspNodeGpu& n = nodes[index];
    int axis = n.word & 3;
    if (axis == BSP_LEAF) {
      out.leaves.push_back({box, packetPrims(a, n.word >> 2, n.payload)});
      return;
    }
    float split;
    std::memcpy(&split, &n.payload, sizeof split);
    CellBox below = box, above = box;
    below.hi[axis] = above.lo[axis] = split;
    walk(index + 1, below);
    walk(n.word >> 2, above);
  };
  walk(0, headerBox(a));
  return out;
}

// Brute force: each primitive meeting a cell is in it; no primitive meets a
// cell left out of the tree.
void checkComplete(const std::vector<ObjectGpu>& objects, const Cells& cells) {
  PrimitiveSet prims = gatherPrimitives(objects);
  std::size_t lost = 0, checked = 0;
  std::string first;
  for (const auto& [box, ids] : cells.leaves)
    for (std::size_t i = 0; i < prims.bounded.size(); ++i) {
      int id = prims.bounded[i];
      if (ids.count(id) || !overlapsCell(objects[id], prims.bounds[i], box, nullptr)) continue;
      if (lost++ == 0) first = "primitive " + std::to_string(id) + " missing from a leaf it meets";
    }
  for (const CellBox& box : cells.missing)
    for (std::size_t i = 0; i < prims.bounded.size(); ++i) {
      ++checked;
      if (overlapsCell(objects[prims.bounded[i]], prims.bounds[i], box, nullptr) && lost++ == 0)
        first = "primitive " + std::to_string(prims.bounded[i]) + " meets a cell that was not stored";
    }
  INFO(cells.leaves.size() << " leaves, " << cells.missing.size() << " cells left out; " << first);
  CHECK(lost == 0);
}

}  // namespace

TEST_CASE("a static triangle's box is its vertices' grown by 2^-20 of its largest extent, rounded outward, one float more",
          "[accel][builder]") {
  // The reference: the double arithmetic objectBounds documents, then the
  // nearest float on the outer side found by stepping with std::nextafter, and
  // one step more; compared bit for bit. Coordinates of every sign around zero
  // (where the rounding's direction changes), of many magnitudes, and zeros.
  const float inf = std::numeric_limits<float>::infinity();
  auto outward = [inf](double x, bool down) {
    float f = static_cast<float>(x);
    while (down ? double(f) > x : double(f) < x) f = std::nextafter(f, down ? -inf : inf);
    return std::nextafter(f, down ? -inf : inf);
  };
  auto bits = [](float f) {
    std::uint32_t b;
    std::memcpy(&b, &f, sizeof b);
    return b;
  };
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> unit(-1, 1);
  std::uniform_int_distribution<int> exponent(-30, 30), kind(0, 9);
  for (int n = 0; n < 20000; ++n) {
    ObjectGpu g{};
    g.type = OBJECT_TRIANGLE;
    const int e = exponent(rng);
    for (float& v : g.p) v = kind(rng) == 0 ? 0.0f : static_cast<float>(std::ldexp(unit(rng), e));
    double lo[3], hi[3], extent = 0;
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::min({g.p[a], g.p[3 + a], g.p[6 + a]});
      hi[a] = std::max({g.p[a], g.p[3 + a], g.p[6 + a]});
      extent = std::max(extent, hi[a] - lo[a]);
    }
    const double pad = extent * 0x1p-20;
    Aabb box;
    REQUIRE(objectBounds(g, &box));
    for (int a = 0; a < 3; ++a) {
      INFO("triangle " << n << ", axis " << a << ": " << lo[a] << " to " << hi[a]);
      CHECK(bits(box.lo[a]) == bits(outward(lo[a] - pad, true)));
      CHECK(bits(box.hi[a]) == bits(outward(hi[a] + pad, false)));
    }
  }
  // Not a triangle of finite vertices: no box.
  for (float bad : {inf, -inf, std::numeric_limits<float>::quiet_NaN()}) {
    ObjectGpu g{};
    g.type = OBJECT_TRIANGLE;
    g.p[4] = bad;
    Aabb box;
    CHECK_FALSE(objectBounds(g, &box));
  }
  // Vertices so large that the padded box leaves the floats.
  ObjectGpu huge{};
  huge.type = OBJECT_TRIANGLE;
  huge.p[0] = std::numeric_limits<float>::max();
  huge.p[3] = -std::numeric_limits<float>::max();
  Aabb box;
  CHECK_FALSE(objectBounds(huge, &box));
}

TEST_CASE("structure names parse, print and reject unknown names with the valid list", "[accel][builder]") {
  for (AccelKind kind : allAccelKinds()) CHECK(parseAccelKind(accelName(kind)) == kind);
  CHECK(allAccelKinds().size() == 4);  // the structures; auto is none of them
  CHECK(parseAccelKind("auto") == AccelKind::Auto);
  CHECK(std::string(accelName(AccelKind::Auto)) == "auto");
  CHECK_THROWS_WITH(parseAccelKind("kdtree"), Catch::Contains("'kdtree'") && Catch::Contains("bvh") &&
                                                  Catch::Contains("octree") && Catch::Contains("bsp") &&
                                                  Catch::Contains("none"));
  AccelKind k;
  CHECK_FALSE(tryParseAccelKind("BVH", &k));
  RenderOptions defaults;
  CHECK(defaults.accel == AccelKind::Auto);
}

TEST_CASE("every octree and BSP leaf holds every primitive that meets its cell", "[accel][builder]") {
  AccelScene scene = mixedScene(800);
  AccelBuildOptions small;
  small.octree_leaf_prims = 4;  // deeper trees: more boundaries to get right
  auto octree = buildAccel(AccelKind::Octree, scene.objects, small);
  auto bsp = buildAccel(AccelKind::Bsp, scene.objects, small);
  INFO(describeAccel(*octree));
  INFO(describeAccel(*bsp));
  CHECK(octree->stats.exact_tests > 0);
  CHECK(octree->stats.straddling > 0);
  CHECK(bsp->stats.straddling > 0);
  checkComplete(scene.objects, octreeCells(*octree));
  checkComplete(scene.objects, bspCells(*bsp));
}

TEST_CASE("an octree cell's content box holds every part of its primitives inside the cell", "[accel][builder]") {
  // The traversal skips a cell whose content box the ray misses and searches
  // only the stretch of the ray inside it, so the box must hold the part of
  // every primitive of the cell that lies in the cell (decided exactly: no
  // primitive meets the slabs of the cell outside the box; and the part
  // clipped in double lies in it), lie in the cell, and lie in its parent's box.
  AccelScene scene = mixedScene(3000);
  auto octree = buildAccel(AccelKind::Octree, scene.objects);
  Cells cells = octreeCells(*octree);
  PrimitiveSet prims = gatherPrimitives(scene.objects);
  std::vector<int> position(scene.objects.size(), -1);
  for (std::size_t i = 0; i < prims.bounded.size(); ++i) position[prims.bounded[i]] = static_cast<int>(i);
  std::size_t outside_cell = 0, reaching_out = 0, tested = 0, clipped_outside = 0, clipped = 0;
  for (std::size_t leaf = 0; leaf < cells.leaves.size(); ++leaf) {
    const auto& [cell, ids] = cells.leaves[leaf];
    const CellBox& box = cells.content[leaf];
    if (ids.empty()) continue;
    if (!inside(box, cell)) ++outside_cell;
    // The part of each primitive inside the cell, clipped in double and
    // rounded outward (the BSP's perfect-split bounds), lies in the box.
    for (int id : ids) {
      Aabb part = clippedBounds(scene.objects[id], prims.bounds[position[id]], cell);
      if (part.empty()) continue;
      ++clipped;
      if (!inside(toCell(part), box)) ++clipped_outside;
    }
    for (int axis = 0; axis < 3; ++axis)
      for (int side = 0; side < 2; ++side) {
        CellBox slab = cell;
        if (side == 0) {
          slab.hi[axis] = std::nextafter(static_cast<float>(box.lo[axis]), -INFINITY);
          if (!(slab.hi[axis] >= cell.lo[axis])) continue;
        } else {
          slab.lo[axis] = std::nextafter(static_cast<float>(box.hi[axis]), INFINITY);
          if (!(slab.lo[axis] <= cell.hi[axis])) continue;
        }
        for (int id : ids) {
          ++tested;
          if (overlapsCell(scene.objects[id], prims.bounds[position[id]], slab, nullptr)) ++reaching_out;
        }
      }
  }
  INFO(cells.leaves.size() << " leaves, " << tested << " primitive-slab tests, " << clipped << " clipped parts");
  CHECK(tested > 1000);
  CHECK(clipped > 1000);
  CHECK(clipped_outside == 0);
  CHECK(outside_cell == 0);
  CHECK(reaching_out == 0);
  CHECK(cells.boxes_outside_parent == 0);
}

namespace {

// Each lane of a packet as appendLeafPackets writes it: a packet triangle's
// (or a moving one's, its id flagged PACKET_MOVING) vertex and edges, or
// another primitive's id to test one by one. Returns the lanes that are not.
std::size_t wrongLanes(const DeviceAccel& a, const std::vector<ObjectGpu>& objects) {
  std::size_t wrong = 0;
  for (const TriPacketGpu& p : a.packets)
    for (int k = 0; k < PACKET_LANES; ++k) {
      const int id = p.prim[k];
      if (id == PACKET_EMPTY) continue;
      if (id <= -2) {
        const ObjectGpu& ob = objects[-id - 2];
        wrong += isPacketTriangle(ob) || (isMovingPacketTriangle(ob) && -id - 2 < PACKET_MOVING);
        continue;
      }
      const bool moving = (id & PACKET_MOVING) != 0;
      const ObjectGpu& ob = objects[id & ~PACKET_MOVING];
      const float* v = ob.p;
      wrong += !(moving ? isMovingPacketTriangle(ob) : isPacketTriangle(ob)) || p.v0x[k] != v[0] ||
               p.v0y[k] != v[1] || p.v0z[k] != v[2] || p.e1x[k] != v[3] - v[0] || p.e1y[k] != v[4] - v[1] ||
               p.e1z[k] != v[5] - v[2] || p.e2x[k] != v[6] - v[0] || p.e2y[k] != v[7] - v[1] ||
               p.e2z[k] != v[8] - v[2];
    }
  return wrong;
}

// Static objects, a plane among them, then moving ones: the gather closes its
// arrays up over the plane and bounds the moving objects after its threads.
const char* kMovingScene = R"({
  "camera": {"shutter": [0, 1]},
  "objects": [
    {"type": "sphere", "center": [0, 0, 0], "radius": 1},
    {"type": "triangle", "vertices": [[0, 0, 2], [1, 0, 2], [0, 1, 2]]},
    {"type": "plane", "point": [0, -2, 0], "normal": [0, 1, 0]},
    {"type": "box", "min": [-3, -1, -1], "max": [-2, 1, 1]},
    {"type": "triangle", "vertices": [[2, 0, 0], [3, 0, 0], [2, 1, 0]], "transform_end": {"translate": [0, 1, 0]}},
    {"type": "triangle", "vertices": [[2, 0, 1], [3, 0, 1], [2, 1, 1]], "transform_end": {"translate": [0, 1, 0]}},
    {"type": "sphere", "center": [5, 0, 0], "radius": 0.5, "transform_end": {"translate": [1, 0, 0]}},
    {"type": "triangle", "vertices": [[0, 3, 0], [1, 3, 0], [0, 4, 0]]}
  ]
})";

AccelScene movingScene() {
  const Scene scene = parseScene(kMovingScene, "moving.json");
  AccelScene s;
  s.name = "moving";
  s.objects = flattenScene(scene, RenderOptions::fromScene(scene)).objects;
  return s;
}

}  // namespace

// Four scenes, for the gather's and the packets' paths: with planes
// (unbounded), every primitive bounded but of several kinds, a mesh (packet
// triangles only, whose leaves' packets are written in place), and moving
// primitives (built over their swept boxes, whose nodes are plain BVH nodes).
TEST_CASE("the BVH holds each bounded primitive once, inside its boxes", "[accel][builder]") {
  AccelScene mixed = mixedScene(2000);
  AccelScene bounded = mixed;
  bounded.objects.erase(std::remove_if(bounded.objects.begin(), bounded.objects.end(),
                                       [](const ObjectGpu& o) { return o.type == OBJECT_PLANE; }),
                        bounded.objects.end());
  const AccelScene scenes[] = {mixed, bounded, meshScene("torus", bumpyTorus(20000)), movingScene()};
  AccelBuildOptions swept;
  swept.bvh_linear_bounds = false;
  for (const AccelScene& scene : scenes) {
    INFO(scene.name << ", " << scene.objects.size() << " objects");
    auto bvh = buildAccel(AccelKind::Bvh, scene.objects, swept);
    PrimitiveSet prims = gatherPrimitives(scene.objects);
    std::vector<int> seen(scene.objects.size(), 0);
    const BvhNodeGpu* nodes = nodesOf<BvhNodeGpu>(*bvh);
    std::size_t outside = 0;
    std::function<void(int)> walk = [&](int index) {
      const BvhNodeGpu& n = nodes[index];
      for (int i = 0; i < BVH_WIDTH; ++i) {
        int code = n.child[i];
        if (code > 0) walk(code);
        if (code >= 0) continue;
        int x = ~code;
        for (int id : packetPrims(*bvh, x >> BVH_LEAF_COUNT_BITS, (x & (BVH_LEAF_MAX_PACKETS - 1)) + 1)) {
          ++seen[id];
          Aabb b;
          REQUIRE(objectBounds(scene.objects[id], &b));
          outside += b.lo[0] < n.lo_x[i] || b.hi[0] > n.hi_x[i] || b.lo[1] < n.lo_y[i] || b.hi[1] > n.hi_y[i] ||
                     b.lo[2] < n.lo_z[i] || b.hi[2] > n.hi_z[i];
        }
      }
    };
    walk(0);
    CHECK(outside == 0);
    CHECK(wrongLanes(*bvh, scene.objects) == 0);
    for (std::size_t i = 0; i < prims.bounded.size(); ++i) CHECK(seen[prims.bounded[i]] == 1);
    for (int id : prims.unbounded) CHECK(seen[id] == 0);
    CHECK(bvh->unbounded == prims.unbounded);
    CHECK(bvh->stats.duplication == 1.0);
    CHECK(bvh->stats.references == prims.bounded.size());
  }
}

TEST_CASE("builds report their statistics", "[accel][builder]") {
  AccelScene scene = meshScene("torus", bumpyTorus(20000));
  for (AccelKind kind : {AccelKind::Bvh, AccelKind::Octree, AccelKind::Bsp}) {
    auto a = buildAccel(kind, scene.objects);
    const AccelStats& s = a->stats;
    INFO(describeAccel(*a));
    CHECK(s.primitives == scene.objects.size());
    CHECK(s.unbounded == 0);
    CHECK(s.build_seconds > 0);
    CHECK(s.bytes == a->nodes.size() * 16 + a->packets.size() * sizeof(TriPacketGpu));
    CHECK(s.node_count >= s.leaf_count);
    CHECK(s.leaf_count > 0);
    CHECK(s.mean_prims_per_leaf > 1);
    CHECK(s.sah_cost > 1);
    CHECK(s.duplication >= 1);
    CHECK(s.references >= s.primitives);
    CHECK(s.max_depth > 1);
    CHECK_THAT(a->kernel_options, Catch::Contains("-DPRISM_ACCEL_") && Catch::Contains("-DPRISM_ACCEL_STACK="));
  }
}

TEST_CASE("builds are the same whatever the number of threads", "[accel][builder]") {
  // A mesh (every primitive bounded and static) and a mix with planes,
  // transformed objects and degenerate triangles, large enough for the
  // primitives' boxes to be cut into runs.
  for (const AccelScene& scene : {meshScene("torus", bumpyTorus(60000)), mixedScene(20000)}) {
    for (AccelKind kind : {AccelKind::Bvh, AccelKind::Octree, AccelKind::Bsp}) {
      AccelBuildOptions one;
      one.threads = 1;
      auto a = buildAccel(kind, scene.objects, one);
      // Two and three threads: the bounds, references and leaf packets are cut
      // into as many runs.
      for (int threads : {2, 3}) {
        AccelBuildOptions more;
        more.threads = threads;
        auto b = buildAccel(kind, scene.objects, more);
        INFO(scene.name << ", " << accelName(kind) << " on " << threads << " threads");
        REQUIRE(a->nodes.size() == b->nodes.size());
        REQUIRE(a->packets.size() == b->packets.size());
        CHECK(std::memcmp(a->nodes.data(), b->nodes.data(), a->nodes.size() * sizeof(AccelWord)) == 0);
        CHECK(std::memcmp(a->packets.data(), b->packets.data(), a->packets.size() * sizeof(TriPacketGpu)) == 0);
        CHECK(a->unbounded == b->unbounded);
        CHECK(a->kernel_options == b->kernel_options);
      }
    }
  }
}

TEST_CASE("triangles lying exactly on the octree's splitting planes are found", "[accel][builder]") {
  AccelScene scene = meshScene("soup", triangleSoup(3000, 21, 0.03f));
  auto first = buildAccel(AccelKind::Octree, scene.objects);
  const OctreeNodeGpu root = nodesOf<OctreeNodeGpu>(*first)[0];
  REQUIRE(root.child_mask != 0);
  const float c[3] = {root.cx, root.cy, root.cz};
  // Small triangles in the three centre planes, well inside the scene's box,
  // so the root cell (and so its centre) stays the same.
  std::vector<int> on_plane;
  for (int axis = 0; axis < 3; ++axis)
    for (int k = 0; k < 10; ++k) {
      ObjectGpu g = identityObject(OBJECT_TRIANGLE, 0);
      float a = 0.2f + 0.06f * k, b = 0.3f + 0.05f * k;
      float pts[3][2] = {{a, b}, {a + 0.02f, b}, {a, b + 0.02f}};
      for (int v = 0; v < 3; ++v) {
        g.p[3 * v + axis] = c[axis];
        g.p[3 * v + (axis + 1) % 3] = pts[v][0];
        g.p[3 * v + (axis + 2) % 3] = pts[v][1];
      }
      on_plane.push_back(static_cast<int>(scene.objects.size()));
      scene.objects.push_back(g);
    }
  auto octree = buildAccel(AccelKind::Octree, scene.objects);
  const OctreeNodeGpu& again = nodesOf<OctreeNodeGpu>(*octree)[0];
  REQUIRE(again.cx == c[0]);
  REQUIRE(again.cy == c[1]);
  REQUIRE(again.cz == c[2]);
  checkComplete(scene.objects, octreeCells(*octree));

  // Rays from both sides of each plane through each triangle's centroid find it.
  std::vector<QueryRay> rays;
  for (int id : on_plane) {
    const float* p = scene.objects[id].p;
    float m[3];
    for (int a = 0; a < 3; ++a) m[a] = (p[a] + p[3 + a] + p[6 + a]) / 3;
    int axis = p[0] == p[3] && p[0] == p[6] ? 0 : (p[1] == p[4] && p[1] == p[7] ? 1 : 2);
    for (float side : {-1.0f, 1.0f}) {
      QueryRay r{m[0], m[1], m[2], 0, 0, 0, 0, INFINITY};
      (&r.ox)[axis] -= side * 2;
      (&r.dx)[axis] = side;
      rays.push_back(r);
    }
  }
  RayQueryEngine none(sharedContext(), scene.objects, AccelKind::None);
  std::vector<HitGpu> ref = none.intersect(rays);
  for (AccelKind kind : {AccelKind::Octree, AccelKind::Bsp, AccelKind::Bvh}) {
    RayQueryEngine engine(sharedContext(), scene.objects, kind);
    std::vector<HitGpu> hits = engine.intersect(rays);
    for (std::size_t i = 0; i < rays.size(); ++i) {
      INFO(accelName(kind) << " ray " << i);
      CHECK(hits[i].prim == ref[i].prim);
      CHECK(hits[i].t == ref[i].t);
    }
  }
}
