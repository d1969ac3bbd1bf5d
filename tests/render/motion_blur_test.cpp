// Motion blur against the time integral: a sphere moving across the view covers
// each pixel for the fraction of the shutter the closed form gives; every
// acceleration structure sees moving objects where brute force does; the host's
// motion interpolation reproduces both end transforms and slerps rotation.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <vector>

#include "accel_workloads.h"
#include "render/gpu_scene.h"
#include "render/renderer.h"
#include "scene/motion.h"
#include "scene_format/scene_loader.h"
#include "support/shared_context.h"

using namespace prism;
using namespace prism::test;

namespace {

// A sphere of radius R moving by L along x during the shutter, seen face on.
constexpr double kR = 0.5, kL = 3.0;

Scene movingSphereScene(int spp) {
  const std::string json = R"({
    "camera": {"position": [0, 0, 20], "look_at": [0, 0, 0], "fov": 15, "shutter": [0, 1]},
    "film": {"width": 96, "height": 32, "spp": )" + std::to_string(spp) + R"(},
    "render": {"max_depth": 0},
    "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 0.5,
                 "transform": {"translate": [-1.5, 0, 0]}, "transform_end": {"translate": [1.5, 0, 0]}}]
  })";
  return parseScene(json, "moving_sphere.json");
}

// The fraction of the shutter during which the ray (o, d) meets the sphere of
// radius kR whose centre moves from (-kL/2, 0, 0) to (kL/2, 0, 0): the times
// where |c(s) - o|^2 - ((c(s) - o)·d)^2 < R^2 form one interval, the roots of a
// quadratic in s.
double coveredFraction(const Vec3& o, const Vec3& d) {
  // c(s) - o = a + s b
  const Vec3 a = Vec3{-kL / 2, 0, 0} - o, b{kL, 0, 0};
  auto perp = [&](const Vec3& v) { return v - d * dot(v, d); };
  const Vec3 pa = perp(a), pb = perp(b);
  const double qa = dot(pb, pb), qb = 2 * dot(pa, pb), qc = dot(pa, pa) - kR * kR;
  const double disc = qb * qb - 4 * qa * qc;
  if (disc <= 0) return 0;
  const double s0 = (-qb - std::sqrt(disc)) / (2 * qa), s1 = (-qb + std::sqrt(disc)) / (2 * qa);
  return std::max(0.0, std::min(1.0, s1) - std::max(0.0, s0));
}

// Every structure renders `scene` (with `opt`) to the same ids and colours as
// the brute-force `reference`.
void checkStructuresMatch(const Scene& scene, RenderOptions opt, const RenderResult& reference) {
  for (AccelKind kind : {AccelKind::Bvh, AccelKind::Octree, AccelKind::Bsp}) {
    opt.accel = kind;
    const RenderResult r = sharedRenderer().render(scene, opt);
    INFO(accelName(kind));
    CHECK(r.primid == reference.primid);
    CHECK(r.rgba == reference.rgba);
  }
  // The BVH over swept boxes: moving triangles sit in its ordinary leaves,
  // which the camera rays' packets (render/ray_kernel.h) test ray by ray.
  AccelBuildOptions swept;
  swept.bvh_linear_bounds = false;
  sharedRenderer().setAccelBuildOptions(swept);
  opt.accel = AccelKind::Bvh;
  const RenderResult r = sharedRenderer().render(scene, opt);
  sharedRenderer().setAccelBuildOptions({});
  INFO("bvh, swept boxes");
  CHECK(r.primid == reference.primid);
  CHECK(r.rgba == reference.rgba);
}

}  // namespace

