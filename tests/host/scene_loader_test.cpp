// Tests for the JSON scene loader (host/scene_format/scene_loader.cpp) and the affine
// transform arithmetic it relies on (host/scene/transform.cpp). Expected messages
// are the ones documented in docs/scene-format.md.
#include "scene_format/scene_loader.h"

#include <catch2/catch.hpp>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "scene/scene.h"
#include "scene/transform.h"
#include "support/scene_errors.h"

using namespace prism;
using namespace prism::test;

namespace {

const std::string kScenes = std::string(PRISM_SOURCE_DIR) + "/scenes/";

bool nearIdentity(const Transform& t, double eps) {
  const Transform id;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 4; ++j)
      if (std::fabs(t.m[i][j] - id.m[i][j]) > eps) return false;
  return true;
}

std::string sphere(const std::string& extra) {
  return R"({"objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1)" + extra + "}]}";
}

}  // namespace

TEST_CASE("the Whitted example scene loads as described", "[scene]") {
  const Scene s = loadSceneFile(kScenes + "whitted.json");
  CHECK(s.warnings.empty());
  CHECK(s.source == kScenes + "whitted.json");
  CHECK(s.film.width == 640);
  CHECK(s.film.height == 360);
  CHECK(s.render.max_depth == 8);
  REQUIRE(s.lights.size() == 2);
  REQUIRE(s.objects.size() == 3);
  REQUIRE(s.materials.size() == 4);
  CHECK(s.materials[0].name == "default");

  const Object& plane = s.objects[0];
  CHECK(plane.type == ObjectType::Plane);
  CHECK(length(plane.normal) == Approx(1));
  CHECK(s.materials[plane.material].texture.kind == Texture::Kind::Checker);

  int mirrors = 0, glasses = 0;
  for (const Object& o : s.objects) {
    if (o.type != ObjectType::Sphere) continue;
    const Material& m = s.materials[o.material];
    if (m.reflect >= 0.7 && m.transmit == 0) ++mirrors;
    if (m.transmit >= 0.8 && m.ior == Approx(1.5) && m.reflect > 0) ++glasses;
    CHECK(o.center.y - o.radius >= -1e-9);  // resting on or above the plane
  }
  CHECK(mirrors == 1);
  CHECK(glasses == 1);
  // Looking down at the spheres, with the horizon inside the frame.
  const Vec3 view = normalize(s.camera.look_at - s.camera.position);
  const double down = std::asin(-view.y) * 180 / 3.14159265358979323846;
  CHECK(down > 0);
  CHECK(down < s.camera.fov / 2);
}

TEST_CASE("the Cornell example scene loads as described", "[scene]") {
  const Scene s = loadSceneFile(kScenes + "cornell.json");
  CHECK(s.warnings.empty());
  CHECK(s.film.width == 512);
  CHECK(s.film.height == 512);
  int boxes = 0, planes = 0, spheres = 0;
  for (const Object& o : s.objects) {
    boxes += o.type == ObjectType::Box;
    planes += o.type == ObjectType::Plane;
    spheres += o.type == ObjectType::Sphere;
  }
  CHECK(boxes >= 4);
  CHECK(planes >= 1);
  CHECK(spheres == 2);
  REQUIRE_FALSE(s.lights.empty());
  CHECK(s.lights.size() <= 2);
  for (const Light& l : s.lights) {  // inside the box, near the ceiling
    CHECK(std::fabs(l.position.x) < 1);
    CHECK(l.position.y > 1.5);
    CHECK(l.position.y < 2);
    CHECK(std::fabs(l.position.z) < 1);
  }
}

TEST_CASE("an empty scene takes every documented default", "[scene]") {
  const Scene s = parseScene("{}", "empty.json");
  CHECK(s.source == "empty.json");
  CHECK(s.warnings.empty());
  CHECK(s.camera.position == Vec3(0, 0, 5));
  CHECK(s.camera.look_at == Vec3(0, 0, 0));
  CHECK(s.camera.up == Vec3(0, 1, 0));
  CHECK(s.camera.fov == 45);
  CHECK(s.film.width == 640);
  CHECK(s.film.height == 480);
  CHECK(s.film.spp == 1);
  CHECK(s.render.max_depth == 5);
  CHECK(s.render.min_weight == 0.01);
  CHECK(s.render.ambient == Vec3::splat(0.1));
  CHECK(s.render.background == Vec3());
  CHECK(s.render.seed == 0);
  CHECK(s.render.accel == "auto");
  REQUIRE(s.materials.size() == 1);
  CHECK(s.lights.empty());
  CHECK(s.objects.empty());

  const Material& d = s.materials[0];
  CHECK(d.name == "default");
  CHECK(d.model == ShadingModel::Phong);
  CHECK(d.ambient == Vec3::splat(1));
  CHECK(d.diffuse == Vec3::splat(0.8));
  CHECK(d.specular == Vec3());
  CHECK(d.reflect == 0);
  CHECK(d.transmit == 0);
  CHECK(d.ior == 1);
  CHECK(d.texture.kind == Texture::Kind::None);
}

