// Quadrics, polygons and polyhedra in whole renders: a quadric sphere against
// the sphere primitive (two methods, one surface), the Z-buffer pass against
// traced primary rays on every kind, the scene format's presets against their
// closed forms, and the refusals of bad ones.
#include <catch2/catch.hpp>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "render/gpu_scene.h"
#include "render/ray_queries.h"
#include "render/renderer.h"
#include "scene/mesh_objects.h"
#include "scene_format/scene_loader.h"
#include "support/scene_errors.h"
#include "support/shared_context.h"
#include "support/test_data.h"

using namespace prism;
using namespace prism::test;

namespace {

std::string zooScene(const std::string& objects) {
  return R"({
    "camera": {"position": [0, 2.2, 6.5], "look_at": [0, 0.6, 0], "fov": 42},
    "film": {"width": 96, "height": 64},
    "render": {"max_depth": 4, "background": [0.2, 0.3, 0.45]},
    "materials": {
      "clay": {"diffuse": [0.8, 0.7, 0.6], "specular": 0.3, "shininess": 40},
      "mirror": {"diffuse": 0.05, "reflect": 0.8, "specular": 0.6, "shininess": 120},
      "glass": {"diffuse": 0, "transmit": 0.9, "reflect": 0.05, "ior": 1.5},
      "floor": {"texture": {"type": "checker", "color1": 0.9, "color2": 0.2, "scale": 0.5}}
    },
    "lights": [{"position": [3, 6, 5], "intensity": 0.8}, {"position": [-4, 3, 2], "intensity": 0.4}],
    "objects": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0], "material": "floor"}, )" +
         objects + "]}";
}

double maxChannelDiff(const RenderResult& a, const RenderResult& b, std::size_t p) {
  double diff = 0;
  for (int c = 0; c < 4; ++c) diff = std::max(diff, std::fabs(double(a.rgba[4 * p + c]) - b.rgba[4 * p + c]));
  return diff;
}

}  // namespace

TEST_CASE("a quadric sphere renders as the sphere primitive: depth, normal and colour, through glass too",
          "[render][quadric]") {
  for (const char* material : {"clay", "glass", "mirror"}) {
    const std::string m = material;
    const Scene sphere = parseScene(
        zooScene(R"({"type": "sphere", "center": [0.2, 0.8, 0], "radius": 0.8, "material": ")" + m + R"("})"), "s");
    // (x - 0.2)^2 + (y - 0.8)^2 + z^2 - 0.64, capped by its own bounding box.
    const Scene quadric = parseScene(
        zooScene(R"({"type": "quadric", "coefficients": [1, 1, 1, 0, 0, 0, -0.4, -1.6, 0, 0.04], "capped": true,
                     "clip": {"min": [-0.6, 0, -0.8], "max": [1, 1.6, 0.8]}, "material": ")" + m + R"("})"),
        "q");
    const RenderOptions opt = RenderOptions::fromScene(sphere);
    const RenderResult a = sharedRenderer().render(sphere, opt);
    const RenderResult b = sharedRenderer().render(quadric, opt);
    const std::size_t pixels = a.primid.size();
    std::size_t both = 0, same_hit = 0, close_depth = 0, close_normal = 0, close_colour = 0;
    for (std::size_t p = 0; p < pixels; ++p) {
      same_hit += a.primid[p] == b.primid[p];
      if (a.primid[p] != 1 || b.primid[p] != 1) continue;
      ++both;
      // Where the view grazes the sphere, t is ill-conditioned (its error grows
      // as 1 / cos^2 of the angle to the normal): the tolerance follows.
      const Vec3 n{a.normal[3 * p], a.normal[3 * p + 1], a.normal[3 * p + 2]};
      const Vec3 hit = Vec3{0.2, 0.8, 0} + n * 0.8, to_camera = normalize(Vec3{0, 2.2, 6.5} - hit);
      const double cos = std::max(std::fabs(dot(n, to_camera)), 1e-3);
      close_depth += std::fabs(a.depth[p] - b.depth[p]) <= 1e-5 * a.depth[p] / (cos * cos);
      double dn = 0;
      for (int k = 0; k < 3; ++k) dn = std::max(dn, std::fabs(double(a.normal[3 * p + k]) - b.normal[3 * p + k]));
      close_normal += dn < 1e-4 / cos;
      close_colour += maxChannelDiff(a, b, p) < 2e-3;
    }
    INFO(m << ": " << both << " pixels on the sphere in both, " << same_hit << " of " << pixels << " same primid, "
           << close_depth << " depths, " << close_normal << " normals, " << close_colour << " colours close");
    CHECK(both > pixels / 20);
    CHECK(same_hit >= pixels - 2);  // an edge pixel may round either way
    CHECK(close_depth == both);
    CHECK(close_normal == both);
    CHECK(close_colour >= both * 99 / 100);
  }
}