TEST_CASE("a sphere moving across the view covers each pixel for the time the integral predicts",
          "[render][distributed][motion]") {
  const Scene scene = movingSphereScene(64);
  RenderOptions opt = RenderOptions::fromScene(scene);
  RenderResult r = sharedRenderer().render(scene, opt);
  REQUIRE(r.stats.first_hit == FirstHitMode::Trace);  // a shutter interval needs traced rays

  // The reference: the time integral, averaged over a 6 x 6 grid of each pixel.
  const CameraBasis cam = cameraBasis(scene.camera, opt.width, opt.height);
  const int row = opt.height / 2;
  std::vector<double> expected_row(opt.width);
  for (int i = 0; i < opt.width; ++i) {
    double expected = 0;
    for (int sy = 0; sy < 6; ++sy)
      for (int sx = 0; sx < 6; ++sx) {
        const double fx = (i + (sx + 0.5) / 6) / opt.width * 2 - 1;
        const double fy = 1 - (row + (sy + 0.5) / 6) / opt.height * 2;
        expected += coveredFraction(cam.origin, normalize(cam.forward + cam.right * fx + cam.up * fy)) / 36;
      }
    expected_row[i] = expected;
    const double alpha = r.rgba[4 * (static_cast<size_t>(row) * opt.width + i) + 3];
    INFO("pixel " << i << ": alpha " << alpha << ", expected " << expected);
    // 64 samples stratified in time and position: well inside 0.06 of the integral.
    CHECK(std::fabs(alpha - expected) < 0.06);
  }
  // The plateau: coverage 2R/L wherever the whole sphere passes over the pixel
  // (this row is half a pixel off the centre line, where the chord is a little
  // shorter than 2R).
  const double top = *std::max_element(expected_row.begin(), expected_row.end());
  CHECK(std::fabs(top - 2 * kR / kL) < 0.01);
  double plateau_sum = 0;
  int plateau_n = 0, ramp_pixels = 0;
  for (int i = 0; i < opt.width; ++i) {
    if (expected_row[i] > top - 1e-3) {
      plateau_sum += r.rgba[4 * (static_cast<size_t>(row) * opt.width + i) + 3];
      ++plateau_n;
    }
    if (expected_row[i] > 0.02 && expected_row[i] < top - 0.02) ++ramp_pixels;
  }
  REQUIRE(plateau_n > 10);
  CHECK(std::fabs(plateau_sum / plateau_n - 2 * kR / kL) < 0.02);
  // Two ramps of width 2R each, in pixels through the camera's scale.
  const double pixels_per_unit = opt.width / (2 * length(cam.right) * length(Vec3{0, 0, 20}));
  CHECK(std::fabs(ramp_pixels - 2 * 2 * kR * pixels_per_unit) < 6);
}

TEST_CASE("every structure finds moving spheres, boxes, triangles, planes, quadrics and polygons where brute force does", "[render][distributed][motion][accel]") {
  const char* json = R"({
    "camera": {"position": [0, 2, 9], "look_at": [0, 0.5, 0], "fov": 40, "shutter": [0, 1]},
    "film": {"width": 48, "height": 36, "spp": 4},
    "render": {"max_depth": 2},
    "materials": {"m": {"diffuse": 0.7, "reflect": 0.3}},
    "lights": [{"position": [2, 6, 4]}],
    "objects": [
      {"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0],
       "transform_end": [{"rotate": {"axis": [1, 0, 0], "angle": 8}}, {"translate": [0, -0.2, 0]}]},
      {"type": "sphere", "center": [0, 0.6, 0], "radius": 0.6, "material": "m",
       "transform": {"translate": [-2, 0, 0]}, "transform_end": {"translate": [1, 0, 1]}},
      {"type": "box", "min": [-0.4, -0.4, -0.4], "max": [0.4, 0.4, 0.4], "material": "m",
       "transform": {"translate": [1.5, 1.5, 0]},
       "transform_end": [{"rotate": {"axis": [1, 1, 0], "angle": 120}}, {"scale": 1.5}, {"translate": [1.5, 1.8, 0]}]},
      {"type": "triangle", "vertices": [[-1, 0.1, -1], [1, 0.1, -1], [0, 1.5, -1]],
       "transform_end": {"translate": [0, 1, 0]}},
      {"type": "cylinder", "radius": 0.3, "height": 0.8, "material": "m", "transform": {"translate": [-1.5, 0, 1]},
       "transform_end": [{"rotate": {"axis": [0, 0, 1], "angle": 60}}, {"translate": [-1, 0.3, 1]}]},
      {"type": "polygon", "vertices": [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0.5, 0.4, 0], [0, 1, 0]], "material": "m",
       "transform": {"translate": [2, 0.2, 1]}, "transform_end": {"translate": [2.5, 0.8, 1]}}
    ]
  })";
  const Scene scene = parseScene(json, "moving.json");
  RenderOptions opt = RenderOptions::fromScene(scene);
  opt.accel = AccelKind::None;
  const RenderResult reference = sharedRenderer().render(scene, opt);
  checkStructuresMatch(scene, opt, reference);
}