TEST_CASE("many materials keep their file order, a repeated name its first place and last value", "[scene]") {
  // 3000 materials named so that sorted order differs from file order, one
  // repeated, a key named like a material inside another object, and objects
  // naming materials from both ends.
  std::string materials, objects;
  const int n = 3000;
  for (int i = 0; i < n; ++i) {
    const std::string name = "m" + std::to_string((i * 7919) % n);
    materials += (i ? ", \"" : "\"") + name + "\": {\"diffuse\": " + std::to_string(i % 10 / 10.0) + "}";
  }
  materials += ", \"m0\": {\"diffuse\": 0.25}";  // "m0" came first in the file; this value wins
  for (int i : {0, 1, n - 1})
    objects += std::string(objects.empty() ? "" : ", ") + R"({"type": "sphere", "center": [0, 0, 0], "radius": 1,
        "material": "m)" + std::to_string((i * 7919) % n) + "\"}";
  const Scene s = parseScene("{\"camera\": {\"m5\": 1}, \"materials\": {" + materials + "}, \"objects\": [" +
                                 objects + "]}",
                             "many.json");
  REQUIRE(s.materials.size() == static_cast<std::size_t>(n) + 1);
  for (int i = 0; i < n; ++i) CHECK(s.materials[i + 1].name == "m" + std::to_string((i * 7919) % n));
  CHECK(s.materials[1].diffuse == Vec3::splat(0.25));
  CHECK(s.materials[2].diffuse == Vec3::splat(0.1));
  REQUIRE(s.objects.size() == 3);
  CHECK(s.objects[0].material == 1);
  CHECK(s.objects[1].material == 2);
  CHECK(s.objects[2].material == n);
  // An unknown name lists the first 20 and counts the rest.
  CHECK_THROWS_WITH(parseScene("{\"materials\": {" + materials + R"(}, "objects": [{"type": "sphere",
                        "center": [0, 0, 0], "radius": 1, "material": "nope"}]})",
                               "many.json"),
                    Catch::Contains("unknown material 'nope'") && Catch::Contains("and 2981 more"));
}

TEST_CASE("materials, lights and objects fill in their defaults", "[scene]") {
  const Scene s = parseScene(R"({
    "materials": {"zeta": {}, "alpha": {"diffuse": 0.5, "texture": {"type": "checker"}}},
    "lights": [{"position": [1, 2, 3]}],
    "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 2}]
  })",
                             "d.json");
  REQUIRE(s.materials.size() == 3);
  CHECK(s.materials[1].name == "zeta");  // file order, not sorted
  CHECK(s.materials[2].name == "alpha");
  CHECK(s.materials[1].diffuse == Vec3::splat(0.8));
  CHECK(s.materials[1].shininess == 32);
  CHECK(s.materials[2].diffuse == Vec3::splat(0.5));  // one number is a grey
  CHECK(s.materials[2].texture.kind == Texture::Kind::Checker);
  CHECK(s.materials[2].texture.scale == 1);
  REQUIRE(s.lights.size() == 1);
  CHECK(s.lights[0].position == Vec3(1, 2, 3));
  CHECK(s.lights[0].color == Vec3::splat(1));
  CHECK(s.lights[0].intensity == 1);
  REQUIRE(s.objects.size() == 1);
  CHECK(s.objects[0].material == 0);
  CHECK(s.objects[0].transform.isIdentity());
  CHECK(s.objects[0].radius == 2);
}