TEST_CASE("Z-buffer and traced primary rays agree on every quadric preset, a polygon and a polyhedron", "[render][quadric][firsthit]") {
  const Scene scene = parseScene(zooScene(R"(
      {"type": "cylinder", "radius": 0.4, "height": 1.2, "material": "clay", "transform": {"translate": [-2, 0, 0]}},
      {"type": "cone", "radius": 0.5, "height": 1.3, "material": "mirror", "transform": {"translate": [-1, 0, 0]}},
      {"type": "paraboloid", "radius": 0.5, "height": 1, "capped": false, "material": "clay"},
      {"type": "ellipsoid", "radii": [0.4, 0.7, 0.4], "material": "glass", "transform": {"translate": [1, 0.7, 0]}},
      {"type": "hyperboloid", "radius": 0.25, "top_radius": 0.5, "height": 0.6, "material": "clay",
       "transform": {"translate": [2, 0.6, 0]}},
      {"type": "hyperboloid", "sheets": 2, "vertex": 0.2, "top_radius": 0.4, "height": 0.6, "material": "clay",
       "transform": [{"rotate": {"axis": [0, 0, 1], "angle": 90}}, {"translate": [0, 0.5, 1.5]}]},
      {"type": "quadric", "coefficients": [1, -1, 0, 0, 0, 0, 0, 0, -1, 0], "material": "clay",
       "clip": {"min": [-0.5, -0.5, -0.5], "max": [0.5, 0.5, 0.5]}, "transform": {"translate": [-1.5, 0.6, 1.5]}},
      {"type": "polygon", "vertices": [[1, 0.2, 1.2], [2, 0.2, 1.2], [2, 1.2, 1.2], [1.5, 0.6, 1.2], [1, 1.2, 1.2]],
       "material": "mirror"},
      {"type": "polyhedron", "material": "glass", "transform": {"translate": [-0.5, 0.5, 2]},
       "planes": [[1, 1, 1, -0.5], [1, 1, -1, -0.5], [1, -1, 1, -0.5], [1, -1, -1, -0.5],
                  [-1, 1, 1, -0.5], [-1, 1, -1, -0.5], [-1, -1, 1, -0.5], [-1, -1, -1, -0.5]]})"),
                                 "zoo");
  RenderOptions zopt = RenderOptions::fromScene(scene), topt = zopt;
  zopt.first_hit = FirstHitMode::ZBuffer;
  topt.first_hit = FirstHitMode::Trace;
  const RenderResult z = sharedRenderer().render(scene, zopt);
  const RenderResult t = sharedRenderer().render(scene, topt);
  REQUIRE(z.stats.first_hit == FirstHitMode::ZBuffer);
  const std::size_t pixels = z.primid.size();
  std::size_t quadric_hits = 0, differ = 0;
  for (std::size_t p = 0; p < pixels; ++p) {
    quadric_hits += t.primid[p] >= 1;
    differ += z.primid[p] != t.primid[p] || z.depth[p] != t.depth[p] || maxChannelDiff(z, t, p) != 0;
  }
  INFO(quadric_hits << " pixels on quadrics, " << differ << " differ");
  CHECK(quadric_hits > pixels / 10);
  // Both passes finish with the same ray-quadric routine: the same image.
  CHECK(differ == 0);
}

