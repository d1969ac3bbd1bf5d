// The first-hit (Z-buffer) pass against traced primary rays (render/ray_queries.h,
// brute force over the scene) at random sample positions and at every pixel
// corner: scenes of triangles, transformed spheres and boxes and a plane, a camera
// inside the scene, a real mesh from the shared data, and a million-triangle grid
// whose answer is known in closed form.
#include "render/firsthit.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <iterator>
#include <memory>
#include <string>
#include <utility>
#include <vector>

#include "accel/prim_ref.h"
#include "accel_workloads.h"
#include "kernels/shared/ray_gpu.h"
#include "render/gpu_scene.h"
#include "render/ray_queries.h"
#include "render/sampler.h"
#include "support/shared_context.h"
#include "support/test_data.h"

using namespace prism;
using namespace prism::test;

namespace {

// The primary rays of sample positions, through the same camera arithmetic the
// firsthit kernel uses, so the two passes are handed the same rays.
const char* kRayProbe = R"(
#include "sampling/camera_ray.h"
#include "shading/ray_io.h"
__kernel void camera_rays(__global const CameraGpu* camera, __global const float* xy, int count,
                          __global RayGpu* rays) {
  int k = get_global_id(0);
  if (k >= count) return;
  float3 d = camera_ray_dir(camera, xy[2 * k], xy[2 * k + 1]);
  rays[k] = ray_make(load3g(camera->origin), d, 0.0f, INFINITY, (float3)(1.0f), k, 0, RAY_KIND_PRIMARY, 0);
}
)";

std::vector<RayGpu> cameraRays(const CameraGpu& camera, const std::vector<float>& xy) {
  Context& ctx = sharedContext();
  const size_t n = xy.size() / 2;
  Buffer cam(ctx, sizeof(CameraGpu)), pos(ctx, xy.size() * sizeof(float)), rays(ctx, n * sizeof(RayGpu));
  cam.write(&camera, sizeof(CameraGpu));
  pos.writeVector(xy);
  ctx.launch(ctx.kernelFromText(kRayProbe, "camera_rays.cl", "camera_rays"))
      .arg(cam)
      .arg(pos)
      .arg(static_cast<cl_int>(n))
      .arg(rays)
      .run(n);
  return rays.readVector<RayGpu>(n);
}

struct TestRng {
  std::uint64_t s;
  double next() {
    s = s * 6364136223846793005ull + 1442695040888963407ull;
    return static_cast<double>(s >> 11) * (1.0 / 9007199254740992.0);
  }
  double in(double lo, double hi) { return lo + (hi - lo) * next(); }
  Vec3 vec(double lo, double hi) { return {in(lo, hi), in(lo, hi), in(lo, hi)}; }
};

Scene emptyScene(const Vec3& eye, const Vec3& at, double fov, int width, int height) {
  Scene s;
  s.materials.push_back(defaultMaterial());
  s.camera.position = eye;
  s.camera.look_at = at;
  s.camera.fov = fov;
  s.film.width = width;
  s.film.height = height;
  return s;
}

Object triangle(const Vec3& a, const Vec3& b, const Vec3& c) {
  Object o;
  o.type = ObjectType::Triangle;
  o.vertices[0] = a;
  o.vertices[1] = b;
  o.vertices[2] = c;
  return o;
}

Object sphere(const Vec3& c, double r, const Transform& t = Transform::identity()) {
  Object o;
  o.type = ObjectType::Sphere;
  o.center = c;
  o.radius = r;
  o.transform = t;
  return o;
}

Object box(const Vec3& lo, const Vec3& hi, const Transform& t = Transform::identity()) {
  Object o;
  o.type = ObjectType::Box;
  o.box_min = lo;
  o.box_max = hi;
  o.transform = t;
  return o;
}

Object plane(const Vec3& p, const Vec3& n) {
  Object o;
  o.type = ObjectType::Plane;
  o.point = p;
  o.normal = n;
  return o;
}

// Random positions over the film plus every pixel corner (the film's edges included).
std::vector<float> samplePoints(int width, int height, int spp, std::uint64_t seed) {
  SamplingOptions random;
  random.mode = AaMode::Random;
  random.spp = spp;
  std::vector<float> xy = samplePositions(sharedContext(), random, width, height, seed);
  for (int j = 0; j <= height; ++j)
    for (int i = 0; i <= width; ++i) {
      xy.push_back(static_cast<float>(i));
      xy.push_back(static_cast<float>(j));
    }
  return xy;
}