TEST_CASE("Cook-Torrance materials take a roughness, a distribution and a plastic's index", "[scene]") {
  const Scene s = parseScene(R"({"materials": {
    "plastic": {"model": "cook-torrance"},
    "metal": {"model": "cook-torrance", "roughness": 0.1, "distribution": "ggx", "ior": 3}}})",
                             "ct.json");
  REQUIRE(s.materials.size() == 3);
  CHECK(s.materials[1].model == ShadingModel::CookTorrance);
  CHECK(s.materials[1].roughness == 0.3);
  CHECK(s.materials[1].distribution == MicrofacetDistribution::Beckmann);
  CHECK(s.materials[1].ior == 1.5);  // the Fresnel factor needs an index; Phong's default 1 reflects nothing
  CHECK(s.materials[2].roughness == 0.1);
  CHECK(s.materials[2].distribution == MicrofacetDistribution::Ggx);
  CHECK(s.materials[2].ior == 3);
}

TEST_CASE("a material named default replaces the built-in one", "[scene]") {
  const Scene s = parseScene(
      R"({"materials": {"red": {"diffuse": [1, 0, 0]}, "default": {"diffuse": [0, 0, 1]}},
          "objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": "default"}]})",
      "d.json");
  REQUIRE(s.materials.size() == 2);
  CHECK(s.materials[0].name == "default");
  CHECK(s.materials[0].diffuse == Vec3(0, 0, 1));
  CHECK(s.materials[1].name == "red");
  CHECK(s.objects[0].material == 0);
}

TEST_CASE("scene files may carry comments", "[scene]") {
  const Scene s = parseScene("// a comment\n{ /* inline */ \"film\": {\"width\": 8} }", "c.json");
  CHECK(s.film.width == 8);
}