TEST_CASE("the presets put their surface where their parameters say", "[render][quadric][scene]") {
  // Points the closed forms put on each surface satisfy its coefficients (up
  // to rounding), and points off it do not.
  auto q = [](const std::string& json) {
    return parseScene(R"({"objects": [)" + json + "]}", "preset").objects.at(0).params;
  };
  auto value = [](const std::vector<double>& c, double x, double y, double z) {
    return c[0] * x * x + c[1] * y * y + c[2] * z * z + c[3] * x * y + c[4] * x * z + c[5] * y * z + c[6] * x +
           c[7] * y + c[8] * z + c[9];
  };
  const auto cyl = q(R"({"type": "cylinder", "radius": 0.5, "height": 2})");
  CHECK(value(cyl, 0.5, 1.3, 0) == Approx(0).margin(1e-12));
  CHECK(value(cyl, 0.3, 0.2, 0.4) == Approx(0).margin(1e-12));
  CHECK(value(cyl, 0, 1, 0) < 0);  // inside is Q < 0
  CHECK(cyl[14] == 2);             // clip max y: the height
  const auto cone = q(R"({"type": "cone", "radius": 0.5, "height": 2})");
  CHECK(value(cone, 0.5, 0, 0) == Approx(0).margin(1e-12));   // base rim
  CHECK(value(cone, 0, 2, 0) == Approx(0).margin(1e-12));     // apex
  CHECK(value(cone, 0.25, 1, 0) == Approx(0).margin(1e-12));  // halfway up, half the radius
  CHECK(value(cone, 0, 0.5, 0) < 0);
  const auto para = q(R"({"type": "paraboloid", "radius": 0.5, "height": 2})");
  CHECK(value(para, 0.5, 2, 0) == Approx(0).margin(1e-12));
  CHECK(value(para, 0, 0, 0) == Approx(0).margin(1e-12));
  CHECK(value(para, 0.25, 0.5, 0) == Approx(0).margin(1e-12));  // r^2 grows with y
  const auto ell = q(R"({"type": "ellipsoid", "radii": [1, 2, 3]})");
  CHECK(value(ell, 1, 0, 0) == Approx(0).margin(1e-12));
  CHECK(value(ell, 0, 2, 0) == Approx(0).margin(1e-12));
  CHECK(value(ell, 0, 0, -3) == Approx(0).margin(1e-12));
  const auto hyp1 = q(R"({"type": "hyperboloid", "radius": 0.5, "top_radius": 1, "height": 2})");
  CHECK(value(hyp1, 0.5, 0, 0) == Approx(0).margin(1e-12));  // the waist
  CHECK(value(hyp1, 0, -2, 1) == Approx(0).margin(1e-12));   // the rim
  CHECK(value(hyp1, 0, 0, 0) < 0);
  const auto hyp2 = q(R"({"type": "hyperboloid", "sheets": 2, "vertex": 0.5, "top_radius": 1, "height": 2})");
  CHECK(value(hyp2, 0, 0.5, 0) == Approx(0).margin(1e-12));  // a tip
  CHECK(value(hyp2, 1, -2, 0) == Approx(0).margin(1e-12));   // the rim
  CHECK(value(hyp2, 0, 1.5, 0) < 0);                          // inside a bowl
  CHECK(value(hyp2, 0, 0, 0) > 0);                            // between the sheets
}

