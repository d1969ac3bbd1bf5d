// Whether a light can be rendered; shared by the scene loader (which adds the
// JSON path) and the C API, so both give the same rule and the same message.
#pragma once

#include <cstddef>
#include <string>

#include "scene/scene.h"

namespace prism {

// The most shadow feelers per pixel a light may ask for.
constexpr int kMaxLightSamples = 4096;

// "" when the light is usable, else what is wrong with it, naming the field.
std::string lightProblem(const Light& light);

// The brightest component of color x intensity, of one light and of all the
// scene's lights together: a shaded point sums what every light gives it, so
// the sum, not each light alone, must stay within kMaxBrightness.
constexpr double kMaxBrightness = 1e30;
double lightBrightness(const Light& light);
// "" when the brightness of `count` lights summed, `total`, is within kMaxBrightness.
std::string lightsTogetherProblem(double total, std::size_t count);

// "point", "quad", "disk", "sphere".
const char* lightTypeName(LightType type);

}  // namespace prism
