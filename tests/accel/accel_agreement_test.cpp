// The four structures (bvh, octree, bsp and brute-force none) give the same
// answers on the same rays: the same closest primitive with bit-identical t,
// u and v (up to exact ties in t), the same occlusion, and the same
// transmittance through semitransparent primitives. Over a scene with every
// primitive kind, procedural meshes and real meshes, with camera rays,
// random rays, shadow rays and rays aimed at vertices and edges, and rays from
// afar past cell faces that lie within a rounding of the primitives.
#include <catch2/catch.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <memory>
#include <utility>
#include <random>
#include <sstream>

#include "accel/accel_scenes.h"
#include "kernels/shared/octree_node_gpu.h"
#include "render/ray_queries.h"
#include "support/shared_context.h"

using namespace prism;
using namespace prism::test;

namespace {

bool sameBits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// Rays through vertices and edge midpoints of the scene's triangles, from
// random points around: they meet several triangles at exactly the same t.
std::vector<QueryRay> vertexRays(const std::vector<ObjectGpu>& objects, std::size_t count, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<std::size_t> tris;
  for (std::size_t i = 0; i < objects.size(); ++i)
    if (objects[i].type == OBJECT_TRIANGLE) tris.push_back(i);
  std::vector<QueryRay> rays;
  if (tris.empty()) return rays;
  Aabb box = boundsOf(objects);
  std::uniform_real_distribution<float> u01(0, 1);
  for (std::size_t k = 0; k < count; ++k) {
    const float* p = objects[tris[rng() % tris.size()]].p;
    int v = static_cast<int>(rng() % 3), w = (v + 1) % 3;
    bool edge = rng() % 2;
    float target[3];
    for (int a = 0; a < 3; ++a) target[a] = edge ? 0.5f * (p[3 * v + a] + p[3 * w + a]) : p[3 * v + a];
    float o[3];
    for (int a = 0; a < 3; ++a) o[a] = box.lo[a] - 0.5f * (box.hi[a] - box.lo[a]) + 2 * (box.hi[a] - box.lo[a]) * u01(rng);
    rays.push_back(QueryRay{o[0], o[1], o[2], 0, target[0] - o[0], target[1] - o[1], target[2] - o[2], INFINITY});
  }
  return rays;
}

// Whether float arithmetic may decide this ray/primitive pair either way: the
// ray meets the triangle (in double) within a relative 1e-5 of an edge, or
// nearly parallel to it. Only triangles are judged; anything else is never
// "too close to call".
bool ambiguous(const QueryRay& r, const ObjectGpu& ob) {
  if (ob.type != OBJECT_TRIANGLE) return false;
  const float* p = ob.p;
  double v0[3] = {p[0], p[1], p[2]}, e1[3], e2[3], d[3] = {r.dx, r.dy, r.dz}, o[3] = {r.ox, r.oy, r.oz};
  for (int a = 0; a < 3; ++a) {
    e1[a] = double(p[3 + a]) - v0[a];
    e2[a] = double(p[6 + a]) - v0[a];
  }
  auto cross = [](const double* x, const double* y, double* z) {
    z[0] = x[1] * y[2] - x[2] * y[1];
    z[1] = x[2] * y[0] - x[0] * y[2];
    z[2] = x[0] * y[1] - x[1] * y[0];
  };
  auto dot = [](const double* x, const double* y) { return x[0] * y[0] + x[1] * y[1] + x[2] * y[2]; };
  double n[3], pv[3], tv[3], qv[3];
  cross(e1, e2, n);
  double nl = std::sqrt(dot(n, n)), dl = std::sqrt(dot(d, d));
  if (!(nl > 0) || std::fabs(dot(n, d)) < 1e-4 * nl * dl) return true;  // degenerate or grazing
  cross(d, e2, pv);
  double det = dot(e1, pv);
  for (int a = 0; a < 3; ++a) tv[a] = o[a] - v0[a];
  double u = dot(tv, pv) / det;
  cross(tv, e1, qv);
  double v = dot(d, qv) / det;
  double margin = std::min({u, v, 1 - u - v});
  return std::fabs(margin) < 1e-5;
}

struct Comparison {
  std::size_t rays = 0, hits = 0, ties = 0, ambiguous = 0, mismatches = 0;
  std::string first;
};

// `got` against `ref`: identical hits (prim, and t, u, v to the bit), exact
// ties in t, and pairs float cannot call (ambiguous above); anything else is a
// mismatch.
Comparison compareHits(const std::vector<ObjectGpu>& objects, const std::vector<QueryRay>& rays,
                       const std::vector<HitGpu>& ref, const std::vector<HitGpu>& got) {
  Comparison c;
  c.rays = rays.size();
  for (std::size_t i = 0; i < rays.size(); ++i) {
    const HitGpu& a = ref[i];
    const HitGpu& b = got[i];
    if (a.prim >= 0) ++c.hits;
    bool same = a.prim == b.prim && (a.prim < 0 || (sameBits(a.t, b.t) && sameBits(a.u, b.u) && sameBits(a.v, b.v)));
    if (same) continue;
    if (a.prim >= 0 && b.prim >= 0 && a.t == b.t) {
      ++c.ties;
      continue;
    }
    if ((a.prim >= 0 && ambiguous(rays[i], objects[a.prim])) || (b.prim >= 0 && ambiguous(rays[i], objects[b.prim]))) {
      ++c.ambiguous;
      continue;
    }
    if (c.mismatches++ == 0) {
      std::ostringstream os;
      const QueryRay& r = rays[i];
      os.precision(9);
      os << "ray " << i << " o=(" << r.ox << "," << r.oy << "," << r.oz << ") d=(" << r.dx << "," << r.dy << ","
         << r.dz << ") [" << r.tmin << "," << r.tmax << "]: expected prim " << a.prim << " t " << a.t << ", got prim "
         << b.prim << " t " << b.t;
      c.first = os.str();
    }
  }
  return c;
}

// Hits that must be the same to the bit, ray for ray, ties included: one
// structure answering the same rays by two walks (render/ray_kernel.h).
void checkIdentical(const char* what, const std::vector<HitGpu>& ref, const std::vector<HitGpu>& got) {
  REQUIRE(got.size() == ref.size());
  std::size_t differ = 0, first = ref.size();
  for (std::size_t i = 0; i < ref.size(); ++i) {
    const HitGpu& a = ref[i];
    const HitGpu& b = got[i];
    const bool same = a.prim == b.prim && sameBits(a.t, b.t) && sameBits(a.u, b.u) && sameBits(a.v, b.v);
    if (!same && differ++ == 0) first = i;
  }
  INFO(what << ": " << differ << " of " << ref.size() << " hits differ; the first at ray " << first);
  CHECK(differ == 0);
}

// A structure's packet walk against its walk of one ray at a time, on all of
// `rays` and on a stretch of them starting three rays later, whose packets
// hold other rays together (and whose last packet is not full).
void checkPackets(RayQueryEngine& engine, const std::vector<QueryRay>& rays, const std::vector<HitGpu>& single) {
  INFO(describeAccel(engine.accel()));
  REQUIRE(engine.tracesPackets());  // (PacketUse::Always)
  checkIdentical("packets against one ray at a time", single, engine.intersect(rays, nullptr, RayCoherence::Coherent));
  if (rays.size() < 13) return;
  const std::vector<QueryRay> shifted(rays.begin() + 3, rays.end() - 2);
  const std::vector<HitGpu> expected(single.begin() + 3, single.end() - 2);
  checkIdentical("packets of other rays", expected, engine.intersect(shifted, nullptr, RayCoherence::Coherent));
}

// The same for shadow rays: occlusion, and transmittance to the bit (the
// packet walk sends a ray that meets a semitransparent primitive on alone, so
// its product is taken in the same order).
void checkShadowPackets(RayQueryEngine& engine, const std::vector<RayGpu>& rays,
                        const std::vector<std::uint8_t>& occluded, const std::vector<float>& carried) {
  INFO(describeAccel(engine.accel()));
  REQUIRE(engine.tracesPackets());
  const bool shift = rays.size() >= 13;
  const std::vector<RayGpu> shifted = shift ? std::vector<RayGpu>(rays.begin() + 3, rays.end() - 2) : rays;
  for (int pass = 0; pass < (shift ? 2 : 1); ++pass) {
    const std::vector<RayGpu>& in = pass ? shifted : rays;
    const std::size_t skip = pass ? 3 : 0;
    const std::vector<std::uint8_t> o = engine.occluded(in, nullptr, RayCoherence::Coherent);
    const std::vector<float> c = engine.transmittance(in, nullptr, RayCoherence::Coherent);
    std::size_t differ = 0, part = 0;
    for (std::size_t i = 0; i < in.size(); ++i) {
      differ += o[i] != occluded[i + skip] || !sameBits(c[i], carried[i + skip]);
      part += carried[i + skip] > 0.0f && carried[i + skip] < 1.0f;
    }
    INFO((pass ? "packets of other rays" : "packets") << ": " << differ << " of " << in.size()
                                                      << " shadow rays differ; " << part << " carry part of the light");
    CHECK(differ == 0);
  }
}

template <typename T>
std::vector<T> everyNth(const std::vector<T>& v, std::size_t n) {
  std::vector<T> out;
  for (std::size_t i = 0; i < v.size(); i += n) out.push_back(v[i]);
  return out;
}

void checkHits(const AccelScene& scene, const char* what, const std::vector<QueryRay>& rays,
               const std::vector<HitGpu>& ref, const std::vector<HitGpu>& got) {
  Comparison c = compareHits(scene.objects, rays, ref, got);
  INFO(what << ": " << c.rays << " rays, " << c.hits << " hits, " << c.ties << " exact ties, " << c.ambiguous
            << " too close to call; first mismatch: " << c.first);
  CHECK(c.mismatches == 0);
  CHECK(c.ambiguous <= c.rays / 1000 + 2);
}

// Near-edge shadow rays may be called either way too: only clear
// disagreements count, and at most 0.1% may be unclear.
void checkOcclusion(const char* what, const std::vector<std::uint8_t>& ref, const std::vector<std::uint8_t>& got) {
  std::size_t differ = 0;
  for (std::size_t i = 0; i < ref.size(); ++i) differ += ref[i] != got[i];
  INFO(what << ": " << differ << " of " << ref.size() << " occlusion answers differ");
  CHECK(differ <= ref.size() / 1000 + 2);
}

void checkCarried(const char* what, const std::vector<float>& ref, const std::vector<float>& got) {
  // Products of the same factors in another order: equal to rounding.
  std::size_t differ = 0;
  for (std::size_t i = 0; i < ref.size(); ++i) differ += std::fabs(got[i] - ref[i]) > 1e-6f * std::max(1.0f, ref[i]);
  INFO(what << ": " << differ << " of " << ref.size() << " transmittances differ");
  CHECK(differ <= ref.size() / 1000 + 2);
}

// `none` answers a sample of about `none_rays` rays (it is O(primitives) per
// ray); the BVH answers all of them and the octree and BSP are compared with it.
void checkScene(const AccelScene& scene, std::size_t random_count, int camera_size, std::size_t none_rays) {
  Context& context = sharedContext();
  const Aabb box = boundsOf(scene.objects);
  std::vector<QueryRay> rays = cameraRays(box, camera_size, camera_size);
  std::vector<QueryRay> random = randomRays(box, random_count, 99);
  std::vector<QueryRay> aimed = vertexRays(scene.objects, random_count / 4, 5);
  rays.insert(rays.end(), random.begin(), random.end());
  rays.insert(rays.end(), aimed.begin(), aimed.end());

  RayQueryEngine bvh(context, scene.objects, AccelKind::Bvh, scene.materials, {}, PacketUse::Always);
  const std::vector<HitGpu> bvh_hits = bvh.intersect(rays);
  // Camera rays, then random and aimed ones: packets alike and packets of
  // rays in every direction.
  checkPackets(bvh, rays, bvh_hits);
  const float light[3] = {box.hi[0] + 1, box.hi[1] + 2, box.hi[2] + 1.5f};
  std::vector<QueryRay> shadows = shadowRays(rays, bvh_hits, light);
  std::vector<QueryRay> segments = randomRays(box, random_count, 123);  // many end inside the scene
  for (QueryRay& s : segments) s.tmax = 0.5f * (box.hi[0] - box.lo[0]);
  shadows.insert(shadows.end(), segments.begin(), segments.end());
  const std::vector<RayGpu> shadow_rays = toRayGpu(shadows);
  const std::vector<std::uint8_t> bvh_occluded = bvh.occluded(shadows);
  const std::vector<float> bvh_carried = bvh.transmittance(shadow_rays);
  checkShadowPackets(bvh, shadow_rays, bvh_occluded, bvh_carried);

  std::size_t blocked = 0;
  for (std::uint8_t o : bvh_occluded) blocked += o;
  INFO(scene.name << ": " << rays.size() << " rays, " << shadows.size() << " shadow rays, " << blocked
                  << " occluded");
  CHECK(blocked > 0);
  CHECK(blocked < shadows.size());

  {
    RayQueryEngine none(context, scene.objects, AccelKind::None, scene.materials);
    const std::size_t step = std::max<std::size_t>(1, rays.size() / std::max<std::size_t>(none_rays, 1));
    std::vector<QueryRay> sample = everyNth(rays, step);
    std::vector<QueryRay> shadow_sample = everyNth(shadows, step);
    INFO(describeAccel(bvh.accel()));
    checkHits(scene, "bvh against none", sample, none.intersect(sample), everyNth(bvh_hits, step));
    checkOcclusion("bvh against none", none.occluded(shadow_sample), everyNth(bvh_occluded, step));
    checkCarried("bvh against none", none.transmittance(toRayGpu(shadow_sample)), everyNth(bvh_carried, step));
  }
  for (AccelKind kind : {AccelKind::Octree, AccelKind::Bsp}) {
    RayQueryEngine engine(context, scene.objects, kind, scene.materials, {}, PacketUse::Always);
    INFO(describeAccel(engine.accel()));
    const std::vector<HitGpu> hits = engine.intersect(rays);
    const std::vector<std::uint8_t> occluded = engine.occluded(shadows);
    const std::vector<float> carried = engine.transmittance(shadow_rays);
    checkHits(scene, "against bvh", rays, bvh_hits, hits);
    checkOcclusion("against bvh", bvh_occluded, occluded);
    checkCarried("against bvh", bvh_carried, carried);
    checkPackets(engine, rays, hits);
    checkShadowPackets(engine, shadow_rays, occluded, carried);
  }
  {
    // The same tree with "set of normals" bounds: only the node tests differ.
    AccelBuildOptions kdop;
    kdop.kdop_objects = kdop.kdop_bvh = true;
    RayQueryEngine engine(context, scene.objects, AccelKind::Bvh, scene.materials, kdop, PacketUse::Always);
    INFO("k-DOP " << describeAccel(engine.accel()));
    CHECK(engine.accel().kernel_options.find("-DPRISM_BVH_KDOP") != std::string::npos);
    checkHits(scene, "k-DOP bvh against bvh", rays, bvh_hits, engine.intersect(rays));
    CHECK_FALSE(engine.tracesPackets());  // the packet walk does not test the diagonal slabs
    checkOcclusion("k-DOP bvh against bvh", bvh_occluded, engine.occluded(shadows));
    checkCarried("k-DOP bvh against bvh", bvh_carried, engine.transmittance(shadow_rays));
  }
}

}  // namespace