// The kinds of atomics this device runs: 64-bit where it has them, and always
// the 32-bit pair of raster passes (what a device without them runs).
std::vector<ZBufferAtomics> atomicsOnThisDevice(Context& context) {
  if (context.device().hasExtension("cl_khr_int64_extended_atomics"))
    return {ZBufferAtomics::Wide, ZBufferAtomics::Narrow};
  return {ZBufferAtomics::Narrow};
}

const char* atomicsName(ZBufferAtomics atomics) { return atomics == ZBufferAtomics::Wide ? "64-bit" : "32-bit"; }

struct Agreement {
  size_t samples = 0, same_prim = 0, identical = 0, hits = 0;
};

// firstHits against traceClosest (a brute-force loop over the scene, equal
// depths to the lower index) on the same rays, with either kind of atomics.
Agreement compare(const Scene& scene, const std::vector<float>& xy, ZBufferAtomics atomics, int pixel_spp) {
  RenderOptions options = RenderOptions::fromScene(scene);
  GpuScene gpu = flattenScene(scene, options);
  std::vector<HitGpu> z = firstHits(sharedContext(), gpu, xy, atomics, pixel_spp);
  std::vector<HitGpu> traced = traceClosest(sharedContext(), scene, cameraRays(gpu.camera, xy));
  Agreement a;
  a.samples = z.size();
  for (size_t k = 0; k < z.size(); ++k) {
    if (z[k].prim != traced[k].prim) continue;
    ++a.same_prim;
    if (z[k].prim >= 0) ++a.hits;
    // The same routine on the same ray: the same t, u, v bit for bit.
    if (z[k].prim < 0 || std::memcmp(&z[k], &traced[k], sizeof(HitGpu)) == 0) ++a.identical;
  }
  return a;
}

// With each kind of atomics the device runs.
// pixel_spp > 0: xy holds that many samples a pixel in pixel order (no pixel
// corners), as the per-pixel sampling modes hand a batch to the pass.
void checkAgreement(const Scene& scene, const std::vector<float>& xy, int pixel_spp = 0) {
  for (ZBufferAtomics atomics : atomicsOnThisDevice(sharedContext())) {
    Agreement a = compare(scene, xy, atomics, pixel_spp);
    INFO(atomicsName(atomics) << " atomics: " << a.samples << " samples, " << a.same_prim << " with the same primid, "
                              << a.identical << " identical, " << a.hits << " hits");
    CHECK(a.same_prim == a.samples);
    CHECK(a.identical == a.samples);
    CHECK(a.hits > a.samples / 4);
  }
}

FirstHitStats passStats(const GpuScene& gpu, const std::vector<float>& xy) {
  Context& ctx = sharedContext();
  FirstHitPass pass(ctx);
  pass.prepare(gpu, primitiveKernelOptions(gpu.objects));
  GeometryBuffers objects(ctx, gpu);
  Buffer pos(ctx, xy.size() * sizeof(float)), hits(ctx, xy.size() / 2 * sizeof(HitGpu));
  pos.writeVector(xy);
  pass.run(objects, pos, xy.size() / 2, hits);
  return pass.stats();
}

}  // namespace

