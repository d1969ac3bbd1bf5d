// How the C API's building calls speak to the scene loader: a caller's floats as
// scene-format JSON, a fragment checked by the loader with a refusal reported as
// the caller's bad argument, and the model's values back as a caller's floats.
#pragma once

#include <nlohmann/json.hpp>

#include "scene/scene.h"

namespace prism {

inline nlohmann::json jsonTriple(const float* v) { return nlohmann::json::array({v[0], v[1], v[2]}); }

inline void putVec3(float* out, const Vec3& v) {
  out[0] = static_cast<float>(v.x), out[1] = static_cast<float>(v.y), out[2] = static_cast<float>(v.z);
}

// addSceneFragment for a typed call: a refused value is the caller's argument
// (std::invalid_argument with the loader's message), not a malformed document.
void addCallFragment(Scene& scene, const nlohmann::json& fragment);

}  // namespace prism
