// Scenes at the edges of what the scene format accepts render to finite
// pixels: every rgba value and every normal and albedo AOV finite (depth is
// +inf on a miss by contract). Each was a NaN, an inf or a crash before its
// guard: refraction through an ior of 1e300 or 1e-300 (NaN directions, which
// once overran the BVH's stack), spheres of radius 1e15 and 1e-15, objects at
// 1e15, a camera inside glass, a light on a surface, a squashed transform,
// 31 bounces in a closed mirror box, and every colour at its bound of 1e6
// under a light of 1e24.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <string>

#include "kernels/shared/ray_gpu.h"
#include "render/renderer.h"
#include "scene_format/scene_loader.h"
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

// The pixels of r that are not finite, counted here.
std::size_t notFinitePixels(const RenderResult& r) {
  std::size_t n = 0;
  for (std::size_t p = 0; 4 * p < r.rgba.size(); ++p)
    n += !std::all_of(&r.rgba[4 * p], &r.rgba[4 * p + 4], [](float x) { return std::isfinite(x); });
  return n;
}

// The render's warning about pixels that are not finite, or "" if none.
std::string notFiniteWarning(const RenderResult& r) {
  for (const std::string& w : r.stats.warnings)
    if (w.find("not finite") != std::string::npos) return w;
  return "";
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
    CHECK(notFiniteWarning(r) == "");
    std::size_t hits = 0;
    for (std::int32_t id : r.primid) hits += id >= 0;
    CHECK(hits > 0);  // the camera sees something in every case
  }
}

// --check-nan's detector, against the image it watched: a light of NaN
// intensity (which the loader refuses, so it is set after loading) poisons
// every lit primary hit. The finding must be the first sample, in the image's
// own order, whose pixel is not finite, its ray the camera's ray through that
// sample (from the camera's position, unit length, meeting the unit sphere at
// the reported t) and its primitive the one the primid AOV shows there.
TEST_CASE("check_nan names the first sample whose light is not finite, and the ray that brought it",
          "[render][reliability]") {
  Scene s = parseScene(scene(R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "matte"})",
                             R"("matte": {"diffuse": 0.8})", "", "",
                             R"({"max_depth": 0, "min_weight": 0, "aa": "none"})"),
                       "nan.json");
  RenderOptions options = RenderOptions::fromScene(s);
  options.check_nan = true;
  const RenderResult clean = test::sharedRenderer().render(s, options);
  CHECK_FALSE(clean.stats.nan.has_value());
  CHECK(notFiniteWarning(clean) == "");

  s.lights[0].intensity = std::nan("");
  const RenderResult r = test::sharedRenderer().render(s, options);
  std::size_t first = r.rgba.size();
  for (std::size_t p = 0; 4 * p < r.rgba.size() && first == r.rgba.size(); ++p)
    for (int c = 0; c < 4; ++c)
      if (!std::isfinite(r.rgba[4 * p + c])) first = p;
  REQUIRE(first < r.rgba.size());
  REQUIRE(r.stats.nan.has_value());
  const NanFinding& f = *r.stats.nan;
  CHECK(f.sample == first);
  CHECK(f.ray_kind == RAY_KIND_PRIMARY);
  CHECK(f.depth == 0);
  CHECK(static_cast<std::size_t>(f.film_x) == first % r.width);
  CHECK(static_cast<std::size_t>(f.film_y) == first / r.width);
  CHECK(f.prim == r.primid[first]);
  CHECK(f.prim == 0);
  CHECK(f.origin[0] == 0.0f);
  CHECK(f.origin[1] == 1.0f);
  CHECK(f.origin[2] == 6.0f);
  const double dx = f.direction[0], dy = f.direction[1], dz = f.direction[2];
  CHECK(std::abs(std::sqrt(dx * dx + dy * dy + dz * dz) - 1.0) < 1e-6);
  const double hx = 0 + f.t * dx, hy = 1 + f.t * dy, hz = 6 + f.t * dz;
  CHECK(std::abs(std::sqrt(hx * hx + hy * hy + hz * hz) - 1.0) < 1e-5);
  const bool value_finite = std::isfinite(f.value[0]) && std::isfinite(f.value[1]) && std::isfinite(f.value[2]);
  CHECK_FALSE(value_finite);
  // Without check_nan too, the render warns, counting the pixels the image holds.
  options.check_nan = false;
  const RenderResult plain = test::sharedRenderer().render(s, options);
  CHECK_THAT(notFiniteWarning(plain), Catch::StartsWith(std::to_string(notFinitePixels(plain)) + " of the colour image's " +
                                                        std::to_string(plain.width * plain.height) + " pixels are not finite") &&
                                          Catch::EndsWith("names the first ray that brought one"));
  CHECK(notFinitePixels(plain) > 0);
  // With check_nan on, the warning does not send the user to it.
  CHECK_THAT(notFiniteWarning(r), Catch::StartsWith(std::to_string(notFinitePixels(r)) + " of the colour image's") &&
                                      !Catch::Contains("check_nan"));
}

// Every value within its own bound, but together past float: a diffuse colour
// of 1e6 on a checker of 1e6 under a light of 1e30 gives 1e42 at every lit
// point. The image is not silently handed back: the render warns, with the
// count of pixels that are not finite.
TEST_CASE("a render whose bright values together pass float's range warns with the count of such pixels",
          "[render][reliability]") {
  const Scene s = parseScene(
      scene(sphere("[0, 0, 0]", "1", "hot"),
            R"("hot": {"diffuse": 1e6, "texture": {"type": "checker", "color1": 1e6, "color2": 1e6}})",
            R"({"position": [0, 1, 6], "intensity": 1e30})", "", R"({"max_depth": 0})"),
      "bright.json");
  for (const char* aa : {"none", "adaptive"}) {
    INFO("aa " << aa);
    RenderOptions options = RenderOptions::fromScene(s);
    options.aa = std::string(aa) == "none" ? AaMode::None : AaMode::Adaptive;
    const RenderResult r = test::sharedRenderer().render(s, options);
    const std::size_t bad = notFinitePixels(r);
    CHECK(bad > 0);
    CHECK_THAT(notFiniteWarning(r), Catch::StartsWith(std::to_string(bad) + " of the colour image's " +
                                                      std::to_string(r.width * r.height) + " pixels are not finite"));
  }
}
