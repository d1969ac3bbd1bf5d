// Scenes at the edges of what the scene format accepts render to finite
// pixels: every rgba value and every normal and albedo AOV finite (depth is
// +inf on a miss by contract). Each was a NaN, an inf or a crash before its
// guard: refraction through an ior of 1e300 or 1e-300 (NaN directions, which
// once overran the BVH's stack), spheres of radius 1e15 and 1e-15, objects at
// 1e15, a camera inside glass, a light on a surface, a squashed transform,
// 31 bounces in a closed mirror box, and every colour at its bound of 1e6
// under a light of 1e24.
#include <catch2/catch.hpp>

#include <cmath>
#include <string>

#include "render/renderer.h"
#include "scene/scene_loader.h"
#include "support/shared_context.h"

using namespace prism;

namespace {

std::string scene(const std::string& objects, const std::string& materials = "", const std::string& lights = "",
                  const std::string& camera = "", const std::string& render = "") {
  const std::string m = materials.empty()
                            ? R"("glass": {"transmit": 0.9, "reflect": 0.1, "ior": 1.5, "specular": 1, "shininess": 1e6},
                                 "mirror": {"reflect": 1, "diffuse": 0, "specular": 1e6, "shininess": 0})"
                            : materials;
  return R"({"camera": )" + (camera.empty() ? R"({"position": [0, 1, 6], "look_at": [0, 0, 0], "fov": 40})" : camera) +
         R"(, "film": {"width": 32, "height": 24}, "render": )" +
         (render.empty() ? R"({"max_depth": 6, "min_weight": 0})" : render) + R"(, "materials": {)" + m +
         R"(}, "lights": [)" + (lights.empty() ? R"({"position": [2, 4, 5], "intensity": 1e24})" : lights) +
         R"(], "objects": [)" + objects + "]}";
}

std::string sphere(const std::string& center, const std::string& radius, const char* material = "glass") {
  return R"({"type": "sphere", "center": )" + center + R"(, "radius": )" + radius + R"(, "material": ")" + material +
         R"("})";
}

}  // namespace

TEST_CASE("scenes at the edges of the format render to finite pixels", "[render][reliability]") {
  const std::pair<const char*, std::string> cases[] = {
      {"ior 1e300", scene(sphere("[0, 0, 0]", "1"), R"("glass": {"transmit": 1, "ior": 1e300})")},
      {"ior 1e-300", scene(sphere("[0, 0, 0]", "1"), R"("glass": {"transmit": 1, "ior": 1e-300})")},
      {"huge sphere", scene(sphere("[0, 0, 0]", "1e15") + ", " + sphere("[0, 0, 0]", "1"))},
      {"tiny spheres", scene(sphere("[0, 0, 0]", "1e-15") + ", " + sphere("[0, 0, 0.5]", "1e-30") + ", " +
                             sphere("[1.5, 0, 0]", "0.5", "mirror"))},
      {"far objects", scene(sphere("[1e15, 0, 0]", "1") + ", " + sphere("[0, 0, -1e15]", "1e14"))},
      {"camera inside glass", scene(sphere("[0, 1, 6]", "2"), "", "", R"({"position": [0, 1, 6], "look_at": [0, 0, 0]})")},
      {"light on a surface",
       scene(sphere("[0, 0, 0]", "1"), "", R"({"position": [0, 1, 0], "intensity": 1e24}, {"position": [0, 0, 0]})")},
      {"squashed sphere",
       scene(R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "glass",
                 "transform": {"scale": [1e7, 1e-7, 1]}})")},
      {"mirror box, 31 bounces",
       scene(R"({"type": "box", "min": [-3, -3, -3], "max": [3, 3, 3], "material": "mirror"}, )" +
                 sphere("[0, 0, 0]", "1"),
             "", "", R"({"position": [0, 0, 2.5], "look_at": [0, 0, 0]})", R"({"max_depth": 31, "min_weight": 0})")},
      {"every colour at 1e6",
       scene(sphere("[0, 0, 0]", "1", "mirror"),
             R"("mirror": {"ambient": 1e6, "diffuse": 1e6, "specular": 1e6, "reflect": 1})", "", "",
             R"({"ambient": 1e6, "background": 1e6, "max_depth": 31, "min_weight": 0})")},
  };
  for (const auto& [name, json] : cases) {
    INFO(name);
    const Scene s = parseScene(json, "extreme.json");
    const RenderResult r = test::sharedRenderer().render(s, RenderOptions::fromScene(s));
    std::size_t bad = 0;
    for (float x : r.rgba) bad += !std::isfinite(x);
    for (float x : r.normal) bad += !std::isfinite(x);
    for (float x : r.albedo) bad += !std::isfinite(x);
    CHECK(bad == 0);
    std::size_t hits = 0;
    for (std::int32_t id : r.primid) hits += id >= 0;
    CHECK(hits > 0);  // the camera sees something in every case
  }
}