TEST_CASE("first hits agree with traced rays on triangles, transformed spheres and boxes, and a plane", "[firsthit]") {
  Scene scene = emptyScene({0.5, 1.0, 9}, {0, 0, 0}, 40, 96, 72);
  TestRng rng{11};
  for (int k = 0; k < 1500; ++k) {
    Vec3 c = rng.vec(-3, 3);
    double size = k % 50 == 0 ? 2.5 : rng.in(0.05, 0.6);
    scene.objects.push_back(triangle(c + rng.vec(-size, size), c + rng.vec(-size, size), c + rng.vec(-size, size)));
  }
  for (int k = 0; k < 6; ++k) {
    Transform t = Transform::translate(rng.vec(-2.5, 2.5)) * Transform::rotate(rng.vec(-1, 1), rng.in(0, 180)) *
                  Transform::scale({rng.in(0.3, 1.2), rng.in(0.3, 1.2), rng.in(0.3, 1.2)});
    scene.objects.push_back(k % 2 ? sphere({0, 0, 0}, 0.6, t) : sphere(rng.vec(-2.5, 2.5), rng.in(0.2, 0.7)));
    scene.objects.push_back(k % 2 ? box({-0.5, -0.4, -0.3}, {0.5, 0.4, 0.3}, t) : box({1, 1, 1}, {1.6, 1.3, 1.2}));
  }
  scene.objects.push_back(plane({0, -3.5, 0}, normalize(Vec3{0.05, 1, 0.1})));
  std::vector<float> xy = samplePoints(96, 72, 3, 7);
  checkAgreement(scene, xy);
  RenderOptions options = RenderOptions::fromScene(scene);
  const GpuScene gpu = flattenScene(scene, options);
  // Positions in pixel order (3 to a pixel, as the per-pixel modes number them)
  // need no sort: the same hits as sorting them.
  SamplingOptions random;
  random.mode = AaMode::Random;
  random.spp = 3;
  std::vector<float> ordered = samplePositions(sharedContext(), random, 96, 72, 8);
  std::vector<HitGpu> sorted = firstHits(sharedContext(), gpu, ordered, ZBufferAtomics::Auto, 0);
  std::vector<HitGpu> unsorted = firstHits(sharedContext(), gpu, ordered, ZBufferAtomics::Auto, 3);
  REQUIRE(sorted.size() == unsorted.size());
  CHECK(std::memcmp(sorted.data(), unsorted.data(), sorted.size() * sizeof(HitGpu)) == 0);
  FirstHitStats stats = passStats(gpu, xy);
  CHECK(stats.others == 13);  // the spheres, the boxes and the plane
  // The plane covers every 8x8 block (12 x 9); the triangles, mostly small, few each.
  CHECK(stats.pairs >= 12 * 9);
  CHECK(stats.pairs < 12 * 9 + 8 * scene.objects.size());
}

TEST_CASE("first hits agree with traced rays when primitives cross the camera plane or surround the camera",
          "[firsthit]") {
  // A camera inside a room (a box around it) among triangles and a transformed
  // sphere that pass beside and behind it; some triangles lie wholly behind it.
  Scene scene = emptyScene({0, 0, 0}, {0.2, -0.1, -1}, 70, 64, 48);
  TestRng rng{5};
  scene.objects.push_back(box({-6, -4, -6}, {6, 4, 6}, Transform::rotate({0, 1, 0}, 20)));
  for (int k = 0; k < 600; ++k) {
    Vec3 c = rng.vec(-3, 3);
    double size = rng.in(0.2, 2.5);
    scene.objects.push_back(triangle(c + rng.vec(-size, size), c + rng.vec(-size, size), c + rng.vec(-size, size)));
  }
  // Slivers from behind the camera to in front of it: their images run off the
  // film on the side where they cross the camera plane.
  for (int k = 0; k < 300; ++k) {
    Vec3 behind{rng.in(-1.5, 1.5), rng.in(-1.5, 1.5), rng.in(0.05, 1)};
    Vec3 front{rng.in(-1, 1), rng.in(-1, 1), -rng.in(1, 4)};
    scene.objects.push_back(triangle(behind, front, front + rng.vec(-0.3, 0.3)));
  }
  scene.objects.push_back(triangle({-1, -1, 0.5}, {1, -1, 0.5}, {0, 1, 0.7}));  // entirely behind
  scene.objects.push_back(sphere({0, 0, 0}, 1, Transform::translate({0.3, 0, 0.2}) * Transform::scale({1.5, 0.3, 2})));
  scene.objects.push_back(plane({0, -2, 0}, {0, 1, 0}));
  checkAgreement(scene, samplePoints(64, 48, 4, 3));
}

