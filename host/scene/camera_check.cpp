#include "scene/camera_check.h"

#include <cmath>

namespace prism {

std::string cameraProblem(const Camera& c) {
  for (const Vec3* v : {&c.position, &c.look_at, &c.up})
    if (!std::isfinite(v->x) || !std::isfinite(v->y) || !std::isfinite(v->z)) return "camera values must be finite";
  if (!(c.fov > 0 && c.fov < 180)) return "fov must be in (0, 180) degrees, got " + std::to_string(c.fov);
  const Vec3 view = c.look_at - c.position;
  if (view == Vec3()) return "the camera's position and look_at point are the same";
  if (c.up == Vec3() || !(length(cross(normalize(c.up), normalize(view))) > 1e-9))
    return "the camera's up direction is parallel to its view direction";
  return "";
}

}  // namespace prism
