// The boxes the structures keep for moving primitives: the swept box holds the
// object at every instant of its motion, and the linear bounds (BVH motion
// nodes) hold it at every instant when interpolated to it. The oracle is the
// object itself: points of its surface, moved by the double-precision motion
// (scene/motion.h) from the scene's own transforms.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>

#include "accel/prim_ref.h"
#include "kernels/shared/motion_gpu.h"
#include "render/gpu_scene.h"
#include "scene/motion.h"
#include "scene_format/scene_loader.h"

using namespace prism;

namespace {

const char* kMovingScene = R"({
  "camera": {"shutter": [0, 2]},
  "objects": [
    {"type": "sphere", "center": [0.5, 0, 0], "radius": 0.7,
     "transform": [{"scale": [2, 1, 1]}, {"translate": [1, 2, 3]}],
     "transform_end": [{"rotate": {"axis": [1, 2, 3], "angle": 170}}, {"scale": 0.5}, {"translate": [-3, 1, 0]}]},
    {"type": "box", "min": [-1, -0.5, -0.2], "max": [1, 0.5, 0.2],
     "transform_end": [{"rotate": {"axis": [0, 1, 0], "angle": 90}}, {"translate": [0, 4, 0]}]},
    {"type": "triangle", "vertices": [[0, 0, 0], [3, 0, 0], [0, 1, 0]],
     "transform": {"rotate": {"axis": [0, 0, 1], "angle": -60}},
     "transform_end": [{"rotate": {"axis": [0, 0, 1], "angle": 60}}, {"translate": [1, 0, 0]}]},
    {"type": "sphere", "center": [0, 0, 0], "radius": 0.5,
     "transform": [{"scale": [1, 3, 1]}, {"rotate": {"axis": [1, 0, 0], "angle": 30}}],
     "transform_end": [{"scale": [1, 3, 1]}, {"rotate": {"axis": [1, 0, 0], "angle": 30}}, {"translate": [5, -2, 1]}]}
  ]
})";

// Points of object `ob` (scene model, object space).
std::vector<Vec3> surfacePoints(const Object& ob, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0, 1);
  std::vector<Vec3> points;
  for (int i = 0; i < 400; ++i) {
    const double a = u(rng), b = u(rng);
    switch (ob.type) {
      case ObjectType::Sphere: {
        const double z = 2 * a - 1, r = std::sqrt(1 - z * z), phi = 2 * M_PI * b;
        points.push_back(ob.center + Vec3{r * std::cos(phi), r * std::sin(phi), z} * ob.radius);
        break;
      }
      case ObjectType::Box:
        points.push_back({i & 1 ? ob.box_max.x : ob.box_min.x, ob.box_min.y + a * (ob.box_max.y - ob.box_min.y),
                          ob.box_min.z + b * (ob.box_max.z - ob.box_min.z)});
        break;
      default: {
        const double s = std::sqrt(a);
        points.push_back(ob.vertices[0] * (1 - s) + ob.vertices[1] * (s * (1 - b)) + ob.vertices[2] * (s * b));
        break;
      }
    }
  }
  return points;
}

bool inside(const Aabb& box, const Vec3& p) {
  return p.x >= box.lo[0] && p.x <= box.hi[0] && p.y >= box.lo[1] && p.y <= box.hi[1] && p.z >= box.lo[2] &&
         p.z <= box.hi[2];
}

}  // namespace

TEST_CASE("moving primitives' swept and linear bounds hold them at every instant", "[accel][motion]") {
  const Scene scene = parseScene(kMovingScene, "moving.json");
  RenderOptions options = RenderOptions::fromScene(scene);
  const GpuScene gpu = flattenScene(scene, options);
  REQUIRE(gpu.primitive_count == scene.objects.size());
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> uniform(0, 1);
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    const Object& ob = scene.objects[i];
    INFO("object " << i);
    REQUIRE(gpu.objects[i].has_transform == OBJECT_MOVING);
    Aabb swept, open, close;
    REQUIRE(objectBounds(gpu.objects[i], &swept));
    REQUIRE(objectLinearBounds(gpu.objects[i], &open, &close));
    const DecomposedTransform a = decompose(ob.transform), b = decompose(ob.transform_end);
    const std::vector<Vec3> points = surfacePoints(ob, rng);
    for (int k = 0; k < 300; ++k) {
      const double s = k < 2 ? k : uniform(rng);
      const Transform t = interpolate(a, b, s);
      Aabb at;
      for (int axis = 0; axis < 3; ++axis) {
        at.lo[axis] = static_cast<float>(open.lo[axis] + s * (double(close.lo[axis]) - open.lo[axis]));
        at.hi[axis] = static_cast<float>(open.hi[axis] + s * (double(close.hi[axis]) - open.hi[axis]));
      }
      for (const Vec3& p : points) {
        const Vec3 w = t.applyPoint(p);
        INFO("s " << s << " point " << w.x << " " << w.y << " " << w.z);
        REQUIRE(inside(swept, w));
        REQUIRE(inside(at, w));
      }
    }
    // A translation keeps its linear part constant (the kernels' short path).
    const MotionGpu& motion = *reinterpret_cast<const MotionGpu*>(&gpu.objects[i] + (gpu.objects[i].flags >> OBJECT_MOTION_SHIFT));
    CHECK((motion.kind == MOTION_TRANSLATE) == (i == 3));
    // Not vacuous: the linear bounds are tighter than the swept box at the ends.
    CHECK(open.area() < swept.area());
    CHECK(close.area() < swept.area());
  }
}