TEST_CASE("first hits agree with traced rays on triangles with a vertex on the camera plane", "[firsthit]") {
  // Slivers from a point beside the camera (on its plane, within the film
  // bounds' tolerance of it) to the view ahead, before a wall: the image of each
  // runs off the film toward that vertex, beyond the bounds of the other two.
  Scene scene = emptyScene({0, 0, 0}, {0.2, -0.1, -1}, 70, 64, 48);
  TestRng rng{7};
  const Vec3 forward = normalize(Vec3{0.2, -0.1, -1});
  for (int k = 0; k < 40; ++k) {
    Vec3 side = normalize(cross(rng.vec(-1, 1), forward)) * rng.in(0.3, 2);
    Vec3 front = forward * rng.in(1.5, 4) + rng.vec(-1, 1);
    scene.objects.push_back(triangle(side, front, front + rng.vec(-0.3, 0.3)));
  }
  scene.objects.push_back(box({-20, -20, -30}, {20, 20, -25}));
  checkAgreement(scene, samplePoints(64, 48, 4, 3));
}

TEST_CASE("triangles facing away from the camera keep every sample where they lie nearest", "[firsthit]") {
  // The pass rasterises triangles facing away from the camera after the rest, and skips a block's row where a bound says none of their
  // tests could come nearer than every depth kept in it. The camera sits at
  // the centre of a sphere of radius 3, so a row's kept depths are 3 except
  // where plates facing the camera hide it at 1.5 to 2.5. Small triangles
  // facing away lie square to their line of sight from 2e-5 to 2e-2 of that
  // distance inside the sphere (and some just outside): a bound too high by
  // half a percent hides some of them; others lean away from the camera, so
  // that their t is least at one edge of their film box. Slivers facing away
  // run from behind the camera to beyond the sphere, where only the box of
  // their two vertices in front is known. The film is not a whole number of
  // 8x8 blocks; the samples go in pixel order and, sorted, in cell order.
  Scene scene = emptyScene({0, 0, 0}, {0, 0, -1}, 20, 61, 45);
  const Vec3 forward{0, 0, -1}, right{1, 0, 0}, up{0, 1, 0};
  const double half = std::tan(10.0 * 3.14159265358979 / 180.0);  // of the film's width
  scene.objects.push_back(sphere({0, 0, 0}, 3));
  TestRng rng{11};
  const auto facing = [](Object t, bool away) {
    const Vec3 n = cross(t.vertices[1] - t.vertices[0], t.vertices[2] - t.vertices[0]);
    if ((dot(Vec3{0, 0, 0} - t.vertices[0], n) > 0) == away) std::swap(t.vertices[1], t.vertices[2]);
    return t;
  };
  const auto sight = [&] { return normalize(forward + right * rng.in(-half, half) + up * rng.in(-0.75, 0.75) * half); };
  for (int k = 0; k < 12; ++k) {  // plates at 1.5 to 2.5
    const Vec3 c = sight() * rng.in(1.5, 2.5);
    const double w = rng.in(0.03, 0.12), h = rng.in(0.01, 0.06);
    scene.objects.push_back(facing(triangle(c + Vec3{-w, -h, 0}, c + Vec3{w, -h, 0}, c + Vec3{w, h, 0}), false));
    scene.objects.push_back(facing(triangle(c + Vec3{-w, -h, 0}, c + Vec3{w, h, 0}, c + Vec3{-w, h, 0}), false));
  }
  const size_t first_away = scene.objects.size();
  for (int k = 0; k < 500; ++k) {
    const Vec3 d = sight();
    const double gap = std::pow(10.0, rng.in(-4.7, -1.7)) * (k % 5 == 0 ? -1 : 1);
    const Vec3 c = d * (3 * (1 - gap));
    const Vec3 u = normalize(cross(d, up)), v = cross(u, d);
    const double size = rng.in(0.004, 0.03);
    const auto corner = [&] { return c + u * rng.in(-size, size) + v * rng.in(-size, size); };
    scene.objects.push_back(facing(triangle(corner(), corner(), corner()), true));
  }
  for (int k = 0; k < 60; ++k) {
    const Vec3 d = sight();
    const Vec3 c = d * (3 * (1 - std::pow(10.0, rng.in(-3.0, -1.5))));
    const Vec3 u = normalize(cross(d, up)), v = cross(u, d);
    const double s = rng.in(0.02, 0.06), tilt = rng.in(2.0, 6.0);
    const Vec3 side = k % 2 ? u : v, other = k % 2 ? v : u;
    scene.objects.push_back(facing(triangle(c - other * s, c + other * s, c + side * s + d * (s * tilt)), true));
  }
  for (int k = 0; k < 30; ++k) {
    const Vec3 behind{rng.in(-1, 1), rng.in(-1, 1), rng.in(0.1, 1)};
    const Vec3 far = sight() * rng.in(4, 6);
    scene.objects.push_back(facing(triangle(behind, far, far + rng.vec(-0.2, 0.2)), true));
  }
  for (int spp : {1, 4}) {
    INFO(spp << " samples a pixel");
    SamplingOptions random;
    random.mode = AaMode::Random;
    random.spp = spp;
    const std::vector<float> xy = samplePositions(sharedContext(), random, 61, 45, 17);
    checkAgreement(scene, xy, spp);
    checkAgreement(scene, xy, 0);
    // The scene tests what it means to: triangles facing away win many
    // samples, and the sphere and the plates keep some.
    const GpuScene gpu = flattenScene(scene, RenderOptions::fromScene(scene));
    const std::vector<HitGpu> z = firstHits(sharedContext(), gpu, xy, ZBufferAtomics::Auto, spp);
    size_t away = 0, sphere_kept = 0, plates = 0;
    for (const HitGpu& h : z) {
      away += h.prim >= static_cast<int>(first_away);
      sphere_kept += h.prim == 0;
      plates += h.prim > 0 && h.prim < static_cast<int>(first_away);
    }
    CHECK(away > z.size() / 10);
    CHECK(sphere_kept > z.size() / 10);
    CHECK(plates > z.size() / 50);

    // The frame in three batches on one pass, cut mid-row (and mid-pixel at
    // 4 spp) as a render cuts its batches wherever 2^22 samples end, the
    // middle one last: its cull must read the depths of its own rows, not
    // those its neighbours left in the block rows it shares with them (0 in
    // rows they had no samples in). With both kinds of atomics.
    Context& context = sharedContext();
    GeometryBuffers geometry(context, gpu);
    Buffer positions(context, xy.size() * sizeof(float)), hits(context, z.size() * sizeof(HitGpu));
    positions.writeVector(xy);
    const size_t row = 61 * static_cast<size_t>(spp), cut1 = 15 * row - 5, cut2 = 30 * row + 7;
    REQUIRE(45 * row == z.size());
    const std::pair<size_t, size_t> batches[] = {{0, cut1}, {cut2, z.size()}, {cut1, cut2}};
    for (ZBufferAtomics atomics : atomicsOnThisDevice(context)) {
      INFO(atomicsName(atomics) << " atomics, in three batches");
      FirstHitPass pass(context, atomics);
      pass.prepare(gpu, primitiveKernelOptions(gpu.objects));
      std::vector<HitGpu> batched(z.size());
      for (const auto& [first, end] : batches) {
        pass.rasterize(geometry, positions, 0, first, end - first, spp);
        pass.resolve(geometry, 0, end - first, hits);
        hits.read(batched.data() + first, (end - first) * sizeof(HitGpu));
      }
      CHECK(std::memcmp(batched.data(), z.data(), z.size() * sizeof(HitGpu)) == 0);
    }
  }
}

