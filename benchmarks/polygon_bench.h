// `prism-bench polygons`: the speed of the three point-in-polygon tests
// (crossing, radial, left-right) on fields of polygons of 4 to 256 sides,
// convex and not, with the same rays through the same BVH, as ratios to the
// crossing test taken in one run, and whether they agree hit for hit.
#pragma once

#include <string>
#include <vector>

namespace prism::bench {

// `prism-bench polygons ARGS...` (args[0] is "polygons"): parses its options,
// runs, and returns the exit status (2 for a usage error).
int polygonMain(const std::vector<std::string>& args);

}  // namespace prism::bench