TEST_CASE("all structures agree on a scene of every primitive kind", "[accel]") {
  checkScene(mixedScene(), 20000, 96, 100000);
}

TEST_CASE("all structures agree on rays aimed at each quadric, polygon and polyhedron, and each is hit", "[accel]") {
  // They are small in the mixed scene; aim rays at each one's box from
  // around the scene (leaving out the teapot, which stands aside).
  AccelScene scene = mixedScene(300);
  Aabb box;
  for (std::size_t i = 0, n = primitiveCount(scene.objects); i < n; ++i) {
    Aabb b;  // (in place: a record finds its side data from where it sits)
    if (scene.objects[i].type != OBJECT_PATCH && objectBounds(scene.objects[i], &b)) box.extend(b);
  }
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<float> u01(0, 1);
  std::vector<QueryRay> rays;
  std::vector<std::int32_t> quadrics;
  for (std::size_t i = 0, n = primitiveCount(scene.objects); i < n; ++i) {
    const int type = scene.objects[i].type;
    if (type != OBJECT_QUADRIC && type != OBJECT_POLYGON && type != OBJECT_POLYHEDRON) continue;
    quadrics.push_back(static_cast<std::int32_t>(i));
    Aabb b;
    REQUIRE(objectBounds(scene.objects[i], &b));
    for (int k = 0; k < 400; ++k) {
      float o[3], t[3];
      for (int a = 0; a < 3; ++a) {
        o[a] = box.lo[a] - 0.5f * (box.hi[a] - box.lo[a]) + 2 * (box.hi[a] - box.lo[a]) * u01(rng);
        t[a] = b.lo[a] + (b.hi[a] - b.lo[a]) * u01(rng);
      }
      rays.push_back(QueryRay{o[0], o[1], o[2], 0, t[0] - o[0], t[1] - o[1], t[2] - o[2], INFINITY});
    }
  }
  REQUIRE(quadrics.size() == 7 + 3 + 2);
  RayQueryEngine none(sharedContext(), scene.objects, AccelKind::None, scene.materials);
  const std::vector<HitGpu> ref = none.intersect(rays);
  for (std::int32_t q : quadrics) {
    std::size_t hits = 0;
    for (const HitGpu& h : ref) hits += h.prim == q;
    INFO("object " << q);
    CHECK(hits >= 5);
  }
  for (AccelKind kind : {AccelKind::Bvh, AccelKind::Octree, AccelKind::Bsp}) {
    RayQueryEngine engine(sharedContext(), scene.objects, kind, scene.materials);
    INFO(accelName(kind));
    checkHits(scene, "against none", rays, ref, engine.intersect(rays));
  }
}