// The 3,851-triangle bunny filling the middle of an 80x60 film, a sphere beside it.
static Scene bunnyAndSphere(int width = 80) {
  prism::SharedMesh bunny = prism_test::loadTestMesh("bunny/bun_zipper_res3.ply");
  REQUIRE(bunny->triangleCount() == 3851);
  Scene scene = emptyScene({0, 1.6, 4}, {0, 1.0, 0}, 35, width, 60);
  Object mesh;
  mesh.type = ObjectType::Mesh;
  mesh.mesh = bunny;
  mesh.transform = Transform::translate({0.2, -0.4, 0}) * Transform::scale({14, 14, 14});
  scene.objects.push_back(mesh);
  scene.objects.push_back(sphere({-1.3, 0.6, -0.5}, 0.5));
  return scene;
}

TEST_CASE("first hits agree with traced rays on a real mesh", "[firsthit][mesh]") {
  Scene scene = bunnyAndSphere();
  scene.objects.push_back(plane({0, 0.05, 0}, {0, 1, 0}));
  checkAgreement(scene, samplePoints(80, 60, 4, 21));
}

TEST_CASE("a batch in pixel order, begun and ended mid-pixel and resolved in chunks, gives the hits of sorting it",
          "[firsthit][mesh]") {
  // The renders' path: a batch of the frame's samples from `first` on, in a
  // window of positions that starts before it (xy_first), kept in pixel order
  // and resolved chunk by chunk (firsthit_resolve), against the same
  // positions sorted by the counting sort and resolved sample by sample; with
  // both kinds of atomics, on a film whose width is not a multiple of the
  // raster's 8-pixel blocks.
  constexpr int kWidth = 83;
  const Scene scene = bunnyAndSphere(kWidth);
  RenderOptions options = RenderOptions::fromScene(scene);
  const GpuScene gpu = flattenScene(scene, options);
  SamplingOptions random;
  random.mode = AaMode::Random;
  random.spp = 3;
  const std::vector<float> all = samplePositions(sharedContext(), random, kWidth, 60, 5);  // 14,940
  // From pixel (40, 30), on the bunny, its second sample, to a pixel's second sample.
  const size_t xy_first = 1000, first = 3 * (30 * kWidth + 40) + 1, count = 4999;
  REQUIRE((first + count) % 3 != 0);
  Context& context = sharedContext();
  GeometryBuffers geometry(context, gpu);
  Buffer xy(context, (all.size() - 2 * xy_first) * sizeof(float));
  xy.write(all.data() + 2 * xy_first, (all.size() - 2 * xy_first) * sizeof(float));
  Buffer hits(context, count * sizeof(HitGpu));

  for (ZBufferAtomics atomics : atomicsOnThisDevice(context)) {
    INFO(atomicsName(atomics) << " atomics");
    FirstHitPass pass(context, atomics);
    pass.prepare(gpu, primitiveKernelOptions(gpu.objects));
    pass.rasterize(geometry, xy, xy_first, first, count, 0);
    pass.resolve(geometry, 0, count, hits);
    const std::vector<HitGpu> sorted = hits.readVector<HitGpu>(count);

    pass.rasterize(geometry, xy, xy_first, first, count, 3);
    std::vector<HitGpu> chunked;
    for (size_t at = 0; at < count; at += 777) {
      const size_t n = std::min<size_t>(777, count - at);
      pass.resolve(geometry, at, n, hits);
      const std::vector<HitGpu> part = hits.readVector<HitGpu>(n);
      chunked.insert(chunked.end(), part.begin(), part.end());
    }
    REQUIRE(chunked.size() == sorted.size());
    REQUIRE(sorted.front().prim >= 0);  // the split pixels' samples are hits, so their places are checked
    CHECK(std::memcmp(chunked.data(), sorted.data(), sorted.size() * sizeof(HitGpu)) == 0);
    size_t hit = 0;
    for (const HitGpu& h : sorted) hit += h.prim >= 0;
    CHECK(hit > count / 4);  // the bunny and the sphere fill part of the frame
  }
}

