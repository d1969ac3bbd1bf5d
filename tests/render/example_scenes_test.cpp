// Every example scene in scenes/ loads and renders (small) to finite pixels
// that are not all the background, and renders the same bits with the BVH's
// children bounded by k-DOP slabs as by boxes: the scenes between them hold
// every kind of object, motion, an animation, area lights, depth of field and
// textures.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "render/renderer.h"
#include "scene/animation.h"
#include "scene_format/scene_loader.h"
#include "support/shared_context.h"

using namespace prism;
namespace fs = std::filesystem;

TEST_CASE("every example scene renders finite pixels, the same with k-DOP bounds as with boxes", "[render][scenes]") {
  std::vector<fs::path> files;
  for (const fs::directory_entry& e : fs::directory_iterator(PRISM_SOURCE_DIR "/scenes"))
    if (e.path().extension() == ".json") files.push_back(e.path());
  std::sort(files.begin(), files.end());
  REQUIRE(files.size() >= 10);
  for (const fs::path& file : files) {
    INFO(file.filename().string());
    // An animation's last frame (a still's only one).
    const Scene file_scene = loadSceneFile(file.string());
    Scene scene = sceneAtFrame(file_scene, file_scene.animation.frames - 1);
    RenderOptions boxes = RenderOptions::fromScene(scene);
    boxes.width = 16;
    boxes.height = 12;
    boxes.spp = 1;
    boxes.aa.reset();
    boxes.accel = AccelKind::Bvh;
    boxes.bounds = BoundsKind::Aabb;
    RenderOptions kdop = boxes;
    kdop.bounds = BoundsKind::Kdop;
    RenderResult a = test::sharedRenderer().render(scene, boxes);
    RenderResult b = test::sharedRenderer().render(scene, kdop);
    REQUIRE(a.rgba.size() == 4u * 16 * 12);
    CHECK(std::all_of(a.rgba.begin(), a.rgba.end(), [](float x) { return std::isfinite(x); }));
    CHECK(std::any_of(a.primid.begin(), a.primid.end(), [](auto id) { return id >= 0; }));
    REQUIRE(b.rgba.size() == a.rgba.size());
    CHECK(std::memcmp(a.rgba.data(), b.rgba.data(), a.rgba.size() * sizeof(float)) == 0);
  }
}