TEST_CASE("all structures agree on rays aimed at the teapot's patch pieces, and each aimed at is hit", "[accel][patches]") {
  AccelScene scene = mixedScene(300);
  const Aabb box = boundsOf(scene.objects);
  std::mt19937_64 rng(19);
  std::uniform_real_distribution<float> u01(0, 1);
  std::vector<QueryRay> rays;
  std::vector<std::int32_t> pieces;
  std::size_t seen = 0;
  for (std::size_t i = 0, n = primitiveCount(scene.objects); i < n; ++i) {
    if (scene.objects[i].type != OBJECT_PATCH || seen++ % 50) continue;
    pieces.push_back(static_cast<std::int32_t>(i));
    Aabb b;
    REQUIRE(objectBounds(scene.objects[i], &b));
    for (int k = 0; k < 60; ++k) {
      float o[3], t[3];
      for (int a = 0; a < 3; ++a) {
        o[a] = box.lo[a] - 0.5f * (box.hi[a] - box.lo[a]) + 2 * (box.hi[a] - box.lo[a]) * u01(rng);
        t[a] = b.lo[a] + (b.hi[a] - b.lo[a]) * u01(rng);
      }
      rays.push_back(QueryRay{o[0], o[1], o[2], 0, t[0] - o[0], t[1] - o[1], t[2] - o[2], INFINITY});
    }
  }
  REQUIRE(pieces.size() > 50);
  RayQueryEngine none(sharedContext(), scene.objects, AccelKind::None, scene.materials);
  const std::vector<HitGpu> ref = none.intersect(rays);
  std::size_t on_pieces = 0;
  for (const HitGpu& h : ref) on_pieces += h.prim >= 0 && scene.objects[h.prim].type == OBJECT_PATCH;
  CHECK(on_pieces > rays.size() / 4);
  for (AccelKind kind : {AccelKind::Bvh, AccelKind::Octree, AccelKind::Bsp}) {
    RayQueryEngine engine(sharedContext(), scene.objects, kind, scene.materials);
    INFO(accelName(kind));
    checkHits(scene, "against none", rays, ref, engine.intersect(rays));
  }
}

TEST_CASE("all structures agree on procedural meshes", "[accel]") {
  checkScene(meshScene("icosphere5", icosphere(5, 0, 0, 0, 1)), 20000, 96, 10000);
  checkScene(meshScene("soup20k", triangleSoup(20000, 3, 0.02f)), 20000, 96, 3000);
}

TEST_CASE("all structures agree on real meshes", "[accel]") {
  for (const char* file : {"bunny/bun_zipper_res2.ply", "teapot/teapot.obj", "cornell_box/CornellBox-Original.obj",
                           "dragon/dragon_vcg_43k.ply"}) {
    SharedMesh mesh = loadTestMesh(file);
    checkScene(meshScene(file, *mesh), 20000, 128, 3000);
  }
}

// Two thousand triangles a few millimetres across, each with a vertex on the
// plane y = 0 (itself in the scene), seen from several units away: rays aimed
// at those vertices meet a triangle and the plane at the same t, or a triangle
// a few ulps before or after its neighbour, so a cell dropped one ulp too early
// loses the hit and a transmittance counted by cell intervals loses it too.
struct TinyTriangles {
  AccelScene scene;
  std::vector<QueryRay> rays;
};

TinyTriangles tinyTrianglesOnAPlane(std::size_t ray_count) {
  TinyTriangles out;
  out.scene.name = "tiny triangles on a plane";
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<float> u01(0, 1);
  std::vector<std::array<float, 3>> feet;
  for (int i = 0; i < 2000; ++i) {
    ObjectGpu g = identityObject(OBJECT_TRIANGLE, 0);
    const float x = 4 * u01(rng), z = 4 * u01(rng);
    const float v[9] = {x, 0, z, x + 0.001f, 0.003f, z, x - 0.0005f, 0.003f + 0.001f * u01(rng), z + 0.001f};
    std::copy(v, v + 9, g.p);
    out.scene.objects.push_back(g);
    feet.push_back({x, 0, z});
  }
  ObjectGpu plane = identityObject(OBJECT_PLANE, 0);
  plane.p[4] = 1;  // normal +y through the origin
  out.scene.objects.push_back(plane);
  for (std::size_t k = 0; k < ray_count; ++k) {
    const auto& f = feet[rng() % feet.size()];
    const float o[3] = {-2 + 8 * u01(rng), -5.0f - 5 * u01(rng), -2 + 8 * u01(rng)};
    const float scale = 0.3f + 3 * u01(rng);  // the direction's length changes every t
    out.rays.push_back(QueryRay{o[0], o[1], o[2], 0, (f[0] - o[0]) * scale, (f[1] - o[1]) * scale,
                                (f[2] - o[2]) * scale, INFINITY});
  }
  return out;
}