TEST_CASE("a pass prepared again for another scene and film gives the hits and pairs of a fresh pass",
          "[firsthit][mesh]") {
  // prepare keeps its buffers from one frame to the next, so what a frame
  // finds in them must not matter: a batch of part of a narrow film, then a
  // whole wider film with a plane among its primitives (most buffers grow),
  // then the narrow film's batch again in the larger buffers the wide one
  // left; each batch in pixel order and sorted (the counts and slots of the
  // counting sort), each pass into a buffer of its own. Then a still wider
  // film in pixel order alone (the cell counts' buffer grows and no sorted
  // batch zeroes it), the narrow film's sorted batch again, whose cells fit
  // in what the old buffer had zeroed, and the wide film's sorted batch,
  // whose cells are more than that.
  struct Frame {
    GpuScene gpu;
    size_t first, count;
    std::vector<int> orders;  // pixel_spp of its batches: 1 in pixel order, 0 sorted
  };
  auto frame = [](int width, bool with_plane, size_t first_row, size_t rows, std::vector<int> orders) {
    Scene scene = bunnyAndSphere(width);
    if (with_plane) scene.objects.push_back(plane({0, 0.05, 0}, {0, 1, 0}));
    const size_t w = static_cast<size_t>(width);
    return Frame{flattenScene(scene, RenderOptions::fromScene(scene)), first_row * w, rows * w, std::move(orders)};
  };
  const Frame frames[] = {frame(83, false, 25, 12, {1, 0}), frame(120, true, 0, 60, {1, 0}),
                          frame(83, false, 25, 12, {1, 0}), frame(200, true, 0, 60, {1}),
                          frame(83, false, 25, 12, {0}), frame(120, true, 0, 60, {0})};
  Context& context = sharedContext();
  for (ZBufferAtomics atomics : atomicsOnThisDevice(context)) {
    FirstHitPass reused(context, atomics);
    for (size_t f = 0; f < std::size(frames); ++f) {
      INFO(atomicsName(atomics) << " atomics, frame " << f);
      const Frame& fr = frames[f];
      const int width = fr.gpu.camera.width, height = fr.gpu.camera.height;
      std::vector<float> xy;  // every pixel's centre, in pixel order
      for (int j = 0; j < height; ++j)
        for (int i = 0; i < width; ++i) xy.insert(xy.end(), {i + 0.5f, j + 0.5f});
      GeometryBuffers geometry(context, fr.gpu);
      Buffer pos(context, xy.size() * sizeof(float));
      pos.writeVector(xy);
      for (int pixel_spp : fr.orders) {
        INFO((pixel_spp ? "in pixel order" : "sorted"));
        auto pass = [&](FirstHitPass& p) {
          Buffer hits(context, fr.count * sizeof(HitGpu));
          const std::uint32_t unwritten = 0xFFFFFFFFu;  // no hit's bits: a hit resolve skips cannot match
          hits.fill(&unwritten, sizeof unwritten, fr.count * sizeof(HitGpu));
          p.prepare(fr.gpu, primitiveKernelOptions(fr.gpu.objects));
          p.rasterize(geometry, pos, 0, fr.first, fr.count, pixel_spp);
          p.resolve(geometry, 0, fr.count, hits);
          return std::make_pair(hits.readVector<HitGpu>(fr.count), p.stats().pairs);
        };
        FirstHitPass fresh(context, atomics);
        const auto expected = pass(fresh);
        const auto got = pass(reused);
        size_t hit = 0;
        for (const HitGpu& h : expected.first) hit += h.prim >= 0;
        CHECK(hit > fr.count / 4);
        CHECK(std::memcmp(got.first.data(), expected.first.data(), fr.count * sizeof(HitGpu)) == 0);
        CHECK(got.second == expected.second);
      }
    }
  }
}

