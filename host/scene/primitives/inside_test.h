// The point-in-polygon tests a polygon may use (kernels/geometry/polygon.h):
// the crossing (Jordan curve) test, the radial (angle-sum) test and the
// left-right (same side of every edge) test, which needs a convex polygon.
// Set per polygon ("inside_test"), for every polygon at once (render.inside_test,
// --inside-test, PrismRenderOptions.inside_test).
#pragma once

#include <string>

#include "kernels/shared/object_gpu.h"

namespace prism {

enum class InsideTest { Crossing = POLYGON_CROSSING, Radial = POLYGON_RADIAL, LeftRight = POLYGON_LEFT_RIGHT };

constexpr const char* kInsideTestNames = "crossing, radial, left-right";

// False for an unknown name.
bool tryParseInsideTest(const std::string& name, InsideTest* test);
const char* insideTestName(InsideTest test);

}  // namespace prism