TEST_CASE("errors give the file, the JSON path and what was expected", "[scene][errors]") {
  const std::string materials = R"("materials": {"glass": {}, "mirror": {}})";
  SECTION("exact shapes from the documentation") {
    CHECK(errorOf(R"({"objects": [{"type": "sphere", "center": [0, 0, 0], "radius": -1}]})") ==
          "bad.json: objects[0].radius: expected a positive number, got -1");
    CHECK(errorOf(R"({"objects": [{"type": "sphere", "radius": 1}]})") ==
          "bad.json: objects[0]: missing required key 'center'");
    CHECK(errorOf("{" + materials + R"(, "objects": [{"type": "sphere", "center": [0,0,0], "radius": 1,
                   "material": "glas"}]})") ==
          "bad.json: objects[0].material: unknown material 'glas' (known: default, glass, mirror)");
    CHECK(errorOf(R"({"objects": [{"type": "torus"}]})") ==
          "bad.json: objects[0].type: unknown object type 'torus' (expected sphere, box, plane, triangle, quadric, "
          "cylinder, cone, ellipsoid, paraboloid, hyperboloid, polygon, polyhedron, patches, mesh)");
    CHECK(errorOf("[]") == "bad.json: expected a JSON object at top level, got []");
  }

  struct Case {
    const char* json;
    std::vector<std::string> words;
  };
  const std::vector<Case> cases = {
      // film and render: integer and range checks
      {R"({"film": {"width": 1.5}})",
       {"bad.json: film.width: ", "expected an integer in [1, 32768]", "got 1.5"}},
      {R"({"film": {"width": 0}})", {"film.width", "got 0"}},
      {R"({"film": {"height": 40000}})", {"film.height", "expected an integer", "got 40000"}},
      {R"({"film": {"width": "640"}})", {"film.width", "got \"640\""}},
      {R"({"film": {"spp": 0}})", {"film.spp", "expected an integer in [1,"}},
      {R"({"film": 3})", {"film: expected an object, got 3"}},
      {R"({"render": {"max_depth": 32}})", {"render.max_depth", "[0, 31]", "got 32"}},
      {R"({"render": {"max_depth": -1}})", {"render.max_depth", "got -1"}},
      {R"({"render": {"min_weight": 2}})", {"render.min_weight", "a number in [0, 1]", "got 2"}},
      {R"({"render": {"seed": -1}})", {"render.seed", "a non-negative integer", "got -1"}},
      {R"({"render": {"accel": "kdtree"}})", {"render.accel", "'kdtree'", "auto, bvh, octree, bsp, none"}},
      {R"({"render": {"seed": 2.5}})", {"render.seed", "got 2.5"}},
      {R"({"render": {"ambient": [1, 2]}})", {"render.ambient", "expected a colour", "got [1, 2]"}},
      {R"({"render": {"background": [0, -1, 0]}})",
       {"render.background[1]", "a number in [0, 1e6]", "got -1"}},
      // camera
      {R"({"camera": {"fov": 0}})", {"camera.fov", "(0, 180)", "got 0"}},
      {R"({"camera": {"fov": 180}})", {"camera.fov", "got 180"}},
      {R"({"camera": {"position": [1, 2, 3], "look_at": [1, 2, 3]}})",
       {"camera.look_at", "different from camera.position", "[1, 2, 3]"}},
      {R"({"camera": {"position": [0, 5, 0], "look_at": [0, 0, 0]}})", {"camera.up", "not parallel"}},
      {R"({"camera": {"up": [0, 0, 0]}})", {"camera.up", "not parallel"}},
      {R"({"camera": {"position": [0, "a", 0]}})", {"camera.position[1]", "a finite number", "got \"a\""}},
      {R"({"camera": {"position": [0, 0]}})", {"camera.position", "an array of 3 numbers", "got [0, 0]"}},
      {R"({"camera": []})", {"camera: expected an object"}},
      // The camera's points stay where objects may be (coordinates of at most 1e15); far
      // enough out, the up check must not be what refuses it.
      {R"({"camera": {"position": [0, 0, 1e20]}})", {"camera: position must have coordinates of at most 1e15"}},
      {R"({"camera": {"position": [0, 0, 1e300]}})", {"camera: position must have coordinates of at most 1e15"}},
      {R"({"camera": {"position": [0, 0, 1.5e308], "look_at": [0, 0, -1.5e308]}})",
       {"camera: position must have coordinates of at most 1e15"}},
      {R"({"camera": {"look_at": [-1e16, 0, 0]}})", {"camera: look_at must have coordinates of at most 1e15"}},
      {R"({"camera": {"position_end": [0, 0, 1e20]}})",
       {"camera: position_end must have coordinates of at most 1e15"}},
      {R"({"camera": {"look_at_end": [0, 1e20, 0]}})", {"camera: look_at_end must have coordinates of at most 1e15"}},
      // materials
      {R"({"materials": []})", {"materials: expected an object"}},
      {R"({"materials": {"m": 3}})", {"materials.m: expected an object, got 3"}},
      {R"({"materials": {"m": {"model": "cook"}}})",
       {"materials.m.model", "unknown shading model 'cook'", "phong, blinn, cook-torrance"}},
      {R"({"materials": {"m": {"model": "cook-torrance", "roughness": 0}}})",
       {"materials.m.roughness", "[0.001, 1]", "got 0"}},
      {R"({"materials": {"m": {"model": "cook-torrance", "distribution": "phong"}}})",
       {"materials.m.distribution", "unknown microfacet distribution 'phong'", "beckmann, ggx"}},
      {R"({"materials": {"m": {"reflect": 1.5}}})", {"materials.m.reflect", "[0, 1]", "got 1.5"}},
      {R"({"materials": {"m": {"transmit": -0.1}}})", {"materials.m.transmit", "got -0.1"}},
      {R"({"materials": {"m": {"ior": 0}}})", {"materials.m.ior", "a positive number", "got 0"}},
      {R"({"materials": {"m": {"shininess": -1}}})", {"materials.m.shininess", "[0, 1e6]", "got -1"}},
      {R"({"materials": {"m": {"shininess": 1e300}}})", {"materials.m.shininess", "[0, 1e6]", "got 1e+300"}},
      {R"({"render": {"ambient": [1e39, 1, 1]}})", {"render.ambient[0]", "[0, 1e6]", "got 1e+39"}},
      {R"({"materials": {"m": {"diffuse": 2e6}}})", {"materials.m.diffuse", "[0, 1e6]", "got 2000000"}},
      {R"({"materials": {"m": {"diffuse": "red"}}})",
       {"materials.m.diffuse", "expected a colour", "got \"red\""}},
      {R"({"materials": {"m": {"texture": {"type": "marble"}}}})",
       {"materials.m.texture.type", "unknown texture type 'marble'", "checker"}},
      {R"({"materials": {"m": {"texture": {}}}})", {"materials.m.texture: missing required key 'type'"}},
      {R"({"materials": {"m": {"texture": {"type": "checker", "scale": 0}}}})",
       {"materials.m.texture.scale", "a number in [1e-15, 1e15]", "got 0"}},
      // lights
      {R"({"lights": {}})", {"lights: expected an array", "got an object"}},
      {R"({"lights": [{"type": "spot", "position": [0, 0, 0]}]})",
       {"lights[0].type", "unknown light type 'spot'", "(expected point, quad, rect, disk, sphere)"}},
      {R"({"lights": [{"color": [1, 1, 1]}]})", {"lights[0]: missing required key 'position'"}},
      {R"({"lights": [{"position": [0, 0, 0], "intensity": -1}]})", {"lights[0].intensity", "got -1"}},
      // What a shaded point gets from its lights stays a float: each light's brightest
      // colour component times its intensity, and their sum over the scene.
      {R"({"lights": [{"position": [0, 0, 0], "color": [1, 2, 1], "intensity": 6e29}]})",
       {"lights[0]: color x intensity must be at most 1e30"}},
      {R"({"lights": [{"position": [0, 0, 0], "intensity": 6e29}, {"position": [0, 0, 1], "intensity": 6e29}]})",
       {"lights[1]: color x intensity summed over the scene's 2 lights must be at most 1e30"}},
      // objects
      {R"({"objects": [3]})", {"objects[0]: expected an object, got 3"}},
      {R"({"objects": [{"center": [0, 0, 0]}]})", {"objects[0]: missing required key 'type'"}},
      {R"({"objects": [{"type": 7}]})", {"objects[0].type", "expected a string", "got 7"}},
      {R"({"objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1, "material": 2}]})",
       {"objects[0].material", "a material name", "got 2"}},
      {R"({"objects": [{"type": "box", "min": [0, 0, 0], "max": [1, 0, 1]}]})",
       {"objects[0].max", "max > min on every axis", "[1, 0, 1]", "[0, 0, 0]"}},
      {R"({"objects": [{"type": "box", "min": [0, 0, 0]}]})", {"objects[0]: missing required key 'max'"}},
      {R"({"objects": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 0, 0]}]})",
       {"objects[0].normal", "a non-zero vector", "got [0, 0, 0]"}},
      {R"({"objects": [{"type": "triangle", "vertices": [[0, 0, 0], [1, 1, 1], [2, 2, 2]]}]})",
       {"objects[0].vertices", "non-degenerate", "[[0, 0, 0], [1, 1, 1], [2, 2, 2]]"}},
      {R"({"objects": [{"type": "triangle", "vertices": [[0, 0, 0], [1, 1, 1]]}]})",
       {"objects[0].vertices", "an array of 3 points"}},
      {R"({"objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1}, {"type": "sphere", "center": [0, 0, 0]}]})",
       {"objects[1]: missing required key 'radius'"}},
      {R"({"objects": [{"type": "sphere", "center": [0, 0, 0], "radius": 1e300}]})",
       {"objects[0]: radius must be a positive number of at most 1e15"}},
      {R"({"objects": [{"type": "box", "min": [-1e300, 0, 0], "max": [1, 1, 1]}]})",
       {"objects[0]: min must have coordinates of at most 1e15 in magnitude"}},
      {R"({"objects": [{"type": "triangle", "vertices": [[1e15, 0, 0], [1e15, 1e3, 0], [1e15, 0, 1e3]],
           "transform": {"translate": [1e15, 0, 0]}}]})",
       {"objects[0]: vertices must have coordinates of at most 1e15 in magnitude"}},
      // transforms
      {"*", {"objects[0].transform", "expected a transform", "got \"abc\""}},
      {R"("transform": [{"scale": 2}, 5])", {"objects[0].transform[1]: expected an object, got 5"}},
      {R"("transform": {"scale": 0})", {"objects[0].transform.scale", "non-zero", "got 0"}},
      {R"("transform": {"scale": [1, 0, 1]})", {"objects[0].transform.scale[1]", "non-zero", "got 0"}},
      {R"("transform": {"rotate": {"axis": [0, 0, 0], "angle": 10}})",
       {"objects[0].transform.rotate.axis", "a non-zero vector"}},
      {R"("transform": {"rotate": {"axis": [0, 0, 1]}})",
       {"objects[0].transform.rotate: missing required key 'angle'"}},
      {R"("transform": {"matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 1, 1]})",
       {"objects[0].transform.matrix", "last row to be 0 0 0 1", "got 0 0 1 1"}},
      {R"("transform": {"matrix": [1, 0, 0]})",
       {"objects[0].transform.matrix", "16 numbers", "got [1, 0, 0]"}},
      {R"("transform": {"matrix": [1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1], "scale": 2})",
       {"objects[0].transform", "'matrix' alone", "'scale'"}},
      {R"("transform": {"matrix": [1, 0, 0, 0, 2, 0, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1]})",
       {"objects[0].transform: expected an invertible transform", "singular"}},
      {R"("transform": [{"scale": 1e-200}, {"scale": 1e-200}])", {"objects[0].transform"}},
      {R"("transform": {"scale": 1e20})", {"objects[0].transform", "at most 1e15", "overflows"}},
      {R"("transform": {"scale": 1e-20})", {"objects[0].transform", "inverse", "too close to singular"}},
  };
  for (const Case& c : cases) {
    std::string json = c.json;
    if (json == "*")
      json = sphere(R"(, "transform": "abc")");
    else if (json.rfind("\"transform\"", 0) == 0)
      json = sphere(", " + json);
    const std::string message = errorOf(json);
    INFO("scene: " << json);
    INFO("message: " << message);
    REQUIRE_FALSE(message.empty());
    CHECK(message.rfind("bad.json: ", 0) == 0);
    for (const std::string& w : c.words) CHECK(contains(message, w));
  }
}