TEST_CASE("motion interpolation reproduces both ends and turns at a constant rate", "[host][motion]") {
  const Transform open = Transform::translate({1, 2, 3}) * Transform::rotate({0, 0, 1}, 10) * Transform::scale({2, 1, 1});
  const Transform close =
      Transform::translate({-1, 0, 5}) * Transform::rotate({0, 0, 1}, 100) * Transform::scale({2, 1, 1});
  const DecomposedTransform a = decompose(open), b = decompose(close);
  for (auto [s, want] : {std::pair{0.0, &open}, {1.0, &close}}) {
    const Transform t = interpolate(a, b, s);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 4; ++j) CHECK(t.m[i][j] == Approx(want->m[i][j]).margin(1e-12));
  }
  // Halfway: rotation 55 degrees about z, translation halfway, the same stretch.
  const Transform half = interpolate(a, b, 0.5);
  const Transform want = Transform::translate({0, 1, 4}) * Transform::rotate({0, 0, 1}, 55) * Transform::scale({2, 1, 1});
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j) CHECK(half.m[i][j] == Approx(want.m[i][j]).margin(1e-12));
  CHECK(rotationAngle(a, b) == Approx(90 * 3.14159265358979323846 / 180).epsilon(1e-12));
}

TEST_CASE("a moving mesh looks the same through every structure as through brute force",
          "[render][distributed][motion][accel]") {
  // Many triangles of one moving object share packets that meet the ray moved
  // into their object space; a still mesh beside it keeps world-space packets.
  Scene scene = parseScene(R"({
    "camera": {"position": [0, 1, 6], "look_at": [0, 0.5, 0], "fov": 40, "shutter": [0, 1]},
    "film": {"width": 48, "height": 36, "spp": 4},
    "render": {"max_depth": 1},
    "lights": [{"position": [2, 6, 4]}]
  })", "moving_mesh.json");
  for (int k = 0; k < 2; ++k) {
    Object o;
    o.type = ObjectType::Mesh;
    o.mesh = std::make_shared<TriangleMesh>(icosphere(3, 0, 0, 0, 0.8f));
    o.transform = Transform::translate({k == 0 ? -1.2 : 1.2, 0.8, 0});
    o.moving = k == 0;
    o.transform_end = Transform::translate({-0.2, 1.2, -0.5}) * Transform::rotate({1, 1, 0}, 50);
    scene.objects.push_back(o);
  }
  RenderOptions opt = RenderOptions::fromScene(scene);
  opt.accel = AccelKind::None;
  const RenderResult reference = sharedRenderer().render(scene, opt);
  int moving_hits = 0;
  const int per_mesh = static_cast<int>(scene.objects[0].mesh->triangleCount());
  for (std::int32_t id : reference.primid) moving_hits += id >= 0 && id < per_mesh;
  REQUIRE(moving_hits > 50);  // the moving sphere is in view
  checkStructuresMatch(scene, opt, reference);
}
