// Double-precision reference intersections, written independently of the
// kernels (textbook forms, not the kernels' numerically tuned ones), for checking
// the device's float results. Each kind's own lives with the kind
// (scene/primitives/<kind>.cpp, PrimitiveKind::reference); this adds transforms.
#pragma once

#include <optional>

#include "scene/scene.h"

namespace prism::test {

struct RefRay {
  Vec3 o, d;
  double tmin = 0, tmax = 1e30;
};

// Nearest t in (tmin, tmax) where the ray meets the object, honouring its transform.
std::optional<double> referenceIntersect(const Object& object, const RefRay& ray);

// The same object grown (scale > 1) or shrunk (scale < 1) about its centre by a
// relative amount; a ray whose hit/miss answer differs between the grown and the
// shrunk object passes too close to an edge for float and double to be compared.
// A plane is shifted along its normal by (scale - 1) * (1 + |point|) instead.
Object scaledAboutCentre(const Object& object, double scale);

}  // namespace prism::test
