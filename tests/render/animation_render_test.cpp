// An animation's frames render as the scenes they stand for: a frame equals,
// bit for bit, the scene written by hand with the shutter and the positions the
// closed form of linear motion gives for it (values exact in binary, so both
// scenes hold the same numbers).
#include <catch2/catch.hpp>

#include <string>

#include "render/renderer.h"
#include "scene/animation.h"
#include "scene_format/scene_loader.h"
#include "support/shared_context.h"

using namespace prism;
using namespace prism::test;

namespace {

// A sphere travelling from x = -2 to x = 2 in front of a plane, the camera
// rising from y = 0 to y = 2, over 4 frames `step` 1 apart with `shutter`.
std::string animated(const std::string& shutter, const std::string& frames) {
  return R"({
    "camera": {"position": [0, 0, 8], "look_at": [0, 0, 0], "fov": 40, "shutter": )" + shutter + R"(,
               "position_end": [0, 2, 8]},
    "film": {"width": 48, "height": 32, "spp": 4},
    "render": {"max_depth": 2},
    "lights": [{"position": [3, 5, 6], "intensity": 1}],
    "materials": {"mirror": {"diffuse": 0.3, "reflect": 0.5}},
    "animation": )" + frames + R"(,
    "objects": [{"type": "plane", "point": [0, -1, 0], "normal": [0, 1, 0]},
                {"type": "sphere", "center": [0, 0, 0], "radius": 0.75, "material": "mirror",
                 "transform": {"translate": [-2, 0, 0]}, "transform_end": {"translate": [2, 0, 0]}}]
  })";
}

// The same scene without an animation: the camera and sphere of one frame.
std::string byHand(const std::string& shutter, double y0, double y1, double x0, double x1, bool moving) {
  auto num = [](double v) { return std::to_string(v); };
  return R"({
    "camera": {"position": [0, )" + num(y0) + R"(, 8], "look_at": [0, 0, 0], "fov": 40, "shutter": )" + shutter +
         (moving ? R"(, "position_end": [0, )" + num(y1) + R"(, 8])" : "") + R"(},
    "film": {"width": 48, "height": 32, "spp": 4},
    "render": {"max_depth": 2},
    "lights": [{"position": [3, 5, 6], "intensity": 1}],
    "materials": {"mirror": {"diffuse": 0.3, "reflect": 0.5}},
    "objects": [{"type": "plane", "point": [0, -1, 0], "normal": [0, 1, 0]},
                {"type": "sphere", "center": [0, 0, 0], "radius": 0.75, "material": "mirror",
                 "transform": {"translate": [)" + num(x0) + R"(, 0, 0]})" +
         (moving ? R"(, "transform_end": {"translate": [)" + num(x1) + R"(, 0, 0]})" : "") + R"(}]
  })";
}

}  // namespace

TEST_CASE("an animation's frames render as the scenes written by hand for them", "[render][animation]") {
  SECTION("frames without a shutter interval: instants 0 to 4 of a path 4 long") {
    const Scene scene = parseScene(animated("[0, 0]", R"({"frames": 5})"), "anim.json");
    for (int f = 0; f < 5; ++f) {
      INFO("frame " << f);
      const double s = f / 4.0;
      const Scene hand = parseScene(byHand("[" + std::to_string(f) + ", " + std::to_string(f) + "]", 2 * s, 0,
                                           -2 + 4 * s, 0, false),
                                    "hand.json");
      const Scene frame = sceneAtFrame(scene, f);
      // Held still, a frame is a pinhole, which the Z-buffer can serve.
      RenderOptions opt = RenderOptions::fromScene(frame);
      opt.first_hit = FirstHitMode::ZBuffer;
      const RenderResult a = sharedRenderer().render(frame, opt);
      const RenderResult b = sharedRenderer().render(hand, opt);
      CHECK(a.rgba == b.rgba);
      CHECK(a.primid == b.primid);
    }
  }
  SECTION("frames back to back, each blurred over its own quarter of the path") {
    const Scene scene = parseScene(animated("[0, 1]", R"({"frames": 4, "step": 1})"), "anim.json");
    for (int f = 0; f < 4; ++f) {
      INFO("frame " << f);
      const double s0 = f / 4.0, s1 = (f + 1) / 4.0;
      const Scene hand = parseScene(byHand("[" + std::to_string(f) + ", " + std::to_string(f + 1) + "]", 2 * s0,
                                           2 * s1, -2 + 4 * s0, -2 + 4 * s1, true),
                                    "hand.json");
      const Scene frame = sceneAtFrame(scene, f);
      const RenderResult a = sharedRenderer().render(frame, RenderOptions::fromScene(frame));
      const RenderResult b = sharedRenderer().render(hand, RenderOptions::fromScene(hand));
      CHECK(a.rgba == b.rgba);
    }
    // And the frames differ: the sphere moves.
    const Scene first = sceneAtFrame(scene, 0), last = sceneAtFrame(scene, 3);
    CHECK(sharedRenderer().render(first, RenderOptions::fromScene(first)).rgba !=
          sharedRenderer().render(last, RenderOptions::fromScene(last)).rgba);
  }
}

TEST_CASE("a shutter that opens late blurs as finely as one that opens at 0", "[render][animation]") {
  // Frame 999,999 of an animation one time unit a frame: its shutter opens at
  // 999,999, where floats are 0.0625 apart; the device counts time from the
  // open, so the frame is the same image as the first one's piece of motion.
  const Scene late = parseScene(byHand("[999999, 999999.5]", 0, 0, -2, -1.5, true), "late.json");
  const Scene early = parseScene(byHand("[0, 0.5]", 0, 0, -2, -1.5, true), "early.json");
  const RenderResult a = sharedRenderer().render(late, RenderOptions::fromScene(late));
  const RenderResult b = sharedRenderer().render(early, RenderOptions::fromScene(early));
  CHECK(a.rgba == b.rgba);
}
