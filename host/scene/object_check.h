// Whether an analytic object's geometry can be rendered, after its transform
// has been baked in: shared by the scene loader (which adds the JSON path) and
// the C API, so both give the same rule and the same message. Meshes are
// checked by mesh validation, their transforms by transformProblem.
#pragma once

#include <string>

#include "scene/scene.h"

namespace prism {

// "" when the object is usable, else what is wrong with it, naming the field.
std::string objectProblem(const Object& object);

}  // namespace prism