TEST_CASE("first hits on a million triangles match the closed form", "[firsthit][scale]") {
  // A grid of nx x ny quads in the plane z = 0 spanning [-1, 1]^2, each cut along
  // its diagonal into (p00, p10, p11) and (p00, p11, p01), seen head-on from z = 3.
  const int nx = 708, ny = 706;
  const int width = 160, height = 120;
  Camera camera;
  camera.position = {0.01, -0.02, 3};
  camera.look_at = {0.01, -0.02, 0};
  camera.fov = 2 * std::atan(1.0 / 3.0) * 180 / M_PI;
  // One mesh: its triangles are compact on the device (accel/scene_geometry.h).
  TriangleMesh grid;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i)
      grid.positions.insert(grid.positions.end(), {static_cast<float>(-1.0 + 2.0 * i / nx),
                                                   static_cast<float>(-1.0 + 2.0 * j / ny), 0.0f});
  auto vertex = [&](int i, int j) { return static_cast<std::uint32_t>(j * (nx + 1) + i); };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      grid.indices.insert(grid.indices.end(), {vertex(i, j), vertex(i + 1, j), vertex(i + 1, j + 1), vertex(i, j),
                                               vertex(i + 1, j + 1), vertex(i, j + 1)});
  GpuScene gpu;
  static_cast<SceneGeometry&>(gpu) = geometryFromMesh(grid);
  REQUIRE(gpu.primitive_count >= 999000);
  REQUIRE(gpu.triangleCount() == gpu.primitive_count);
  CameraBasis b = cameraBasis(camera, width, height);
  auto put = [](float* dst, const Vec3& v) {
    dst[0] = static_cast<float>(v.x);
    dst[1] = static_cast<float>(v.y);
    dst[2] = static_cast<float>(v.z);
  };
  put(gpu.camera.origin, b.origin);
  put(gpu.camera.forward, b.forward);
  put(gpu.camera.right, b.right);
  put(gpu.camera.up, b.up);
  gpu.camera.width = width;
  gpu.camera.height = height;
  gpu.camera.spp = 1;

  std::vector<float> xy = samplePoints(width, height, 1, 9);
  FirstHitStats stats = passStats(gpu, xy);
  INFO(stats.pairs << " pairs");
  CHECK(stats.pairs < 2 * gpu.primitive_count);  // small triangles touch few blocks
  CHECK(stats.others == 0);
  std::vector<HitGpu> hits = firstHits(sharedContext(), gpu, xy);
  // The closed form, in double from the float camera: skip samples within 1e-3
  // of a cell of an edge or a diagonal, where float rounding may pick either side.
  size_t judged = 0, agree = 0, depth_off = 0;
  const Vec3 o{gpu.camera.origin[0], gpu.camera.origin[1], gpu.camera.origin[2]};
  const Vec3 f{gpu.camera.forward[0], gpu.camera.forward[1], gpu.camera.forward[2]};
  const Vec3 r{gpu.camera.right[0], gpu.camera.right[1], gpu.camera.right[2]};
  const Vec3 u{gpu.camera.up[0], gpu.camera.up[1], gpu.camera.up[2]};
  for (size_t k = 0; k < hits.size(); ++k) {
    double sx = 2.0 * xy[2 * k] / width - 1, sy = 1 - 2.0 * xy[2 * k + 1] / height;
    Vec3 d = normalize(f + r * sx + u * sy);
    double t = -o.z / d.z;
    Vec3 p = o + d * t;
    double cx = (p.x + 1) * nx / 2, cy = (p.y + 1) * ny / 2;
    int expected = -1;
    double fx = cx - std::floor(cx), fy = cy - std::floor(cy);
    const double m = 1e-3;
    bool inside = cx >= 0 && cx < nx && cy >= 0 && cy < ny;
    bool near =
        std::min({fx, 1 - fx, fy, 1 - fy, std::fabs(fx - fy)}) < m || cx < m || cy < m || cx > nx - m || cy > ny - m;
    if (near && (inside || cx > -m && cx < nx + m && cy > -m && cy < ny + m)) continue;
    if (inside) expected = 2 * (static_cast<int>(cy) * nx + static_cast<int>(cx)) + (fx >= fy ? 0 : 1);
    ++judged;
    if (hits[k].prim != expected) continue;
    ++agree;
    if (expected >= 0 && std::fabs(hits[k].t - t) / t > 1e-5) ++depth_off;
  }
  INFO(judged << " judged of " << hits.size() << ", " << agree << " agree");
  CHECK(judged > 0.95 * hits.size());
  CHECK(agree >= 0.9999 * judged);
  CHECK(depth_off == 0);
}