TEST_CASE("the camera's up is any finite direction off the view direction, however long", "[scene][errors]") {
  // Only its direction counts, so neither its length nor its square may overflow
  // or underflow on the way (up [0, 1e300, 0] squared is not a double).
  for (const char* up : {"[0, 1e300, 0]", "[0, 1e-300, 0]", "[1e300, 1e300, 0]"}) {
    INFO("up " << up);
    CHECK(errorOf(std::string(R"({"camera": {"up": )") + up + "}}").empty());
    CHECK(errorOf(std::string(R"({"camera": {"up": )") + up + R"(, "position_end": [1, 0, 5]}})").empty());
  }
  CHECK(contains(errorOf(R"({"camera": {"up": [0, 0, 1e300]}})"), "camera.up"));
}

TEST_CASE("lights may be as bright as 1e30 together, and no brighter", "[scene][errors]") {
  CHECK(errorOf(R"({"lights": [{"position": [0, 0, 0], "intensity": 1e30}]})").empty());
  CHECK(errorOf(R"({"lights": [{"position": [0, 0, 0], "intensity": 5e29},
                               {"type": "sphere", "center": [0, 0, 1], "radius": 1, "intensity": 5e29}]})")
            .empty());
  CHECK(contains(errorOf(R"({"lights": [{"position": [0, 0, 0], "intensity": 5e29},
                                        {"type": "sphere", "center": [0, 0, 1], "radius": 1, "intensity": 5.1e29}]})"),
                 "lights[1]: color x intensity summed over the scene's 2 lights"));
}

