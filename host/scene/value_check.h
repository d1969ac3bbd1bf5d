// The float-range rules every checked value follows, shared by the checks of
// lights, objects and the rest (scene/light_check.h, scene/primitives/<kind>.cpp):
// what the kernels compute from a value must fit in float, and lengths are
// squared and multiplied by areas there, so coordinates stay well inside it.
#pragma once

#include <string>

#include "scene/vec3.h"

namespace prism {

constexpr double kMaxCoordinate = 1e15;

// "" when every coordinate of v is finite and at most kMaxCoordinate in
// magnitude, else "NAME must be finite" or "NAME must have coordinates of at
// most 1e15 in magnitude".
std::string vectorProblem(const Vec3& v, const char* name);

}  // namespace prism
