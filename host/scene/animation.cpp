#include "scene/animation.h"

#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "scene/camera_check.h"
#include "scene/mesh_objects.h"
#include "scene/motion.h"
#include "scene/primitives/primitive_kind.h"
#include "scene/transform.h"

namespace prism {

namespace {

Vec3 along(const Vec3& a, const Vec3& b, double s) { return a + (b - a) * s; }

double frameOpen(const Scene& scene, int frame) { return scene.camera.shutter_open + frame * scene.animation.step; }
double frameClose(const Scene& scene, int frame) { return scene.camera.shutter_close + frame * scene.animation.step; }

std::string shortNumber(double x) {
  std::ostringstream text;
  text << x;
  return text.str();
}

}  // namespace

std::string animationProblem(const Scene& scene) {
  const Animation& a = scene.animation;
  if (a.frames < 1 || a.frames > kMaxAnimationFrames)
    return "animation.frames must be an integer in [1, " + std::to_string(kMaxAnimationFrames) + "], got " +
           std::to_string(a.frames);
  if (!(std::isfinite(a.step) && a.step > 0 && a.step <= 1e15))
    return "animation.step must be a time > 0 and at most 1e15, got " + shortNumber(a.step);
  const double last_open = frameOpen(scene, a.frames - 1), last_close = frameClose(scene, a.frames - 1);
  if (!(std::fabs(last_open) <= 1e15 && std::fabs(last_close) <= 1e15))
    return "the last frame's shutter, [" + shortNumber(last_open) + ", " + shortNumber(last_close) +
           "], goes past 1e15 (fewer frames or a shorter animation.step)";
  return "";
}

double animationPhase(const Scene& scene, double t) {
  const double start = frameOpen(scene, 0), end = frameClose(scene, scene.animation.frames - 1);
  return end > start ? (t - start) / (end - start) : 0.0;
}

Scene sceneAtFrame(const Scene& scene, std::uint32_t frame_number) {
  const int frames = scene.animation.frames;
  if (frames < 1 || frame_number >= static_cast<std::uint32_t>(frames))
    throw std::invalid_argument("frame " + std::to_string(frame_number) + " is not in the animation (frames 0 to " +
                                std::to_string(frames - 1) + ")");
  const int frame = static_cast<int>(frame_number);  // below frames, an int
  if (const std::string problem = animationProblem(scene); !problem.empty()) throw std::invalid_argument(problem);
  if (frames == 1) return scene;
  Scene out = scene;
  out.animation = Animation{};
  Camera& camera = out.camera;
  camera.shutter_open = frameOpen(scene, frame);
  camera.shutter_close = frameClose(scene, frame);
  const double s_open = animationPhase(scene, camera.shutter_open);
  const double s_close = animationPhase(scene, camera.shutter_close);
  // A shutter of no length holds everything still at its instant.
  const bool blurred = camera.hasShutterInterval();

  const Camera& path = scene.camera;
  if (path.moving) {
    camera.position = along(path.position, path.position_end, s_open);
    camera.look_at = along(path.look_at, path.look_at_end, s_open);
    camera.moving = blurred;
    camera.position_end = along(path.position, path.position_end, s_close);
    camera.look_at_end = along(path.look_at, path.look_at_end, s_close);
  }
  if (const std::string problem = cameraProblem(camera); !problem.empty())
    throw std::invalid_argument("frame " + std::to_string(frame) + " of the animation: " + problem);
  for (std::size_t i = 0; i < out.objects.size(); ++i) {
    Object& ob = out.objects[i];
    if (!ob.moving) continue;
    const DecomposedTransform start = decompose(ob.transform), end = decompose(ob.transform_end);
    ob.transform = interpolate(start, end, s_open);
    ob.transform_end = interpolate(start, end, s_close);
    ob.moving = blurred;
    // The path may pass through a transform neither end is (a scale from 1 to
    // -1 crosses 0).
    for (const Transform* t : {&ob.transform, &ob.transform_end}) {
      if (t == &ob.transform_end && !blurred) break;
      if (const std::string problem = transformProblem(*t); !problem.empty())
        throw std::invalid_argument("frame " + std::to_string(frame) + " of the animation: objects[" +
                                    std::to_string(i) + "]: its transform there: " + problem);
    }
    if (blurred) continue;
    if (ob.type == ObjectType::Mesh) {  // placed by the flattening where the frame holds it
      if (const std::string problem = meshPlacementProblem(*ob.mesh, ob.transform, nullptr, "transform at this frame");
          !problem.empty())
        throw std::invalid_argument("frame " + std::to_string(frame) + " of the animation: objects[" +
                                    std::to_string(i) + "]: " + problem);
      continue;
    }
    // Held still, it is what the loader makes of a static object: the kinds the
    // kernels keep in world space take the transform into their geometry.
    const PrimitiveKind& kind = primitiveKind(ob.type);
    if (kind.bake && !ob.transform.isIdentity()) {
      kind.bake(ob);
      ob.transform = Transform::identity();
    }
    const std::string problem = kind.problem(ob);
    if (!problem.empty())
      throw std::invalid_argument("frame " + std::to_string(frame) + " of the animation: objects[" +
                                  std::to_string(i) + "]: " + problem);
  }
  return out;
}

}  // namespace prism
