#include "scene/camera_check.h"

#include <cmath>
#include <utility>

#include "scene/value_check.h"

namespace prism {

std::string cameraProblem(const Camera& c) {
  // Points where the objects' coordinates may be (value_check.h); the up
  // direction is only a direction.
  for (auto [v, name] : {std::pair{&c.position, "position"}, std::pair{&c.look_at, "look_at"}}) {
    const std::string p = vectorProblem(*v, name);
    if (!p.empty()) return p;
  }
  if (!std::isfinite(c.up.x) || !std::isfinite(c.up.y) || !std::isfinite(c.up.z)) return "up must be finite";
  if (!(c.fov > 0 && c.fov < 180)) return "fov must be in (0, 180) degrees, got " + std::to_string(c.fov);
  const Vec3 view = c.look_at - c.position;
  if (view == Vec3()) return "the camera's position and look_at point are the same";
  if (c.up == Vec3() || !(length(cross(unitVector(c.up), unitVector(view))) > 1e-9))
    return "the camera's up direction is parallel to its view direction";
  if (!(std::isfinite(c.aperture) && c.aperture >= 0 && c.aperture <= 1e15))
    return "aperture (the lens radius) must be a number in [0, 1e15], got " + std::to_string(c.aperture);
  if (!(std::isfinite(c.focus_distance) && c.focus_distance >= 0 && c.focus_distance <= 1e15))
    return "focus_distance must be a positive number of at most 1e15 (0: the distance to look_at), got " +
           std::to_string(c.focus_distance);
  if (!std::isfinite(c.shutter_open) || !std::isfinite(c.shutter_close) || std::fabs(c.shutter_open) > 1e15 ||
      std::fabs(c.shutter_close) > 1e15)
    return "the shutter times must be finite numbers of at most 1e15 in magnitude";
  if (c.shutter_close < c.shutter_open)
    return "the shutter must close no earlier than it opens, got [" + std::to_string(c.shutter_open) + ", " +
           std::to_string(c.shutter_close) + "]";
  if (c.moving) {
    for (auto [v, name] : {std::pair{&c.position_end, "position_end"}, std::pair{&c.look_at_end, "look_at_end"}}) {
      const std::string p = vectorProblem(*v, name);
      if (!p.empty()) return p;
    }
    const Vec3 view_end = c.look_at_end - c.position_end;
    if (view_end == Vec3()) return "the camera's position_end and look_at_end are the same";
    if (!(length(cross(unitVector(c.up), unitVector(view_end))) > 1e-9))
      return "the camera's up direction is parallel to its view direction at shutter close";
  }
  return "";
}

}  // namespace prism
