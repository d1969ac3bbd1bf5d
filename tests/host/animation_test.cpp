// Animations (host/scene/animation.cpp): each frame is an ordinary scene whose
// motion is the piece of the whole animation's path inside its shutter. Checked
// against the whole path itself (scene/motion.h's interpolation, whose ends and
// constant turning rate tests/render/motion_blur_test.cpp checks), the closed
// form of linear motion, and slerp's composition: the kernels' interpolation
// across a frame's shutter must follow the whole path.
#include "scene/animation.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <string>

#include "scene/motion.h"
#include "scene_format/scene_loader.h"
#include "support/scene_errors.h"

using namespace prism;
using namespace prism::test;

namespace {

double maxDifference(const Transform& a, const Transform& b) {
  double d = 0;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j) d = std::max(d, std::fabs(a.m[i][j] - b.m[i][j]));
  return d;
}

// A box that turns 150 degrees about a tilted axis, stretches and travels, and a
// camera that moves, over `frames` frames of `shutter` each, `step` apart.
Scene turningBox(int frames, double step, double shutter) {
  const std::string json = R"({
    "camera": {"position": [0, 1, 8], "look_at": [0, 0, 0], "shutter": [0, )" + std::to_string(shutter) + R"(],
               "position_end": [4, 2, 8], "look_at_end": [1, 0, 0]},
    "animation": {"frames": )" + std::to_string(frames) + R"(, "step": )" + std::to_string(step) + R"(},
    "objects": [{"type": "box", "min": [-1, -1, -1], "max": [1, 1, 1],
                 "transform": {"translate": [-2, 0, 0]},
                 "transform_end": [{"scale": [1, 2, 0.5]}, {"rotate": {"axis": [1, 2, 3], "angle": 150}},
                                   {"translate": [3, 1, -1]}]},
                {"type": "sphere", "center": [0, 0, 0], "radius": 1}]
  })";
  return parseScene(json, "turning_box.json");
}

}  // namespace

TEST_CASE("a scene of one frame is its own only frame", "[host][animation]") {
  const Scene scene = loadSceneFile(std::string(PRISM_SOURCE_DIR) + "/scenes/motion.json");
  REQUIRE(scene.animation.frames == 1);
  const Scene frame = sceneAtFrame(scene, 0);
  CHECK(frame.camera.shutter_open == scene.camera.shutter_open);
  CHECK(frame.camera.shutter_close == scene.camera.shutter_close);
  for (std::size_t i = 0; i < scene.objects.size(); ++i) {
    CHECK(frame.objects[i].moving == scene.objects[i].moving);
    CHECK(maxDifference(frame.objects[i].transform, scene.objects[i].transform) == 0);
    CHECK(maxDifference(frame.objects[i].transform_end, scene.objects[i].transform_end) == 0);
  }
  CHECK_THROWS_WITH(sceneAtFrame(scene, 1), Catch::Contains("frame 1 is not in the animation (frames 0 to 0)"));
}

TEST_CASE("each frame's shutter is the first one moved by frame x step, and its motion is the path's piece inside it",
          "[host][animation]") {
  const int frames = 6;
  const double step = 0.75, shutter = 0.5;
  const Scene scene = turningBox(frames, step, shutter);
  const double span = (frames - 1) * step + shutter;  // first open to last close
  const DecomposedTransform start = decompose(scene.objects[0].transform), end = decompose(scene.objects[0].transform_end);
  for (int f = 0; f < frames; ++f) {
    INFO("frame " << f);
    const Scene frame = sceneAtFrame(scene, f);
    CHECK(frame.animation.frames == 1);
    CHECK(frame.camera.shutter_open == Approx(f * step).margin(1e-15));
    CHECK(frame.camera.shutter_close == Approx(f * step + shutter));
    const Object& box = frame.objects[0];
    REQUIRE(box.moving);
    CHECK_FALSE(frame.objects[1].moving);
    // Across the frame's shutter, the kernels interpolate between its two ends;
    // slerp of a piece of an arc stays on the arc at the same rate, so every
    // instant of the frame meets the whole path at the same time.
    const DecomposedTransform a = decompose(box.transform), b = decompose(box.transform_end);
    for (double u : {0.0, 0.3, 0.7, 1.0}) {
      const double t = f * step + u * shutter;
      const Transform piece = interpolate(a, b, u), whole = interpolate(start, end, t / span);
      CHECK(maxDifference(piece, whole) < 1e-9);
    }
    // The camera moves linearly along the same time.
    const double s_open = f * step / span;
    CHECK(near(frame.camera.position, Vec3{4 * s_open, 1 + s_open, 8}, 1e-12));
    CHECK(near(frame.camera.look_at, Vec3{s_open, 0, 0}, 1e-12));
  }
  // The first frame starts where the path starts and the last ends where it ends.
  CHECK(maxDifference(sceneAtFrame(scene, 0).objects[0].transform, scene.objects[0].transform) < 1e-12);
  CHECK(maxDifference(sceneAtFrame(scene, frames - 1).objects[0].transform_end, scene.objects[0].transform_end) <
        1e-12);
}