TEST_CASE("compact mesh triangles answer as triangle records do, in every structure, in under a fifth of the bytes",
          "[accel]") {
  // The same mesh two ways: compact (three vertex indices per triangle, the
  // kernels' mesh path) and one 112-byte record per triangle (the object path).
  // The vertices are the same floats, so every answer must be the same bits.
  SharedMesh mesh = loadTestMesh("bunny/bun_zipper_res2.ply");
  const SceneGeometry compact = geometryFromMesh(*mesh);
  const SceneGeometry records = geometryFromRecords(trianglesFromMesh(*mesh));
  REQUIRE(compact.triangleCount() == mesh->triangleCount());
  REQUIRE(records.triangleCount() == 0);
  const Aabb box = boundsOf(records.objects);
  std::vector<QueryRay> rays = cameraRays(box, 96, 96);
  for (const QueryRay& q : randomRays(box, 6000, 5)) rays.push_back(q);
  for (AccelKind kind : allAccelKinds()) {
    INFO(accelName(kind));
    RayQueryEngine a(sharedContext(), compact, kind), b(sharedContext(), records, kind);
    const std::vector<HitGpu> ha = a.intersect(rays), hb = b.intersect(rays);
    std::size_t same = 0, hits = 0;
    for (std::size_t k = 0; k < rays.size(); ++k) {
      same += ha[k].prim == hb[k].prim && sameBits(ha[k].t, hb[k].t) && sameBits(ha[k].u, hb[k].u) &&
              sameBits(ha[k].v, hb[k].v);
      hits += ha[k].prim >= 0;
    }
    CHECK(same == rays.size());
    CHECK(hits > rays.size() / 8);
    CHECK(a.occluded(rays) == b.occluded(rays));
  }
  // 12 bytes of indices per triangle and 12 per vertex, against 112 per record.
  const double per_triangle = double(deviceGeometryBytes(compact)) / compact.triangleCount();
  INFO(per_triangle << " B/tri compact");
  CHECK(per_triangle < 12.0 + 12.0 * mesh->vertexCount() / mesh->triangleCount() + 1.0);
  CHECK(5 * deviceGeometryBytes(compact) < deviceGeometryBytes(records));
}

TEST_CASE("closest hits at exact ties and a few ulps apart: every structure answers as brute force", "[accel]") {
  // Strict: the same primitive (an exact tie goes to the lower id) and the
  // same t, u, v bits as `none`, on every ray.
  TinyTriangles tiny = tinyTrianglesOnAPlane(40000);
  RayQueryEngine none(sharedContext(), tiny.scene.objects, AccelKind::None);
  const std::vector<HitGpu> ref = none.intersect(tiny.rays);
  std::size_t on_plane = 0;
  for (const HitGpu& h : ref) on_plane += h.prim == 2000;
  for (AccelKind kind : {AccelKind::Bvh, AccelKind::Octree, AccelKind::Bsp}) {
    RayQueryEngine engine(sharedContext(), tiny.scene.objects, kind, {}, {}, PacketUse::Always);
    const std::vector<HitGpu> got = engine.intersect(tiny.rays);
    std::size_t differ = 0;
    for (std::size_t i = 0; i < ref.size(); ++i)
      differ += !(ref[i].prim == got[i].prim && sameBits(ref[i].t, got[i].t) && sameBits(ref[i].u, got[i].u) &&
                  sameBits(ref[i].v, got[i].v));
    INFO(accelName(kind) << ": " << differ << " of " << ref.size() << " rays differ; " << on_plane
                         << " reference hits on the plane");
    CHECK(differ == 0);
    // The packet walks, where ties between packet mates' triangles abound:
    // the rays as they come (their directions' signs mixed in most packets)
    // and those whose directions share each axis's sign, which the BSP's
    // packets walk together rather than one by one.
    REQUIRE(engine.tracesPackets());
    checkIdentical("packets against none", ref, engine.intersect(tiny.rays, nullptr, RayCoherence::Coherent));
    std::vector<QueryRay> alike;
    std::vector<HitGpu> alike_ref;
    for (std::size_t i = 0; i < tiny.rays.size(); ++i) {
      const QueryRay& q = tiny.rays[i];
      if (q.dx >= 0 && q.dz >= 0 && (q.dy >= 0) == (tiny.rays[0].dy >= 0)) {
        alike.push_back(q);
        alike_ref.push_back(ref[i]);
      }
    }
    INFO(alike.size() << " rays share their directions' signs");
    CHECK(alike.size() >= 1000);
    checkIdentical("packets of one sign against none", alike_ref,
                   engine.intersect(alike, nullptr, RayCoherence::Coherent));
  }
}

