// Whether a light can be rendered; shared by the scene loader (which adds the
// JSON path) and the C API, so both give the same rule and the same message.
#pragma once

#include <string>

#include "scene/scene.h"

namespace prism {

// The most shadow feelers per pixel a light may ask for.
constexpr int kMaxLightSamples = 4096;

// "" when the light is usable, else what is wrong with it, naming the field.
std::string lightProblem(const Light& light);

// "point", "quad", "disk", "sphere".
const char* lightTypeName(LightType type);

}  // namespace prism