TEST_CASE("JSON syntax errors give line and column", "[scene][errors]") {
  CHECK(errorOf("{\n  \"film\": {\"width\": 640,,}\n}").rfind("bad.json:2:25: invalid JSON: ", 0) == 0);
  CHECK(errorOf("").rfind("bad.json:1:1: invalid JSON: ", 0) == 0);
  CHECK(contains(errorOf("  \n "), "invalid JSON"));
  CHECK(contains(errorOf("{\"film\": {\"width\": 640}"), "invalid JSON"));
  const std::string overflow = errorOf("{\n \"render\": {\"ambient\": 1e999}}");
  CHECK(overflow.rfind("bad.json:2:", 0) == 0);
  CHECK(contains(overflow, "invalid JSON"));
  CHECK(contains(overflow, "1e999"));
}

TEST_CASE("files that cannot be read give SceneIoError", "[scene][errors]") {
  const std::string missing = kScenes + "no-such-scene.json";
  try {
    loadSceneFile(missing);
    FAIL("no exception");
  } catch (const SceneIoError& e) {
    CHECK(std::string(e.what()) == missing + ": cannot open scene file: No such file or directory");
  }
  CHECK_THROWS_AS(loadSceneFile(kScenes), SceneIoError);  // a directory
}

TEST_CASE("unknown keys are warnings that name the JSON path", "[scene][warnings]") {
  const Scene s = parseScene(R"({
    "objcts": [],
    "camera": {"fov_deg": 30},
    "materials": {"glass": {"refract": 1, "texture": {"type": "checker", "size": 2}}},
    "lights": [{"position": [0, 1, 0], "power": 3}],
    "objects": [
      {"type": "sphere", "center": [0, 0, 0], "radius": 1},
      {"type": "box", "min": [0, 0, 0], "max": [1, 1, 1], "radius": 1},
      {"type": "sphere", "center": [0, 0, 0], "radius": 1, "radious": 2,
       "transform": [{"rotation": 5}]}
    ]
  })",
                             "w.json");
  const std::vector<std::string> expected = {
      "w.json: unknown key 'objcts' at top level (known: camera, film, render, materials, lights, objects, animation)",
      "w.json: camera: unknown key 'fov_deg' (ignored)",
      "w.json: materials.glass: unknown key 'refract' (ignored)",
      "w.json: materials.glass.texture: unknown key 'size' (ignored)",
      "w.json: lights[0]: unknown key 'power' (ignored)",
      "w.json: objects[1]: unknown key 'radius' (ignored)",
      "w.json: objects[2]: unknown key 'radious' (ignored)",
      "w.json: objects[2].transform[0]: unknown key 'rotation' (ignored)",
  };
  CHECK(s.warnings == expected);
  CHECK(s.objects.size() == 3);
}