TEST_CASE("first hit auto takes the Z-buffer while primitives are few beside the samples", "[firsthit]") {
  // The rule of firsthit.h: bounded primitives count one each, an unbounded one
  // kUnboundedAsPrims x samples; the Z-buffer pays up to kZBufferPrimsPerSample x samples.
  GpuScene gpu;
  ObjectGpu tri{};
  tri.type = OBJECT_TRIANGLE;
  const float v[9] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  std::copy(v, v + 9, tri.p);
  const std::uint64_t samples = 1000000;
  const size_t limit = static_cast<size_t>(kZBufferPrimsPerSample * samples);
  static_cast<SceneGeometry&>(gpu) = geometryFromRecords(std::vector<ObjectGpu>(limit, tri));
  CHECK(zbufferPays(gpu, samples));
  gpu.objects.push_back(tri);
  gpu.primitive_count = gpu.triangle_base = gpu.objects.size();
  CHECK_FALSE(zbufferPays(gpu, samples));
  CHECK(zbufferPays(gpu, 2 * samples));
  // One plane outweighs a few triangles.
  Scene scene = emptyScene({0, 1, 5}, {0, 0, 0}, 40, 64, 48);
  scene.objects.push_back(triangle({0, 0, 0}, {1, 0, 0}, {0, 1, 0}));
  CHECK(zbufferPays(flattenScene(scene, RenderOptions::fromScene(scene)), 64 * 48));
  scene.objects.push_back(plane({0, -1, 0}, {0, 1, 0}));
  CHECK_FALSE(zbufferPays(flattenScene(scene, RenderOptions::fromScene(scene)), 64 * 48));
}