namespace {

// The same occlusion answer as `none` on every segment, none excused.
void checkSameOcclusion(const char* what, const std::vector<std::uint8_t>& ref, const std::vector<std::uint8_t>& got) {
  REQUIRE(got.size() == ref.size());
  std::size_t differ = 0;
  for (std::size_t i = 0; i < ref.size(); ++i) differ += ref[i] != got[i];
  INFO(what << ": " << differ << " of " << ref.size() << " occlusion answers differ");
  CHECK(differ == 0);
}

// Every structure against `none`, to the bit, on `rays` one at a time and in
// packets (eight consecutive rays a packet), and on segments from each ray's
// origin to one float past its hit, which just counts (transmittance counts
// hits in (tmin, tmax)): there a cell's entry may round past tmax, and the
// octree keeps the cell only through its widened tmax (octree_next_leaf).
void checkAgainstNone(const std::vector<ObjectGpu>& objects, const std::vector<QueryRay>& rays) {
  RayQueryEngine none(sharedContext(), objects, AccelKind::None);
  const std::vector<HitGpu> ref = none.intersect(rays);
  std::vector<QueryRay> segments = rays;
  std::size_t hits = 0;
  for (std::size_t i = 0; i < rays.size(); ++i)
    if (ref[i].prim >= 0) {
      ++hits;
      segments[i].tmax = std::nextafter(ref[i].t, INFINITY);
    }
  const std::vector<std::uint8_t> blocked = none.occluded(segments);
  std::size_t blocked_count = 0;
  for (std::uint8_t b : blocked) blocked_count += b;
  INFO(hits << " of " << rays.size() << " rays hit; " << blocked_count << " segments blocked");
  REQUIRE(hits > rays.size() / 2);
  CHECK(blocked_count == hits);  // each segment holds its ray's hit
  for (AccelKind kind : {AccelKind::Bvh, AccelKind::Octree, AccelKind::Bsp}) {
    RayQueryEngine engine(sharedContext(), objects, kind, {}, {}, PacketUse::Always);
    INFO(describeAccel(engine.accel()));
    REQUIRE(engine.tracesPackets());
    checkIdentical("one ray at a time against none", ref, engine.intersect(rays));
    checkIdentical("packets against none", ref, engine.intersect(rays, nullptr, RayCoherence::Coherent));
    checkSameOcclusion("segments one at a time against none", blocked, engine.occluded(segments));
    checkSameOcclusion("segments in packets against none", blocked,
                       engine.occluded(segments, nullptr, RayCoherence::Coherent));
  }
}

ObjectGpu triangleRecord(const float v[9]) {
  ObjectGpu g = identityObject(OBJECT_TRIANGLE, 0);
  std::copy(v, v + 9, g.p);
  return g;
}

// A layer of small right triangles lying flat in the plane z = 3/8, one in each
// cell of a 16 x 16 grid, their legs along x and y (corners and legs on a 2^-16
// grid), between a triangle far above the layer and one far below it. Every
// box around the layer (each triangle's, so each octree leaf's) is a slab a few
// floats thick whose sides lie a few floats outside the legs (a triangle's box
// grows by 2^-20 of its size and a float), and the BSP's cells around the layer
// are as thin: seen from afar, a ray's interval in them is a float or two, and
// where it passes by a leg the interval's ends, the slabs' and the planes' t
// all round into one another. The triangles above and below put
// planes on both sides of the layer, so the one-ray BSP walk reaches the
// layer's cells from its stack (its interval's far end from the pop) as well
// as by descending (from a split).
struct FlatLayer {
  std::vector<ObjectGpu> objects;
  std::vector<std::array<float, 3>> points;  // on the legs and at the corners, on a 2^-16 grid
};

FlatLayer flatLayerWithLegs(std::uint64_t seed) {
  FlatLayer out;
  std::mt19937_64 rng(seed);
  auto steps = [&](int lo, int hi) { return lo + static_cast<int>(rng() % static_cast<std::uint64_t>(hi - lo)); };
  const float z = 0.375f, step = 0x1p-12f;
  for (int i = 0; i < 16; ++i)
    for (int j = 0; j < 16; ++j) {
      // The right angle at (x, y), legs lx, ly of 1/64 to 1/32 pointing either way.
      const float x = i + 0.25f + steps(0, 2048) * step, y = j + 0.25f + steps(0, 2048) * step;
      const float lx = (rng() % 2 ? 1 : -1) * steps(1024, 2048) * 0x1p-16f;
      const float ly = (rng() % 2 ? 1 : -1) * steps(1024, 2048) * 0x1p-16f;
      const float v[9] = {x, y, z, x + lx, y, z, x, y + ly, z};
      out.objects.push_back(triangleRecord(v));
      out.points.push_back({x, y, z});
      out.points.push_back({x + lx, y, z});
      out.points.push_back({x, y + ly, z});
      for (int k = 1; k * step < std::fabs(lx); k += 4) out.points.push_back({x + std::copysign(k * step, lx), y, z});
      for (int k = 1; k * step < std::fabs(ly); k += 4) out.points.push_back({x, y + std::copysign(k * step, ly), z});
    }
  const float above[9] = {0, 0, z + 11, 0.5f, 0, z + 11, 0, 0.5f, z + 11};
  const float below[9] = {0, 0, z - 7, 0.5f, 0, z - 7, 0, 0.5f, z - 7};
  out.objects.push_back(triangleRecord(above));
  out.objects.push_back(triangleRecord(below));
  return out;
}

// Rays in packets of eight whose directions share their signs (so the BSP's
// packets descend together), each passing exactly through one of `points`:
// d on a 2^-8 grid, the origin m whole steps of d back (m up to 64, up to some
// 220 units away), exact on the 2^-16 grid below 256, so the ray meets the
// point at t = m. For m of 32 and more an ulp of t is 2^-18 or more, far more
// than the ray spends inside the layer's slabs.
std::vector<QueryRay> raysThrough(const std::vector<std::array<float, 3>>& points, std::size_t count,
                                  std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  std::vector<QueryRay> rays;
  while (rays.size() < count) {
    float sign[3];
    for (float& s : sign) s = rng() % 2 ? 1.0f : -1.0f;
    for (int lane = 0; lane < 8; ++lane) {
      const std::array<float, 3>& p = points[rng() % points.size()];
      float d[3];
      for (int a = 0; a < 3; ++a) d[a] = sign[a] * (16 + rng() % 496) * 0x1p-8f;
      const float m = static_cast<float>(1 + rng() % 64);
      rays.push_back(QueryRay{p[0] - m * d[0], p[1] - m * d[1], p[2] - m * d[2], 0, d[0], d[1], d[2], INFINITY});
    }
  }
  return rays;
}

}  // namespace

TEST_CASE("rays from afar through the legs of flat triangles: every structure answers as brute force, one ray at a "
          "time and in packets",
          "[accel][packets]") {
  // Where a ray passes by a leg, the t at which it meets the leaf's slab and
  // the t at which it leaves through the leg's face round to one another: the
  // octree keeps the leaf only through the widened far end of its box test
  // (octree_clip's octree_far, and its packet twin in rays8_cell), and the BSP
  // goes to both sides of a plane by a leg only through ACCEL_CELL_EPS on its
  // interval's ends (bsp_next_leaf: the near end, the far end from a pop and
  // from a split; the packet walk's t0e and t1e).
  const FlatLayer layer = flatLayerWithLegs(7);
  checkAgainstNone(layer.objects, raysThrough(layer.points, 40000, 11));
}

namespace {

// 300 small right triangles lying flat at height z over [-1, 1]^2, legs of
// 0.05 to 0.15 along x and y.
std::vector<ObjectGpu> flatLayer(float z, std::mt19937_64& rng) {
  std::uniform_real_distribution<float> u01(0, 1);
  std::vector<ObjectGpu> objects;
  for (int i = 0; i < 300; ++i) {
    const float x = -1 + 2 * u01(rng), y = -1 + 2 * u01(rng);
    const float v[9] = {x, y, z, x + 0.05f + 0.1f * u01(rng), y, z, x, y + 0.05f + 0.1f * u01(rng), z};
    objects.push_back(triangleRecord(v));
  }
  return objects;
}

// Each object's reflection through the origin, added: the octree's root cube
// is then symmetric about the origin, and its centre planes are x, y, z = 0.
void addReflections(std::vector<ObjectGpu>& objects) {
  const std::size_t count = objects.size();
  for (std::size_t i = 0; i < count; ++i) {
    ObjectGpu g = objects[i];
    for (float& f : g.p) f = -f;
    objects.push_back(g);
  }
}

// A ray from `distance` away, in a direction drawn from `normal` per axis,
// whose direction vector ends at `target` (t = 1 there).
QueryRay rayFromAfar(const float target[3], float distance, std::mt19937_64& rng,
                     std::normal_distribution<float>& normal) {
  float dir[3], length = 0;
  for (int c = 0; c < 3; ++c) {
    dir[c] = normal(rng);
    length += dir[c] * dir[c];
  }
  length = std::sqrt(length) / distance;
  float o[3];
  for (int c = 0; c < 3; ++c) o[c] = target[c] - dir[c] / length;
  return QueryRay{o[0], o[1], o[2], 0, target[0] - o[0], target[1] - o[1], target[2] - o[2], INFINITY};
}

// Barycentric weights (a, b) of a point drawn uniformly over a triangle: a
// draw past the diagonal a + b = 1 is folded back inside.
std::pair<float, float> pointInTriangle(std::mt19937_64& rng, std::uniform_real_distribution<float>& u01) {
  float a = u01(rng), b = u01(rng);
  if (a + b > 1) {
    a = 1 - a;
    b = 1 - b;
  }
  return {a, b};
}

// The root cell of the octree built over `objects`.
OctreeNodeGpu octreeRoot(const std::vector<ObjectGpu>& objects) {
  return nodesOf<OctreeNodeGpu>(*buildAccel(AccelKind::Octree, objects))[0];
}

}  // namespace