TEST_CASE("bad quadrics are refused with the reason", "[render][quadric][scene]") {
  const struct {
    const char* object;
    const char* message;
  } cases[] = {
      {R"({"type": "quadric", "coefficients": [1, 1, 1, 0, 0, 0, 0, 0, 0, -1]})", "objects[0]: missing required key 'clip'"},
      {R"({"type": "quadric", "coefficients": [1, 1, 1], "clip": {"min": [-1, -1, -1], "max": [1, 1, 1]}})",
       "objects[0].coefficients: expected an array of 10 numbers"},
      {R"({"type": "quadric", "coefficients": [0, 0, 0, 0, 0, 0, 0, 0, 0, 1], "clip": {"min": [-1, -1, -1], "max": [1, 1, 1]}})",
       "one of the first nine must be non-zero"},
      {R"({"type": "quadric", "coefficients": [1, 1, 1, 0, 0, 0, 0, 0, 0, -1], "clip": {"min": [1, -1, -1], "max": [1, 1, 1]}})",
       "objects[0].clip.max: expected max > min on every axis"},
      {R"({"type": "cylinder", "radius": -1})", "objects[0].radius: expected a positive number of at most 1e15, got -1"},
      {R"({"type": "hyperboloid", "radius": 2, "top_radius": 1})", "objects[0].top_radius: expected more than radius"},
      {R"({"type": "hyperboloid", "sheets": 2, "vertex": 3, "height": 1})", "objects[0].height: expected more than vertex"},
      {R"({"type": "hyperboloid", "sheets": 3})", "objects[0].sheets: expected an integer in [1, 2]"},
      {R"({"type": "ellipsoid", "radii": [1, 0, 1]})", "objects[0].radii[1]: expected a positive number of at most 1e15, got 0"},
      {R"({"type": "quadric", "coefficients": [1, 1, 1, 0, 0, 0, 0, 0, 0, -1],
           "clip": {"min": [-1, -1, -1], "max": [1, 1, 1e300]}})", "clip.max must have coordinates of at most 1e15"},
      // A preset's sizes are lengths bounding its clip box: refused under the key written.
      {R"({"type": "cylinder", "radius": 1e300})", "objects[0].radius: expected a positive number of at most 1e15"},
      {R"({"type": "cone", "height": 2e15})", "objects[0].height: expected a positive number of at most 1e15"},
      {R"({"type": "ellipsoid", "radii": [1, 1, 1.1e15]})", "objects[0].radii[2]: expected a positive number of at most 1e15"},
      // Each within bounds, together past what float keeps: named with the preset's sizes.
      {R"({"type": "ellipsoid", "radii": [1e-200, 1, 1]})", "objects[0]: the sizes radii [1e-200, 1, 1] make a quadric"},
      {R"({"type": "cone", "radius": 1e10, "height": 1e-10})",
       "objects[0]: the sizes radius 10000000000, height 1e-10 make a quadric prism cannot hold: coefficients span"},
      // A coefficient that the kernel's scaling to a largest magnitude of 1
      // would put below float's smallest normal (2^-126, about 1.18e-38).
      {R"({"type": "quadric", "coefficients": [1, 1e-38, 1, 0, 0, 0, 0, 0, 0, -1], "clip": {"min": [-1, -1, -1], "max": [1, 1, 1]}})",
       "objects[0]: coefficients span more than float holds: 1e-38 beside 1"},
      {R"({"type": "quadric", "coefficients": [1e30, 1e-9, 1, 0, 0, 0, 0, 0, 0, -1], "clip": {"min": [-1, -1, -1], "max": [1, 1, 1]}})",
       "coefficients span more than float holds: 1e-09 beside 1e+30"},
  };
  for (const auto& c : cases) {
    INFO(c.object);
    CHECK_THAT(errorOf(std::string(R"({"objects": [)") + c.object + "]}"), Catch::Contains(c.message));
  }
  // The bounds themselves are accepted: sizes of 1e15 and of 1e-15, and a
  // coefficient just above float's smallest normal once scaled.
  for (const char* object : {R"({"type": "cylinder", "radius": 1e15, "height": 1e15})",
                             R"({"type": "ellipsoid", "radii": [1e15, 1e15, 1e15]})",
                             R"({"type": "cylinder", "radius": 1e-15, "height": 1e-15})",
                             R"({"type": "quadric", "coefficients": [1, 1.2e-38, 1, 0, 0, 0, 0, 0, 0, -1], "clip": {"min": [-1, -1, -1], "max": [1, 1, 1]}})"}) {
    INFO(object);
    CHECK(errorOf(std::string(R"({"objects": [)") + object + "]}") == "");
  }
}

TEST_CASE("bad polyhedra are refused with the reason", "[render][polyhedron][scene]") {
  const struct {
    const char* object;
    const char* message;
  } cases[] = {
      {R"({"type": "polyhedron", "planes": [[1, 0, 0, -1], [-1, 0, 0, -1], [0, 1, 0, -1]]})",
       "objects[0].planes: expected an array of 4 to 4096 planes"},
      {R"({"type": "polyhedron", "planes": [[1, 0, 0, -1], [-1, 0, 0, -1], [0, 1, 0, -1], [0, 0, 0, -1]]})",
       "objects[0].planes[3]: expected a plane with a non-zero normal"},
      // x <= -1 and x >= 1: nothing in common.
      {R"({"type": "polyhedron", "planes": [[1, 0, 0, 1], [-1, 0, 0, 1], [0, 1, 0, -1], [0, -1, 0, -1],
          [0, 0, 1, -1], [0, 0, -1, -1]]})", "objects[0].planes: the half-spaces have no point in common"},
      // A box open towards +z.
      {R"({"type": "polyhedron", "planes": [[1, 0, 0, -1], [-1, 0, 0, -1], [0, 1, 0, -1], [0, -1, 0, -1],
          [0, 0, -1, -1]]})", "objects[0].planes: the half-spaces do not enclose a bounded region"},
      // 0 <= z <= 0: flat.
      {R"({"type": "polyhedron", "planes": [[1, 0, 0, -1], [-1, 0, 0, -1], [0, 1, 0, -1], [0, -1, 0, -1],
          [0, 0, 1, 0], [0, 0, -1, 0]]})", "objects[0].planes: the half-spaces enclose no volume (flat on the z axis)"},
  };
  for (const auto& c : cases) {
    INFO(c.object);
    CHECK_THAT(errorOf(std::string(R"({"objects": [)") + c.object + "]}"), Catch::Contains(c.message));
  }
}

