// The scene format's keys for distributed ray tracing (host/scene_format/scene_loader.cpp):
// area lights (quad/rect, disk, sphere) and their samples, the lens (aperture,
// focus_distance), the shutter and the moving camera, and the gloss and
// translucency exponents. Good values reach the scene model; each bad one is
// refused with a message naming the file, the JSON path and the reason.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>
#include <vector>

#include "scene/light_check.h"
#include "scene/scene.h"
#include "scene_format/scene_loader.h"
#include "support/scene_errors.h"

using namespace prism;
using namespace prism::test;

namespace {

std::string light(const std::string& body) { return R"({"lights": [{"position": [0, 5, 0]}, )" + body + "]}"; }
std::string camera(const std::string& body) {
  return R"({"camera": {"position": [0, 0, 5], "look_at": [0, 0, 0])" + body + "}}";
}
std::string material(const std::string& body) { return R"({"materials": {"m": {)" + body + "}}}"; }

}  // namespace

TEST_CASE("area lights, lens, shutter and lobe keys reach the scene model", "[scene][distributed]") {
  const Scene s = parseScene(R"({
    "camera": {"position": [0, 1, 5], "look_at": [0, 0, 0], "aperture": 0.25, "focus_distance": 4.5,
               "shutter": [0.5, 1.5], "position_end": [1, 1, 5], "look_at_end": [0.5, 0, 0]},
    "materials": {"g": {"reflect": 0.5, "gloss": 120}, "t": {"transmit": 0.8, "translucency": 30.5}},
    "lights": [
      {"type": "quad", "corner": [-1, 3, -1], "edge1": [2, 0, 0], "edge2": [0, 0, 1], "color": [1, 0.5, 0.25],
       "intensity": 2, "samples": 16},
      {"type": "rect", "corner": [0, 3, 0], "edge1": [1, 0, 0], "edge2": [0, 0, 1]},
      {"type": "disk", "center": [1, 2, 3], "normal": [0, -2, 0], "radius": 0.5, "samples": 4},
      {"type": "sphere", "center": [-1, 2, 0], "radius": 0.25, "samples": 9},
      {"position": [0, 10, 0]}
    ]
  })",
                             "good.json");
  CHECK(s.warnings.empty());
  CHECK(s.camera.aperture == 0.25);
  CHECK(s.camera.focus_distance == 4.5);
  CHECK(s.camera.shutter_open == 0.5);
  CHECK(s.camera.shutter_close == 1.5);
  CHECK(s.camera.moving);
  CHECK(near(s.camera.position_end, {1, 1, 5}));
  CHECK(near(s.camera.look_at_end, {0.5, 0, 0}));
  CHECK_FALSE(s.camera.isPinhole());
  REQUIRE(s.materials.size() == 3);
  CHECK(s.materials[1].gloss == 120);
  CHECK(s.materials[2].translucency == 30.5);
  REQUIRE(s.lights.size() == 5);
  CHECK(s.lights[0].type == LightType::Quad);
  CHECK(near(s.lights[0].corner, {-1, 3, -1}));
  CHECK(near(s.lights[0].edge1, {2, 0, 0}));
  CHECK(near(s.lights[0].edge2, {0, 0, 1}));
  CHECK(near(s.lights[0].color, {1, 0.5, 0.25}));
  CHECK(s.lights[0].intensity == 2);
  CHECK(s.lights[0].samples == 16);
  CHECK(s.lights[1].type == LightType::Quad);  // rect is a quad
  CHECK(s.lights[1].samples == 1);             // default
  CHECK(s.lights[2].type == LightType::Disk);
  CHECK(near(s.lights[2].normal, {0, -1, 0}));  // normalised
  CHECK(s.lights[2].radius == 0.5);
  CHECK(s.lights[3].type == LightType::Sphere);
  CHECK(near(s.lights[3].center, {-1, 2, 0}));
  CHECK(s.lights[3].samples == 9);
  CHECK(s.lights[4].type == LightType::Point);

  // Only one of position_end / look_at_end: the other stays where it was.
  const Scene half = parseScene(camera(R"(, "shutter": [0, 1], "position_end": [1, 0, 5])"), "half.json");
  CHECK(half.camera.moving);
  CHECK(near(half.camera.look_at_end, {0, 0, 0}));
  // A pinhole by default.
  CHECK(parseScene("{}", "empty.json").camera.isPinhole());
}