TEST_CASE("every structure answers as brute force on flat triangles 2^-100 either side of the octree's centre "
          "plane, hit from afar",
          "[accel]") {
  // Two layers of triangles lying flat at z = +-2^-100, each the other
  // reflected through the origin, so the octree's root cube is symmetric and
  // its centre plane is z = 0. The root's box is a slab some 3e-7 thick around
  // that plane (the triangles' boxes grow by 2^-20 of their size): seen from
  // ten units away, the ray's entry into it and its crossing of z = 0 often
  // round to the same t, and then only the widened entry (octree_push's t0e)
  // puts the octants on the entry side on the stack. The rays meet the
  // triangles well inside, where no rounding doubts the hit.
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<float> u01(0, 1);
  std::vector<ObjectGpu> objects = flatLayer(0x1p-100f, rng);
  addReflections(objects);
  const OctreeNodeGpu root = octreeRoot(objects);
  REQUIRE(root.child_mask != 0);
  REQUIRE(root.cz == 0.0f);
  std::normal_distribution<float> normal;
  std::vector<QueryRay> rays;
  for (int k = 0; k < 20000; ++k) {
    const float* p = objects[rng() % objects.size()].p;
    const auto [a, b] = pointInTriangle(rng, u01);
    float target[3];
    for (int c = 0; c < 3; ++c) target[c] = p[c] + a * (p[3 + c] - p[c]) + b * (p[6 + c] - p[c]);
    rays.push_back(rayFromAfar(target, 10, rng, normal));
  }
  checkAgainstNone(objects, rays);
}

// Where two or three of an octree cell's centre-plane crossings round to the
// same t, or swap, the ray may pass an octant of the other order over a
// stretch the floats cannot place; octree_push pushes those octants too
// (octree_tie). Found on 2026-12-05 with the layers of the case above plus
// triangles hugging x = 0 or y = 0: the one-ray walk, taking one order only,
// disagreed with brute force on 9,929 of 100,000 rays there. Here small
// triangles fill the root's cube (its content box about [-0.9, 0.95]^3, not a
// thin slab), so the third crossing falls before, between or after a near-tie
// of the other two inside the root's interval, and triangles cornered 2^-100
// from the centre point bring ties of all three.
TEST_CASE("the one-ray octree walk reaches the octants between centre-plane crossings that round together",
          "[accel]") {
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<float> u01(0, 1), u11(-1, 1);
  const float d = 0x1p-100f;
  std::vector<ObjectGpu> objects = flatLayer(d, rng);
  for (int i = 0; i < 300; ++i) {  // the cube's filling
    const float x = 0.9f * u11(rng), y = 0.9f * u11(rng), z = 0.9f * u11(rng);
    const float v[9] = {x, y, z, x + 0.05f, y, z, x, y, z + 0.05f};
    objects.push_back(triangleRecord(v));
  }
  std::vector<std::size_t> legged, cornered;  // a leg or a corner 2^-100 from the centre planes
  for (int i = 0; i < 40; ++i) {
    const float y = u11(rng), side = rng() % 2 ? 1.0f : -1.0f;
    float v[9] = {side * d, y, d, side * (d + 0.1f), y, d, side * d, y + 0.1f, d};
    if (rng() % 2)
      for (int k = 0; k < 3; ++k) std::swap(v[3 * k], v[3 * k + 1]);
    legged.push_back(objects.size());
    objects.push_back(triangleRecord(v));
  }
  for (int i = 0; i < 40; ++i) {
    // The right angle at (+-d, +-d, +-d), the legs outward along two axes.
    float corner[3], v[9];
    for (float& c : corner) c = rng() % 2 ? d : -d;
    const int normal = static_cast<int>(rng() % 3);
    for (int k = 0; k < 3; ++k)
      for (int c = 0; c < 3; ++c) v[3 * k + c] = corner[c];
    v[3 * 1 + (normal + 1) % 3] += corner[(normal + 1) % 3] > 0 ? 0.1f : -0.1f;
    v[3 * 2 + (normal + 2) % 3] += corner[(normal + 2) % 3] > 0 ? 0.1f : -0.1f;
    cornered.push_back(objects.size());
    objects.push_back(triangleRecord(v));
  }
  const std::size_t half = objects.size();
  addReflections(objects);
  const OctreeNodeGpu root = octreeRoot(objects);
  REQUIRE(root.child_mask != 0);
  REQUIRE((root.cx == 0.0f && root.cy == 0.0f && root.cz == 0.0f));
  std::normal_distribution<float> normal;
  std::vector<QueryRay> rays;
  auto reflected = [&](std::size_t i) { return objects[i + (rng() % 2 ? half : 0)].p; };
  for (int k = 0; k < 100000; ++k) {
    float target[3];
    if (k % 2) {
      // A point on a leg along a centre plane, moved inside by up to 1e-5 of
      // the other leg's length (about 1e-6).
      const float* q = reflected(legged[rng() % legged.size()]);
      // The leg along the plane runs from the first vertex to the third, the
      // other from the first to the second, whichever coordinates were swapped.
      const int axis = q[0] == q[6] ? 0 : 1;  // the coordinate that stays +-d along the leg
      const float* end = q + 6;
      const float s = u01(rng);
      for (int c = 0; c < 3; ++c) target[c] = q[c] + s * (end[c] - q[c]);
      const float* across = q + 3;
      target[axis] = q[axis] + (across[axis] - q[axis]) * (u01(rng) * 1e-5f);
    } else {
      // A point within 1e-5 of the legs' lengths (about 1e-6) of the right
      // angle, inside the triangle.
      const float* q = reflected(cornered[rng() % cornered.size()]);
      const auto [a, b] = pointInTriangle(rng, u01);
      for (int c = 0; c < 3; ++c) target[c] = q[c] + 1e-5f * (a * (q[3 + c] - q[c]) + b * (q[6 + c] - q[c]));
    }
    rays.push_back(rayFromAfar(target, 10, rng, normal));
  }
  checkAgainstNone(objects, rays);
}

TEST_CASE("transmittance counts each semitransparent primitive once, however its t rounds", "[accel]") {
  // k_trans 0.5 is a power of two, so the product is exact in any order; the
  // segments end just past the plane y = 0, where the triangles stand.
  TinyTriangles tiny = tinyTrianglesOnAPlane(40000);
  tiny.scene.materials = {materialWithTransmit(0.5f)};
  const ObjectGpu plane = tiny.scene.objects.back();
  tiny.scene.objects.pop_back();
  RayQueryEngine floor(sharedContext(), {plane}, AccelKind::None);
  const std::vector<HitGpu> ground = floor.intersect(tiny.rays);
  for (std::size_t i = 0; i < tiny.rays.size(); ++i) tiny.rays[i].tmax = std::nextafter(ground[i].t, INFINITY);
  const std::vector<RayGpu> rays = toRayGpu(tiny.rays);
  RayQueryEngine none(sharedContext(), tiny.scene.objects, AccelKind::None, tiny.scene.materials);
  const std::vector<float> ref = none.transmittance(rays);
  std::size_t attenuated = 0;
  for (float t : ref) attenuated += t < 1;
  REQUIRE(attenuated > ref.size() / 10);
  for (AccelKind kind : {AccelKind::Bvh, AccelKind::Octree, AccelKind::Bsp}) {
    RayQueryEngine engine(sharedContext(), tiny.scene.objects, kind, tiny.scene.materials);
    const std::vector<float> got = engine.transmittance(rays);
    std::size_t differ = 0;
    std::size_t darker = 0;
    for (std::size_t i = 0; i < ref.size(); ++i) {
      differ += !sameBits(ref[i], got[i]);
      darker += got[i] < ref[i];
    }
    INFO(accelName(kind) << ": " << differ << " of " << ref.size() << " transmittances differ, " << darker << " darker");
    CHECK(differ == 0);
  }
}

