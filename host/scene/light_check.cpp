#include "scene/light_check.h"

#include <cmath>
#include <utility>

#include "scene/value_check.h"

namespace prism {

const char* lightTypeName(LightType type) {
  switch (type) {
    case LightType::Point: return "point";
    case LightType::Quad: return "quad";
    case LightType::Disk: return "disk";
    case LightType::Sphere: return "sphere";
  }
  return "?";
}

double lightBrightness(const Light& l) { return std::fmax(l.color.x, std::fmax(l.color.y, l.color.z)) * l.intensity; }

std::string lightsTogetherProblem(double total, std::size_t count) {
  if (total <= kMaxBrightness) return "";
  return "color x intensity summed over the scene's " + std::to_string(count) +
         " lights must be at most 1e30 (float range: a point sums what every light gives it)";
}

std::string lightProblem(const Light& l) {
  std::string p = vectorProblem(l.color, "color");
  if (!p.empty()) return p;
  if (l.color.x < 0 || l.color.y < 0 || l.color.z < 0) return "color must be non-negative";
  if (!(std::isfinite(l.intensity) && l.intensity >= 0)) return "intensity must be a non-negative number";
  if (!(lightBrightness(l) <= kMaxBrightness)) return "color x intensity must be at most 1e30 (float range)";
  if (l.samples < 1 || l.samples > kMaxLightSamples)
    return "samples must be an integer in [1, " + std::to_string(kMaxLightSamples) + "]";
  switch (l.type) {
    case LightType::Point:
      return vectorProblem(l.position, "position");
    case LightType::Quad: {
      for (auto [v, name] : {std::pair{&l.corner, "corner"}, {&l.edge1, "edge1"}, {&l.edge2, "edge2"}})
        if (!(p = vectorProblem(*v, name)).empty()) return p;
      const Vec3 n = cross(l.edge1, l.edge2);
      // sin(angle between the edges) under 1e-9: no usable area.
      if (!(length(n) > 1e-9 * length(l.edge1) * length(l.edge2)))
        return "edge1 and edge2 must be non-zero and not parallel (the quad has no area)";
      return "";
    }
    case LightType::Disk:
      if (!(p = vectorProblem(l.center, "center")).empty()) return p;
      if (!(p = vectorProblem(l.normal, "normal")).empty()) return p;
      if (l.normal == Vec3()) return "normal must be a non-zero vector";
      if (!(std::isfinite(l.radius) && l.radius > 0 && l.radius <= kMaxCoordinate))
        return "radius must be a positive number of at most 1e15";
      return "";
    case LightType::Sphere:
      if (!(p = vectorProblem(l.center, "center")).empty()) return p;
      if (!(std::isfinite(l.radius) && l.radius > 0 && l.radius <= kMaxCoordinate))
        return "radius must be a positive number of at most 1e15";
      return "";
  }
  return "";
}

}  // namespace prism
