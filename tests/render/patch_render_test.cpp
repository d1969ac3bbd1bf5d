// Bezier patches in whole renders: the two methods draw the same teapot
// (depth within the subdivision tolerance where the surface is clear-cut),
// the Z-buffer pass agrees with traced primary rays on both, transforms are
// honoured alike baked into the control points or applied to rays, and bad
// patch objects are refused with the reason.
#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>
#include <string>

#include "render/renderer.h"
#include "scene/patches/bpt_file.h"
#include "scene_format/scene_loader.h"
#include "support/scene_errors.h"
#include "support/shared_context.h"
#include "support/test_data.h"

using namespace prism;
using namespace prism::test;

namespace {

std::string teapotPath() { return prism_test::testDataDir() + "/patches/teapot.bpt"; }

// The teapot (z up in its file) stood on the floor, turned to show its spout.
std::string teapotScene(const std::string& patch_keys, const std::string& extra_object = "") {
  return R"({
    "camera": {"position": [0, 3.5, 9], "look_at": [0, 1.2, 0], "fov": 40},
    "film": {"width": 96, "height": 64},
    "render": {"max_depth": 3, "background": [0.2, 0.3, 0.45]},
    "materials": {"clay": {"diffuse": [0.8, 0.7, 0.6], "specular": 0.3, "shininess": 40}},
    "lights": [{"position": [3, 6, 5], "intensity": 0.8}, {"position": [-4, 3, 2], "intensity": 0.4}],
    "objects": [{"type": "plane", "point": [0, 0, 0], "normal": [0, 1, 0]},
      {"type": "patches", "file": ")" +
         teapotPath() + "\", " + patch_keys + R"(, "material": "clay",
       "transform": [{"rotate": {"axis": [1, 0, 0], "angle": -90}}, {"rotate": {"axis": [0, 1, 0], "angle": 25}}]})" +
         extra_object + "]}";
}

RenderResult render(const Scene& scene, FirstHitMode first_hit = FirstHitMode::Trace) {
  RenderOptions options = RenderOptions::fromScene(scene);
  options.first_hit = first_hit;
  return sharedRenderer().render(scene, options);
}

}  // namespace

TEST_CASE("the teapot by subdivision and by Newton iteration: the same depth within the tolerance",
          "[render][patches]") {
  const double tol = 0.01;
  const Scene analytic = parseScene(teapotScene(R"("method": "analytic")"), "a");
  const Scene mesh = parseScene(teapotScene(R"("method": "subdivision", "tolerance": 0.01)"), "m");
  const RenderResult a = render(analytic), m = render(mesh);
  std::size_t on_teapot = 0, both = 0, far = 0, colour_far = 0;
  const int w = a.width;
  for (std::size_t p = 0; p < a.depth.size(); ++p) {
    const bool ta = a.primid[p] >= 1, tm = m.primid[p] >= 1;  // 0 is the floor
    on_teapot += ta;
    if (!ta || !tm) continue;
    // Only pixels whose neighbours are on the teapot too: away from silhouettes.
    const int x = static_cast<int>(p) % w, y = static_cast<int>(p) / w;
    bool inner = x > 0 && y > 0 && x + 1 < w && y + 1 < a.height;
    for (int dy = -1; inner && dy <= 1; ++dy)
      for (int dx = -1; inner && dx <= 1; ++dx) inner = a.primid[p + dy * w + dx] >= 1 && m.primid[p + dy * w + dx] >= 1;
    if (!inner) continue;
    ++both;
    // Depth is distance along the ray; the view meets the surface at up to ~80 degrees here.
    far += std::fabs(a.depth[p] - m.depth[p]) > 6 * tol;
    double diff = 0;
    for (int c = 0; c < 3; ++c) diff = std::max(diff, std::fabs(double(a.rgba[4 * p + c]) - m.rgba[4 * p + c]));
    colour_far += diff > 0.1;
  }
  INFO(on_teapot << " pixels on the teapot, " << both << " inner on both, " << far << " deeper apart than 6 tol, "
                 << colour_far << " differ in colour by more than 0.1");
  CHECK(on_teapot > a.depth.size() / 8);
  CHECK(both > on_teapot * 3 / 4);
  CHECK(far <= both / 100);
  CHECK(colour_far <= both / 50);
}

TEST_CASE("Z-buffer and traced primary rays agree on patches by either method", "[render][patches][firsthit]") {
  for (const char* keys : {R"("method": "analytic")", R"("method": "subdivision")"}) {
    INFO(keys);
    const Scene scene = parseScene(teapotScene(keys), "z");
    const RenderResult z = render(scene, FirstHitMode::ZBuffer), t = render(scene, FirstHitMode::Trace);
    REQUIRE(z.stats.first_hit == FirstHitMode::ZBuffer);
    std::size_t hits = 0, differ = 0;
    for (std::size_t p = 0; p < z.primid.size(); ++p) {
      hits += t.primid[p] >= 1;
      bool same = z.primid[p] == t.primid[p] && z.depth[p] == t.depth[p];
      for (int c = 0; c < 4; ++c) same = same && z.rgba[4 * p + c] == t.rgba[4 * p + c];
      differ += !same;
    }
    INFO(hits << " pixels on the teapot, " << differ << " differ");
    CHECK(hits > z.primid.size() / 8);
    CHECK(differ == 0);
  }
}