TEST_CASE("bad distributed keys are refused with the JSON path and the reason", "[scene][distributed]") {
  struct Bad {
    std::string json;
    std::vector<std::string> parts;
  };
  const std::string max_samples = std::to_string(kMaxLightSamples);
  const std::vector<Bad> cases = {
      // light type
      {light(R"({"type": "tube", "center": [0, 0, 0]})"),
       {"bad.json: ", "lights[1].type", "unknown light type 'tube'", "point, quad, rect, disk, sphere"}},
      {light(R"({"type": 3})"), {"lights[1].type", "expected a string", "got 3"}},
      // quad
      {light(R"({"type": "quad", "corner": [0, 3, 0], "edge1": [1, 0, 0], "edge2": [2, 0, 0]})"),
       {"lights[1]: ", "edge1 and edge2", "not parallel"}},
      {light(R"({"type": "quad", "corner": [0, 3, 0], "edge1": [0, 0, 0], "edge2": [1, 0, 0]})"),
       {"lights[1].edge1", "a non-zero vector", "got [0, 0, 0]"}},
      {light(R"({"type": "quad", "corner": [0, 3, 0], "edge1": [1, 0, 0]})"),
       {"lights[1]: missing required key 'edge2'"}},
      {light(R"({"type": "quad", "edge1": [1, 0, 0], "edge2": [0, 0, 1]})"),
       {"lights[1]: missing required key 'corner'"}},
      // disk and sphere
      {light(R"({"type": "disk", "center": [0, 3, 0], "normal": [0, 0, 0], "radius": 1})"),
       {"lights[1].normal", "a non-zero vector"}},
      {light(R"({"type": "disk", "center": [0, 3, 0], "normal": [0, -1, 0], "radius": 0})"),
       {"lights[1].radius", "a positive number", "got 0"}},
      {light(R"({"type": "sphere", "center": [0, 3, 0], "radius": -1})"),
       {"lights[1].radius", "a positive number", "got -1"}},
      {light(R"({"type": "sphere", "radius": 1})"), {"lights[1]: missing required key 'center'"}},
      // samples
      {light(R"({"type": "sphere", "center": [0, 3, 0], "radius": 1, "samples": 0})"),
       {"lights[1].samples", "an integer in [1, " + max_samples + "]", "got 0"}},
      {light(R"({"type": "sphere", "center": [0, 3, 0], "radius": 1, "samples": 2.5})"),
       {"lights[1].samples", "an integer", "got 2.5"}},
      {light(R"({"type": "quad", "corner": [0, 3, 0], "edge1": [1, 0, 0], "edge2": [0, 0, 1], "samples": )" +
             std::to_string(kMaxLightSamples + 1) + "}"),
       {"lights[1].samples", "got " + std::to_string(kMaxLightSamples + 1)}},
      // lens
      {camera(R"(, "aperture": -0.5)"), {"camera.aperture", "a lens radius >= 0", "got -0.5"}},
      {camera(R"(, "aperture": "wide")"), {"camera.aperture", "got \"wide\""}},
      {camera(R"(, "focus_distance": 0)"), {"camera.focus_distance", "a positive distance", "got 0"}},
      {camera(R"(, "focus_distance": -3)"), {"camera.focus_distance", "got -3"}},
      // shutter and motion
      {camera(R"(, "shutter": [1, 0.5])"), {"camera: ", "shutter", "close no earlier than it opens"}},
      {camera(R"(, "shutter": [0, 1, 2])"), {"camera.shutter", "an array [open, close] of 2 numbers"}},
      {camera(R"(, "shutter": [0, "late"])"), {"camera.shutter[1]", "got \"late\""}},
      {camera(R"(, "shutter": [0, 1], "position_end": [1, 1, 1], "look_at_end": [1, 1, 1])"),
       {"camera: ", "position_end and look_at_end are the same"}},
      {camera(R"(, "position_end": [0, 1])"), {"camera.position_end", "an array of 3 numbers"}},
      // lobes
      {material(R"("gloss": -1)"), {"materials.m.gloss", "[0, 1e6]", "got -1"}},
      {material(R"("gloss": 2e6)"), {"materials.m.gloss", "[0, 1e6]", "got 2000000"}},
      {material(R"("translucency": -0.5)"), {"materials.m.translucency", "[0, 1e6]", "got -0.5"}},
      {material(R"("translucency": "frosted")"), {"materials.m.translucency", "got \"frosted\""}},
  };
  for (const Bad& c : cases) {
    const std::string message = errorOf(c.json);
    INFO(c.json << "\n  -> " << message);
    CHECK_FALSE(message.empty());
    CHECK(contains(message, "bad.json: "));
    for (const std::string& part : c.parts) CHECK(contains(message, part));
  }
}

TEST_CASE("samples on a point light and unknown keys on area lights are warned about, not fatal",
          "[scene][distributed]") {
  const Scene s = parseScene(
      R"({"lights": [{"position": [0, 5, 0], "samples": 8},
                     {"type": "disk", "center": [0, 3, 0], "normal": [0, -1, 0], "radius": 1, "edge1": [1, 0, 0]}]})",
      "warn.json");
  REQUIRE(s.warnings.size() == 2);
  CHECK(contains(s.warnings[0], "lights[0]"));
  CHECK(contains(s.warnings[0], "'samples'"));
  CHECK(contains(s.warnings[1], "lights[1]"));
  CHECK(contains(s.warnings[1], "'edge1'"));
}