TEST_CASE("a mesh's faces kept as polygons render the same depth and image as its triangles",
          "[render][polygon][mesh]") {
  // Pentagons, the Cornell box's quads, and a file with a non-planar quad (which
  // stays triangles, with a warning).
  for (const char* file : {"formats/off/geomview/dodec.off", "formats/obj/tinyobjloader/cornell_box.obj",
                           "formats/off/selfmade/ngon_comments_counts_inline.off"}) {
    const std::string path = prism_test::testDataDir() + "/" + file;
    const std::string json = R"({"film": {"width": 96, "height": 72}, "objects": [{"type": "mesh", "file": ")" +
                             path + R"("}]})";
    Scene triangles = parseScene(json, "triangles");
    Scene polygons = parseScene(json.substr(0, json.size() - 3) + R"(, "polygons": true}]})", "polygons");
    // Frame it as the quick render does.
    const Scene framed = sceneForMesh(triangles.objects[0].mesh);
    triangles.camera = polygons.camera = framed.camera;
    triangles.lights = polygons.lights = framed.lights;
    const Object& mesh = polygons.objects[0];
    std::size_t faces = 0, kept_as_polygons = 0;
    for (std::uint32_t c : mesh.mesh->face_corners) faces += c > 3;
    for (bool p : mesh.polygon_faces) kept_as_polygons += p;
    INFO(file << ": " << kept_as_polygons << " of " << faces << " faces of more than 3 corners kept as polygons, "
              << polygons.warnings.size() << " warning(s)");
    CHECK(kept_as_polygons > 0);
    CHECK(mesh.primitiveCount() < triangles.objects[0].primitiveCount());
    CHECK(polygons.warnings.size() == (kept_as_polygons < faces ? 1u : 0u));
    const RenderOptions opt = RenderOptions::fromScene(triangles);
    const RenderResult a = sharedRenderer().render(triangles, opt), b = sharedRenderer().render(polygons, opt);
    std::size_t hits = 0, same_hit = 0, close_depth = 0, close_colour = 0;
    for (std::size_t p = 0; p < a.primid.size(); ++p) {
      same_hit += (a.primid[p] >= 0) == (b.primid[p] >= 0);
      if (a.primid[p] < 0 || b.primid[p] < 0) continue;
      ++hits;
      close_depth += std::fabs(a.depth[p] - b.depth[p]) <= 1e-5f * a.depth[p];
      close_colour += maxChannelDiff(a, b, p) < 1e-3;
    }
    INFO(hits << " pixels hit, " << same_hit << " agree on hit or miss, " << close_depth << " depths, "
              << close_colour << " colours close");
    CHECK(hits > a.primid.size() / 20);
    CHECK(same_hit >= a.primid.size() - 2);  // a silhouette pixel may round either way
    CHECK(close_depth >= hits - 2);
    CHECK(close_colour >= hits * 99 / 100);
  }
}