TEST_CASE("a teapot kept in object space (as moving objects are) matches the one baked into world space",
          "[render][patches][motion]") {
  // A static transform is baked into the control points; a moving object's
  // is not: the kernel maps each ray into object space instead. With a
  // zero-length shutter the moving teapot stands at its start, and both ways
  // must draw the same teapot.
  const std::string moving = teapotScene(R"("method": "analytic", "transform_end": {"translate": [0.4, 0, 0]})");
  const Scene still = parseScene(teapotScene(R"("method": "analytic")"), "s");
  Scene blurred = parseScene(moving, "m");
  REQUIRE(blurred.objects[1].moving);
  // Shutter [0, 0]: every ray at time 0, where the moving teapot is the still one.
  blurred.camera.shutter_open = blurred.camera.shutter_close = 0;
  const RenderResult a = render(still), b = render(blurred);
  std::size_t differ = 0, hits = 0;
  for (std::size_t p = 0; p < a.primid.size(); ++p) {
    hits += a.primid[p] >= 1;
    differ += (a.primid[p] >= 1) != (b.primid[p] >= 1) || std::fabs(a.depth[p] - b.depth[p]) > 1e-3f;
  }
  INFO(differ << " of " << hits << " differ");
  CHECK(hits > a.primid.size() / 8);
  CHECK(differ <= a.primid.size() / 500);
}

TEST_CASE("patches given inline are the patches of the file", "[render][patches][scene]") {
  // The teapot's file written out as inline control points: the same mesh, bit for bit.
  const std::vector<BezierPatch> patches = readBptFile(teapotPath());
  std::ostringstream json;
  json.precision(17);
  json << R"({"objects": [{"type": "patches", "patches": [)";
  for (std::size_t k = 0; k < patches.size(); ++k) {
    json << (k ? ", [" : "[");
    for (int i = 0; i < 16; ++i)
      json << (i ? ", [" : "[") << patches[k].p[i].x << ", " << patches[k].p[i].y << ", " << patches[k].p[i].z << "]";
    json << "]";
  }
  json << "]}]}";
  const Scene inline_scene = parseScene(json.str(), "inline");
  const Scene file_scene = parseScene(R"({"objects": [{"type": "patches", "file": ")" + teapotPath() + "\"}]}", "file");
  REQUIRE(inline_scene.objects[0].mesh);
  CHECK(inline_scene.objects[0].mesh->positions == file_scene.objects[0].mesh->positions);
  CHECK(inline_scene.objects[0].mesh->indices == file_scene.objects[0].mesh->indices);
  CHECK(inline_scene.objects[0].mesh->normals == file_scene.objects[0].mesh->normals);
}

TEST_CASE("bad patch objects are refused with the reason", "[render][patches][scene]") {
  const std::string file = teapotPath();
  const struct {
    std::string object;
    const char* message;
  } cases[] = {
      {R"({"type": "patches"})", "objects[0]: missing required key 'file'"},
      {R"({"type": "patches", "file": "/nonexistent/teapot.bpt"})", "objects[0].file: /nonexistent/teapot.bpt: cannot open: no such file"},
      {R"({"type": "patches", "file": "/dev/zero"})", "not a regular file"},
      {R"({"type": "patches", "file": ")" + file + R"(", "method": "bezier-clipping"})",
       "objects[0].method: unknown method 'bezier-clipping' (expected subdivision or analytic)"},
      {R"({"type": "patches", "file": ")" + file + R"(", "tolerance": 0})", "objects[0].tolerance: expected a positive number"},
      {R"({"type": "patches", "file": ")" + file + R"(", "tolerance": 1e-9})", "a millionth of the patches' size"},
      {R"({"type": "patches", "file": ")" + file + R"(", "tolerance": 1e-5})", "triangles: raise it"},
  };
  for (const auto& c : cases) {
    INFO(c.object);
    CHECK_THAT(errorOf(R"({"objects": [)" + c.object + "]}"), Catch::Contains(c.message));
  }
  // Inline control points: 16 per patch, each a finite point, and not beside a file.
  std::string points15 = "[", points16;
  for (int i = 0; i < 15; ++i) points15 += std::string(i ? ", " : "") + "[" + std::to_string(i) + ", 0, " + std::to_string(i % 4) + "]";
  points16 = points15 + ", [15, 1, 3]]";
  points15 += "]";
  CHECK_THAT(errorOf(R"({"objects": [{"type": "patches", "patches": [)" + points15 + "]}]}"),
             Catch::Contains("objects[0].patches[0]: expected 16 control points"));
  CHECK_THAT(errorOf(R"({"objects": [{"type": "patches", "patches": [)" + points16 + R"(], "file": "t.bpt"}]})"),
             Catch::Contains("either in a file or as 'patches'"));
  CHECK(errorOf(R"({"objects": [{"type": "patches", "patches": [)" + points16 + "]}]}").empty());
  // A file that is no patch file names its line.
  CHECK_THAT(errorOf(R"({"objects": [{"type": "patches", "file": ")" + prism_test::testMeshDir() +
                     R"(/bunny/bun_zipper_res4.ply"}]})"),
             Catch::Contains("bun_zipper_res4.ply:1: expected the number of patches"));
}
