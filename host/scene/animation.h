// An animation: a sequence of frames whose shutters follow one another by a
// fixed step, over which the moving objects and camera travel once.
//
// The motion of a scene (an object's `transform` to `transform_end`, the
// camera's `position`/`look_at` to `position_end`/`look_at_end`) spans the
// whole animation: from the first frame's shutter open to the last frame's
// shutter close. Each frame is then an ordinary scene whose motion is the piece
// of that path inside its own shutter, so the renderer, the structures and the
// kernels know nothing of frames. With one frame the motion spans the shutter,
// as it always has.
#pragma once

#include <cstdint>
#include <string>

#include "scene/scene.h"

namespace prism {

constexpr int kMaxAnimationFrames = 1000000;

// "" when the animation fits the scene, else what is wrong with it: frames in
// [1, kMaxAnimationFrames], a positive finite step, and the last frame's
// shutter within the camera's limits. Shared by the loader and sceneAtFrame.
std::string animationProblem(const Scene& scene);

// The motion's parameter (0 at the first frame's open, 1 at the last frame's
// close) at time `t`; 0 throughout when the span has no length.
double animationPhase(const Scene& scene, double t);

// Frame `frame` (0-based, below scene.animation.frames) as a scene of one frame:
// the shutter moved by frame x step, objects and camera placed on their path at
// the new shutter's open and close (interpolated as scene/motion.h does, which
// is the kernels' interpolation, so the piece follows the whole path); a frame
// whose shutter has no length holds them still at its instant. With one frame,
// the scene unchanged. Throws std::invalid_argument for a frame out of range, or
// when the camera cannot form an image at this frame.
Scene sceneAtFrame(const Scene& scene, std::uint32_t frame);

// use(scene) for a still, use(its frame 0) for an animation: what the C API
// renders and queries when handed a whole animation (prismGetFrameScene gives
// the other frames). A still is passed as it is, not copied.
template <typename Use>
auto withFirstFrame(const Scene& scene, Use&& use) {
  if (scene.animation.frames > 1) return use(sceneAtFrame(scene, 0));
  return use(scene);
}

}  // namespace prism