TEST_CASE("Transform: composition, rotation and inverse", "[transform]") {
  SECTION("rotate 90 degrees about z maps x to y (right-handed)") {
    const Transform r = Transform::rotate({0, 0, 1}, 90);
    CHECK(r.applyVector({1, 0, 0}) == Vec3(0, 1, 0));
    CHECK(r.applyVector({0, 1, 0}) == Vec3(-1, 0, 0));
    CHECK(Transform::rotate({1, 0, 0}, 90).applyVector({0, 1, 0}) == Vec3(0, 0, 1));
    CHECK(Transform::rotate({0, 1, 0}, 90).applyVector({0, 0, 1}) == Vec3(1, 0, 0));
    CHECK(Transform::rotate({0, 0, 2}, -270).applyVector({1, 0, 0}) == Vec3(0, 1, 0));
  }
  SECTION("arbitrary rotations keep the axis and lengths") {
    const Vec3 axis{1, 2, 3};
    const Transform r = Transform::rotate(axis, 37);
    CHECK(near(r.applyVector(axis), axis));
    CHECK(length(r.applyVector({4, -1, 2})) == Approx(length(Vec3{4, -1, 2})));
    CHECK(r.determinant() == Approx(1));
    // 120 degrees about (1,1,1) cycles the axes: x -> y -> z.
    CHECK(near(Transform::rotate({1, 1, 1}, 120).applyVector({1, 0, 0}), {0, 1, 0}));
  }
  SECTION("a * b applies b first") {
    const Transform t = Transform::translate({1, 2, 3}) * Transform::scale({2, 2, 2});
    CHECK(t.applyPoint({1, 1, 1}) == Vec3(3, 4, 5));
    CHECK(t.applyVector({1, 1, 1}) == Vec3(2, 2, 2));
    const Transform u = Transform::scale({2, 2, 2}) * Transform::translate({1, 2, 3});
    CHECK(u.applyPoint({1, 1, 1}) == Vec3(4, 6, 8));
    CHECK(t.determinant() == 8);
    CHECK(Transform::identity().isIdentity());
    CHECK_FALSE(t.isIdentity());
  }
  SECTION("inverse * T is the identity on random transforms") {
    std::mt19937 rng(12345);
    std::uniform_real_distribution<double> u(-1, 1);
    auto scaleFactor = [&] {
      const double s = 0.2 + 2.8 * (u(rng) + 1) / 2;
      return u(rng) < 0 ? -s : s;
    };
    for (int i = 0; i < 200; ++i) {
      const Transform t = Transform::translate({10 * u(rng), 10 * u(rng), 10 * u(rng)}) *
                          Transform::rotate({u(rng), u(rng), u(rng) + 1.5}, 360 * u(rng)) *
                          Transform::scale({scaleFactor(), scaleFactor(), scaleFactor()}) *
                          Transform::rotate({u(rng) + 1.5, u(rng), u(rng)}, 360 * u(rng));
      CHECK(nearIdentity(t.inverse() * t, 1e-9));
      CHECK(nearIdentity(t * t.inverse(), 1e-9));
      const Vec3 p{u(rng), u(rng), u(rng)};
      CHECK(near(t.inverse().applyPoint(t.applyPoint(p)), p, 1e-9));
    }
  }
}

