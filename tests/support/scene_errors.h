// Small helpers of the scene-format tests: the message a bad scene is refused
// with, substring tests, and vector comparison.
#pragma once

#include <cmath>
#include <string>

#include "scene/vec3.h"
#include "scene_format/scene_loader.h"

namespace prism::test {

// The message of the SceneError that parsing `json` throws, or "" if none.
inline std::string errorOf(const std::string& json) {
  try {
    parseScene(json, "bad.json");
  } catch (const SceneError& e) {
    return e.what();
  }
  return "";
}

inline bool contains(const std::string& haystack, const std::string& needle) {
  return haystack.find(needle) != std::string::npos;
}

inline bool near(const Vec3& a, const Vec3& b, double eps = 1e-12) {
  return std::fabs(a.x - b.x) <= eps && std::fabs(a.y - b.y) <= eps && std::fabs(a.z - b.z) <= eps;
}

}  // namespace prism::test