TEST_CASE("transmittance through 24 semitransparent sheets and a large triangle across them", "[accel]") {
  // Segments crossing 24 sheets of small triangles and one large triangle that
  // spans many cells: the large one must count once, however many other
  // semitransparent hits come between the cells that hold it. k_trans 0.5
  // keeps every product exact.
  AccelScene scene;
  scene.name = "sheets";
  scene.materials = {materialWithTransmit(0.5f)};
  auto triangle = [&](std::initializer_list<float> p) {
    ObjectGpu g = identityObject(OBJECT_TRIANGLE, 0);
    std::copy(p.begin(), p.end(), g.p);
    scene.objects.push_back(g);
  };
  const int grid = 6;
  for (int k = 0; k < 24; ++k) {
    const float z = 0.02f + 0.04f * k;
    for (int i = 0; i < grid; ++i)
      for (int j = 0; j < grid; ++j) {
        const float x0 = float(i) / grid, x1 = float(i + 1) / grid, y0 = float(j) / grid, y1 = float(j + 1) / grid;
        triangle({x0, y0, z, x1, y0, z, x1, y1, z});
        triangle({x0, y0, z, x1, y1, z, x0, y1, z});
      }
  }
  triangle({-1, 0.36f, -1, 3, 0.36f, -1, -1, 0.40f, 3});
  std::mt19937_64 rng(2);
  std::uniform_real_distribution<float> u01(0, 1);
  std::vector<QueryRay> segments;
  for (int k = 0; k < 20000; ++k) {
    const float ox = 0.05f + 0.9f * u01(rng), oy = 0.05f + 0.9f * u01(rng);
    const float ex = 0.05f + 0.9f * u01(rng), ey = 0.05f + 0.9f * u01(rng);
    const bool down = rng() & 1;  // both directions
    const float oz = down ? 1.5f : -0.5f, ez = down ? -0.5f : 1.5f;
    segments.push_back(QueryRay{ox, oy, oz, 0, ex - ox, ey - oy, ez - oz, 1});
  }
  const std::vector<RayGpu> rays = toRayGpu(segments);
  RayQueryEngine none(sharedContext(), scene.objects, AccelKind::None, scene.materials);
  const std::vector<float> ref = none.transmittance(rays);
  std::size_t through_big = 0;
  for (float t : ref) through_big += std::ilogb(t) % 2 != 0;  // 24 sheets and the large triangle: odd powers
  REQUIRE(through_big > segments.size() / 10);
  for (AccelKind kind : {AccelKind::Bvh, AccelKind::Octree, AccelKind::Bsp}) {
    RayQueryEngine engine(sharedContext(), scene.objects, kind, scene.materials);
    const std::vector<float> got = engine.transmittance(rays);
    std::size_t darker = 0, lighter = 0;
    for (std::size_t i = 0; i < ref.size(); ++i) {
      darker += got[i] < ref[i];
      lighter += got[i] > ref[i];
    }
    INFO(accelName(kind) << ": " << darker << " darker (counted twice), " << lighter << " lighter (missed) of "
                         << ref.size());
    CHECK(darker == 0);
    CHECK(lighter == 0);
  }
}

TEST_CASE("the structures answer empty scenes, planes only, and a single primitive", "[accel]") {
  AccelScene empty{"empty", {}, {}};
  AccelScene planes = mixedScene(0);
  planes.name = "planes only";
  planes.objects.erase(std::remove_if(planes.objects.begin(), planes.objects.end(),
                                      [](const ObjectGpu& o) { return o.type != OBJECT_PLANE; }),
                       planes.objects.end());
  AccelScene one = meshScene("one triangle", triangleSoup(1, 1, 0.3f));
  for (const AccelScene* s : {&empty, &planes, &one}) {
    std::vector<QueryRay> rays = randomRays(Aabb{{-1, -1, -1}, {2, 2, 2}}, 2000, 4);
    RayQueryEngine none(sharedContext(), s->objects, AccelKind::None);
    std::vector<HitGpu> ref = none.intersect(rays);
    for (AccelKind kind : {AccelKind::Bvh, AccelKind::Octree, AccelKind::Bsp}) {
      RayQueryEngine engine(sharedContext(), s->objects, kind);
      INFO(s->name << " " << accelName(kind));
      checkHits(*s, accelName(kind), rays, ref, engine.intersect(rays));
    }
  }
}

TEST_CASE("traceRays answers closest hits and occlusion with the tracing timed alone", "[accel]") {
  AccelScene scene = meshScene("icosphere3", icosphere(3, 0, 0, 0, 1));
  std::vector<QueryRay> rays = {
      {0, 0, 5, 0, 0, 0, -1, INFINITY},  // hits the sphere's front near t = 4
      {0, 0, 5, 0, 0, 0, 1, INFINITY},   // points away
      {0, 0, 5, 0, 0, 0, -1, 3.5f},      // stops short
      {3, 3, 3, 0, 1, 0, 0, INFINITY},   // passes beside
  };
  for (AccelKind kind : allAccelKinds()) {
    INFO(accelName(kind));
    TraceResult closest = traceRays(sharedContext(), geometryFromRecords(scene.objects), kind, rays, false);
    REQUIRE(closest.hits.size() == rays.size());
    CHECK(closest.occluded.empty());
    CHECK(closest.hits[0].prim >= 0);
    CHECK(closest.hits[0].t == Approx(4.0).epsilon(0.01));
    CHECK(closest.hits[0].u >= 0);
    CHECK(closest.hits[0].v >= 0);
    for (int i : {1, 2, 3}) {
      CHECK(closest.hits[i].prim == -1);
      CHECK(std::isinf(closest.hits[i].t));
    }
    CHECK(closest.trace_seconds > 0);
    CHECK(closest.accel.primitives == (kind == AccelKind::None ? scene.objects.size() : scene.objects.size()));
    TraceResult occluded = traceRays(sharedContext(), geometryFromRecords(scene.objects), kind, rays, true);
    CHECK(occluded.hits.empty());
    CHECK(occluded.occluded == std::vector<std::uint8_t>{1, 0, 0, 0});
  }
}

