// Whether a camera can form an image; shared by the C API and the CLI's camera
// overrides (the scene loader reports the same problems with JSON paths).
#pragma once

#include <string>

#include "scene/scene.h"

namespace prism {

// "" when the camera is usable, else what is wrong with it.
std::string cameraProblem(const Camera& camera);

}  // namespace prism