TEST_CASE("a polyhedron given by its faces meets rays where the box and the convex polyhedron do",
          "[render][polyhedron]") {
  // The unit cube by its faces (one face turned the wrong way round is refused
  // below; all of them turned inwards is turned back), against the box.
  const std::string cube_faces = R"({"type": "polyhedron",
      "vertices": [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]],
      "faces": [[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [2, 3, 7, 6], [1, 2, 6, 5], [0, 4, 7, 3]]})";
  const std::string cube_inwards = R"({"type": "polyhedron",
      "vertices": [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]],
      "faces": [[1, 2, 3, 0], [7, 6, 5, 4], [4, 5, 1, 0], [6, 7, 3, 2], [5, 6, 2, 1], [3, 7, 4, 0]]})";
  const std::string box = R"({"type": "box", "min": [0, 0, 0], "max": [1, 1, 1]})";
  const std::string octa_faces = R"({"type": "polyhedron",
      "vertices": [[1, 0, 0], [-1, 0, 0], [0, 1, 0], [0, -1, 0], [0, 0, 1], [0, 0, -1]],
      "faces": [[0, 2, 4], [2, 1, 4], [1, 3, 4], [3, 0, 4], [2, 0, 5], [1, 2, 5], [3, 1, 5], [0, 3, 5]]})";
  const std::string octa_planes = R"({"type": "polyhedron", "planes": [[1, 1, 1, -1], [1, 1, -1, -1], [1, -1, 1, -1],
      [1, -1, -1, -1], [-1, 1, 1, -1], [-1, 1, -1, -1], [-1, -1, 1, -1], [-1, -1, -1, -1]]})";
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<float> u(-3, 3);
  std::vector<RayGpu> rays(4000);
  for (RayGpu& r : rays) {
    r = RayGpu{};
    r.ox = u(rng), r.oy = u(rng), r.oz = u(rng);
    r.dx = u(rng) * 0.1f - r.ox, r.dy = u(rng) * 0.1f - r.oy, r.dz = u(rng) * 0.1f - r.oz;  // towards the middle
    r.tmax = INFINITY;
    r.kind = RAY_KIND_PRIMARY;
  }
  auto trace = [&](const std::string& object) {
    return traceClosest(sharedContext(), parseScene(R"({"objects": [)" + object + "]}", "one"), rays);
  };
  for (const auto& [a, b] : {std::pair{cube_faces, box}, std::pair{cube_inwards, box}, std::pair{octa_faces, octa_planes}}) {
    const std::vector<HitGpu> ha = trace(a), hb = trace(b);
    std::size_t hits = 0, differ = 0;
    for (std::size_t i = 0; i < rays.size(); ++i) {
      hits += hb[i].prim >= 0;
      differ += (ha[i].prim >= 0) != (hb[i].prim >= 0) || std::fabs(ha[i].t - hb[i].t) > 1e-5f * (1 + hb[i].t);
    }
    INFO(a << "\nagainst " << b << ": " << hits << " hits, " << differ << " differ");
    CHECK(hits > 500);
    CHECK(differ <= 4);  // rays through edges and corners may round either way
  }
  // Turned inwards and turned back: the normals point out again.
  const Scene inwards = parseScene(R"({"objects": [)" + cube_inwards + "]}", "inwards");
  const GpuScene gpu = flattenScene(inwards, RenderOptions::fromScene(inwards));
  CHECK(gpu.objects[0].type == OBJECT_POLYGON);
  CHECK(gpu.objects[0].p[2] == -1.0f);  // the z = 0 face's normal is -z
}

TEST_CASE("polyhedra by faces must be closed and consistently turned", "[render][polyhedron][scene]") {
  const std::string v = R"("vertices": [[0, 0, 0], [1, 0, 0], [1, 1, 0], [0, 1, 0], [0, 0, 1], [1, 0, 1], [1, 1, 1], [0, 1, 1]])";
  const struct {
    std::string faces;
    const char* message;
  } cases[] = {
      {R"([[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [2, 3, 7, 6], [1, 2, 6, 5]])", "belongs to one face only"},
      {R"([[0, 1, 2, 3], [4, 5, 6, 7], [0, 1, 5, 4], [2, 3, 7, 6], [1, 2, 6, 5], [0, 4, 7, 3]])",
       "runs the same way in 2 faces"},
      {R"([[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [2, 3, 7, 6], [1, 2, 6, 5], [0, 4, 7, 9]])",
       "objects[0].faces[5][3]: expected an integer in [0, 7]"},
      {R"([[0, 3, 6, 1], [4, 5, 6, 7], [0, 1, 5, 4], [2, 3, 7, 6], [1, 2, 6, 5], [0, 4, 7, 3]])",
       "objects[0].faces[0]: expected the polygon to be planar"},
  };
  for (const auto& c : cases) {
    INFO(c.faces);
    CHECK_THAT(errorOf(R"({"objects": [{"type": "polyhedron", )" + v + R"(, "faces": )" + c.faces + "}]}"),
               Catch::Contains(c.message));
  }
}