TEST_CASE("rays with NaN or infinite parts, or no direction, are misses in every structure", "[accel]") {
  // Before the guard in kernels/accel/accel.h a NaN direction sent the BVH walk
  // into every child of every node until its stack overran (SIGSEGV).
  AccelScene scene = mixedScene();
  const Aabb box = boundsOf(scene.objects);
  std::vector<QueryRay> good = cameraRays(box, 16, 16);
  const float nan = std::numeric_limits<float>::quiet_NaN(), inf = std::numeric_limits<float>::infinity();
  std::vector<QueryRay> rays;
  std::vector<bool> walkable;
  std::size_t k = 0;
  for (const QueryRay& g : good) {
    rays.push_back(g);
    walkable.push_back(true);
    QueryRay bad = g;
    float* field[] = {&bad.ox, &bad.oy, &bad.oz, &bad.tmin, &bad.dx, &bad.dy, &bad.dz, &bad.tmax};
    switch (k++ % 6) {
      case 0: *field[(k / 6) % 8] = nan; break;                    // any field NaN
      case 1: *field[(k / 6) % 3] = (k % 2 ? inf : -inf); break;   // an infinite origin
      case 2: *field[4 + (k / 6) % 3] = (k % 2 ? inf : -inf); break;  // an infinite direction
      case 3: bad.dx = bad.dy = bad.dz = 0; break;                 // no direction
      case 4: bad.dx = bad.dy = bad.dz = nan; break;
      default: bad.tmin = inf; break;
    }
    rays.push_back(bad);
    walkable.push_back(false);
  }
  std::size_t hits_before = 0;
  for (AccelKind kind : allAccelKinds()) {
    RayQueryEngine engine(sharedContext(), scene.objects, kind, scene.materials, {}, PacketUse::Always);
    INFO(accelName(kind));
    const std::vector<HitGpu> hits = engine.intersect(rays);
    const std::vector<std::uint8_t> occluded = engine.occluded(rays);
    const std::vector<float> carried = engine.transmittance(toRayGpu(rays));
    if (engine.tracesPackets()) {
      checkIdentical("packets", hits, engine.intersect(rays, nullptr, RayCoherence::Coherent));
      checkShadowPackets(engine, toRayGpu(rays), occluded, carried);
    }
    std::size_t good_hits = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
      if (walkable[i]) {
        good_hits += hits[i].prim >= 0;
        continue;
      }
      INFO("ray " << i);
      CHECK(hits[i].prim == -1);
      CHECK(std::isinf(hits[i].t));
      CHECK(occluded[i] == 0);
      CHECK(carried[i] == 1.0f);
    }
    CHECK(good_hits > 0);  // the well-formed rays beside them still hit
    if (hits_before) CHECK(good_hits == hits_before);
    hits_before = good_hits;
  }
}

TEST_CASE("coherent rays go in packets through the trees on a CPU only, never with the BVH's linear motion or "
          "k-DOP bounds",
          "[accel]") {
  // The BVH's packet walk reads a node's boxes at shutter open
  // (accel/bvh_packets.h); a packet's eight lanes run one after another on a
  // GPU.
  DeviceDescription cpu, gpu;
  cpu.type = CL_DEVICE_TYPE_CPU;
  gpu.type = CL_DEVICE_TYPE_GPU;
  AccelScene scene = mixedScene();
  for (AccelKind kind : allAccelKinds()) {
    const std::unique_ptr<DeviceAccel> accel = buildAccel(kind, scene.objects);
    INFO(accelName(kind));
    CHECK(packetsPay(*accel, cpu) == (kind != AccelKind::None));
    CHECK_FALSE(packetsPay(*accel, gpu));
  }
  DeviceAccel moving = *buildAccel(AccelKind::Bvh, scene.objects);
  moving.kernel_options += " -DPRISM_BVH_MOTION";
  CHECK_FALSE(packetsPay(moving, cpu));
  AccelBuildOptions kdop;
  kdop.kdop_bvh = true;
  CHECK_FALSE(packetsPay(*buildAccel(AccelKind::Bvh, scene.objects, kdop), cpu));
}

TEST_CASE("shadow rays in packets through a semitransparent plane and triangles carry what one ray alone does",
          "[accel]") {
  // The plane x = 0.25 (k_trans 0.5) is tested before the tree: the rays that
  // cross it are walked alone from the start, the others in packets.
  AccelScene scene;
  scene.materials = {materialWithTransmit(0), materialWithTransmit(0.5f), materialWithTransmit(0.25f)};
  int m = 0;
  for (ObjectGpu& g : trianglesFromMesh(triangleSoup(600, 3, 0.1f))) {
    g.material = m++ % 3;
    scene.objects.push_back(g);
  }
  ObjectGpu plane = identityObject(OBJECT_PLANE, 1);
  plane.p[0] = 0.25f;
  plane.p[3] = 1;
  scene.objects.push_back(plane);
  std::vector<RayGpu> rays;
  for (int j = 0; j < 64; ++j)
    for (int i = 0; i < 64; ++i) {
      QueryRay q{(i + 0.5f) / 64, (j + 0.5f) / 64, -1, 1e-4f, 0, 0, 0, 1};
      q.dx = 0.5f - q.ox;
      q.dy = 0.5f - q.oy;
      q.dz = 3 - q.oz;
      rays.push_back(toRayGpu({q})[0]);
    }
  for (AccelKind kind : {AccelKind::Bvh, AccelKind::Octree, AccelKind::Bsp}) {
    RayQueryEngine engine(sharedContext(), scene.objects, kind, scene.materials, {}, PacketUse::Always);
    const std::vector<float> carried = engine.transmittance(rays);
    std::size_t dark = 0, clear = 0, plane_only = 0, more = 0, part = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
      const float c = carried[i];
      dark += c == 0.0f;
      clear += c == 1.0f;
      plane_only += c == 0.5f;
      more += c > 0.0f && c < 0.5f;
      // Beside the plane, through semitransparent triangles: met inside the walk.
      part += rays[i].ox > 0.25f && c > 0.0f && c < 1.0f;
    }
    INFO(accelName(kind) << ": " << dark << " rays blocked, " << clear << " clear, " << plane_only
                         << " through the plane alone, " << more << " through it and more, " << part
                         << " through triangles only");
    CHECK(dark > 0);
    CHECK(clear > 0);
    CHECK(plane_only > 0);
    CHECK(more > 0);
    CHECK(part > 0);
    checkShadowPackets(engine, rays, engine.occluded(rays), carried);
  }
}

TEST_CASE("the packet walks answer as one ray at a time on any device", "[accel][packets]") {
  // PacketUse::Always: on whatever device the tests run (PRISM_TEST_DEVICE).
  AccelScene scene = mixedScene(200);
  const Aabb box = boundsOf(scene.objects);
  std::vector<QueryRay> rays = cameraRays(box, 8, 8);
  const std::vector<QueryRay> random = randomRays(box, 60, 3), aimed = vertexRays(scene.objects, 13, 4);
  rays.insert(rays.end(), random.begin(), random.end());
  rays.insert(rays.end(), aimed.begin(), aimed.end());
  for (AccelKind kind : {AccelKind::Bvh, AccelKind::Octree, AccelKind::Bsp}) {
    RayQueryEngine engine(sharedContext(), scene.objects, kind, scene.materials, {}, PacketUse::Always);
    const std::vector<HitGpu> hits = engine.intersect(rays);
    checkPackets(engine, rays, hits);
    // To a light above, and to one behind the semitransparent wall plane (z
    // about -1.5), which sends every feeler on alone.
    const float above[3] = {box.hi[0] + 1, box.hi[1] + 2, box.hi[2] + 1.5f}, behind[3] = {0.5f, 0.5f, -3};
    for (const float* light : {above, behind}) {
      const std::vector<RayGpu> shadows = toRayGpu(shadowRays(rays, hits, light));
      checkShadowPackets(engine, shadows, engine.occluded(shadows), engine.transmittance(shadows));
    }
  }
}