TEST_CASE("frames back to back continue one another", "[host][animation]") {
  const Scene scene = turningBox(5, 1.0, 1.0);  // each frame's shutter closes as the next opens
  for (int f = 0; f + 1 < 5; ++f) {
    INFO("frames " << f << " and " << f + 1);
    const Scene a = sceneAtFrame(scene, f), b = sceneAtFrame(scene, f + 1);
    CHECK(maxDifference(a.objects[0].transform_end, b.objects[0].transform) < 1e-12);
    CHECK(near(a.camera.position_end, b.camera.position, 1e-12));
  }
}

TEST_CASE("a frame without a shutter interval holds the objects still at its instant", "[host][animation]") {
  // Translation alone, over 5 frames at instants 0..4: the closed form -2 + t.
  const Scene scene = parseScene(R"({
    "animation": {"frames": 5},
    "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1,
                 "transform": {"translate": [-2, 0, 0]}, "transform_end": {"translate": [2, 0, 0]}},
                {"type": "triangle", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]],
                 "transform": {"translate": [0, 0, 0]},
                 "transform_end": {"rotate": {"axis": [0, 0, 1], "angle": 90}}}]
  })",
                                 "still_frames.json");
  for (int f = 0; f < 5; ++f) {
    INFO("frame " << f);
    const Scene frame = sceneAtFrame(scene, f);
    CHECK(frame.camera.shutter_open == f);
    CHECK_FALSE(frame.camera.hasShutterInterval());
    const Object& sphere = frame.objects[0];
    CHECK_FALSE(sphere.moving);
    CHECK(near(sphere.transform.applyPoint(Vec3{}), Vec3{-2.0 + f, 0, 0}, 1e-12));
    // A kind kept in world space takes the frame's transform into its vertices,
    // as the loader does for a static one: turned by 22.5 degrees a frame.
    const Object& triangle = frame.objects[1];
    CHECK_FALSE(triangle.moving);
    CHECK(triangle.transform.isIdentity());
    const double angle = f * 22.5 * std::acos(-1.0) / 180;
    CHECK(near(triangle.vertices[1], Vec3{std::cos(angle), std::sin(angle), 0}, 1e-12));
  }
}

TEST_CASE("animations the format refuses, and frames whose camera cannot form an image", "[host][animation][scene]") {
  CHECK(contains(errorOf(R"({"animation": {"frames": 0}})"), "animation.frames"));
  CHECK(contains(errorOf(R"({"animation": {"frames": 2.5}})"), "animation.frames"));
  CHECK(contains(errorOf(R"({"animation": {"frames": 3, "step": 0}})"), "animation.step"));
  CHECK(contains(errorOf(R"({"animation": {"frames": 3, "step": -1}})"), "animation.step"));
  const Scene unknown = parseScene(R"({"animation": {"frames": 3, "speed": 2}})", "unknown.json");
  REQUIRE(unknown.warnings.size() == 1);
  CHECK(contains(unknown.warnings[0], "speed"));
  CHECK(contains(errorOf(R"({"animation": {"frames": 1000000, "step": 1e10}})"), "the last frame's shutter"));
  CHECK(contains(errorOf(R"({"animation": 3})"), "animation"));
  // The camera passes through the point it looks at half-way (frame 2 of 5).
  const Scene scene = parseScene(R"({
    "camera": {"position": [0, 0, 5], "look_at": [0, 0, 0], "position_end": [0, 0, -5], "look_at_end": [0, 0, 0]},
    "animation": {"frames": 5}
  })",
                                 "through.json");
  CHECK_NOTHROW(sceneAtFrame(scene, 1));
  CHECK_THROWS_WITH(sceneAtFrame(scene, 2), Catch::Contains("frame 2 of the animation: the camera's position and look_at"));
  CHECK_THROWS_WITH(sceneAtFrame(scene, 4294967295u), Catch::Contains("frame 4294967295 is not in the animation"));
  // A mirror image by the end: the stretch passes through 0 at the middle frame.
  const Scene flip = parseScene(R"({
    "animation": {"frames": 3},
    "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1,
                 "transform": {"scale": 1}, "transform_end": {"scale": [-1, 1, 1]}}]
  })",
                                "flip.json");
  CHECK_NOTHROW(sceneAtFrame(flip, 0));
  CHECK_THROWS_WITH(sceneAtFrame(flip, 1), Catch::Contains("frame 1 of the animation: objects[0]: its transform there"));
}