TEST_CASE("transforms in scene files", "[scene][transform]") {
  auto first = [](const std::string& objectJson) {
    return parseScene(R"({"objects": [)" + objectJson + "]}", "t.json").objects.at(0);
  };
  SECTION("one object applies scale, then rotate, then translate") {
    const Object o = first(R"({"type": "sphere", "center": [0, 0, 0], "radius": 1, "transform":
        {"translate": [0, 0, 5], "rotate": {"axis": [0, 0, 1], "angle": 90}, "scale": [2, 1, 1]}})");
    CHECK(o.type == ObjectType::Sphere);
    CHECK(near(o.transform.applyPoint({1, 0, 0}), {0, 2, 5}));
  }
  SECTION("an array applies its first element first") {
    const Object o = first(R"({"type": "sphere", "center": [0, 0, 0], "radius": 1,
        "transform": [{"translate": [1, 0, 0]}, {"scale": 2}]})");
    CHECK(o.transform.applyPoint({0, 0, 0}) == Vec3(2, 0, 0));
  }
  SECTION("a matrix is row-major") {
    const Object o = first(R"({"type": "box", "min": [0, 0, 0], "max": [1, 1, 1],
        "transform": {"matrix": [1, 0, 0, 4,  0, 1, 0, 5,  0, 0, 1, 6,  0, 0, 0, 1]}})");
    CHECK(o.transform.applyPoint({0, 0, 0}) == Vec3(4, 5, 6));
  }
  SECTION("triangles are stored in world space") {
    const Object o = first(R"({"type": "triangle", "vertices": [[0, 0, 0], [1, 0, 0], [0, 1, 0]],
        "transform": {"translate": [0, 0, 3]}})");
    CHECK(o.transform.isIdentity());
    CHECK(o.vertices[0] == Vec3(0, 0, 3));
    CHECK(o.vertices[1] == Vec3(1, 0, 3));
    CHECK(o.vertices[2] == Vec3(0, 1, 3));
  }
  SECTION("planes are stored in world space, normals by the inverse transpose") {
    const Object o = first(R"({"type": "plane", "point": [1, -1, 0], "normal": [1, 1, 0],
        "transform": {"scale": [2, 1, 1]}})");
    CHECK(o.transform.isIdentity());
    CHECK(o.point == Vec3(2, -1, 0));
    // The plane x + y = 0 becomes x / 2 + y = 0.
    CHECK(near(o.normal, normalize(Vec3{0.5, 1, 0})));
    const Object r = first(R"({"type": "plane", "point": [0, 0, 0], "normal": [0, 5, 0],
        "transform": {"rotate": {"axis": [0, 0, 1], "angle": 90}}})");
    CHECK(near(r.normal, {-1, 0, 0}));
  }
}

TEST_CASE("no input crashes the loader", "[scene][robustness]") {
  // Every value of the Whitted scene, replaced in turn by values of every JSON
  // kind, and the file text with bytes cut out: the loader either returns or
  // throws SceneError.
  const std::string text = [] {
    std::string t;
    std::FILE* f = std::fopen((kScenes + "whitted.json").c_str(), "rb");
    REQUIRE(f);
    char buf[4096];
    std::size_t n;
    while ((n = std::fread(buf, 1, sizeof buf, f)) > 0) t.append(buf, n);
    std::fclose(f);
    return t;
  }();
  const std::vector<std::string> replacements = {"null",  "true", "-1", "0",         "1.5",       "1e308",
                                                 "\"x\"", "[]",   "{}", "[1, 2, 3]", "[0, 0, 0]", "[[]]"};
  std::size_t tried = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    // Start of a value: after ':' or '[' or ',' inside arrays.
    if (text[i] != ':' && text[i] != '[' && text[i] != ',') continue;
    std::size_t start = text.find_first_not_of(" \n", i + 1);
    if (start == std::string::npos) continue;
    std::size_t end = start;
    int depth = 0;
    bool inString = false;
    for (; end < text.size(); ++end) {
      const char ch = text[end];
      if (inString) {
        inString = ch != '"';
        continue;
      }
      if (ch == '"')
        inString = true;
      else if (ch == '[' || ch == '{')
        ++depth;
      else if (ch == ']' || ch == '}') {
        if (depth == 0) break;
        --depth;
      } else if (ch == ',' && depth == 0)
        break;
    }
    for (const std::string& r : replacements) {
      const std::string mutated = text.substr(0, start) + r + text.substr(end);
      ++tried;
      try {
        parseScene(mutated, "m.json");
      } catch (const SceneError&) {
      } catch (const std::exception& e) {
        FAIL("unexpected exception " << e.what() << " for\n" << mutated);
      }
    }
  }
  CHECK(tried > 100);
  std::mt19937 rng(7);
  for (int i = 0; i < 500; ++i) {
    std::string mutated = text;
    const std::size_t at = rng() % mutated.size();
    mutated.erase(at, 1 + rng() % 8);
    try {
      parseScene(mutated, "m.json");
    } catch (const SceneError&) {
    }
  }
}
