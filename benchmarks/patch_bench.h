// `prism-bench patches`: the two ways of ray tracing bicubic Bezier patches —
// successive subdivision into triangles at several tolerances, and Newton
// iteration on patch pieces — on the same rays through the same BVH: their
// primitives, set-up and build time, speed (as ratios to the analytic
// method, taken in one run) and accuracy against successive subdivision
// along each ray in double.
#pragma once

#include <string>
#include <vector>

namespace prism::bench {

// `prism-bench patches ARGS...` (args[0] is "patches"): parses its options,
// runs, and returns the exit status (2 for a usage error).
int patchMain(const std::vector<std::string>& args);

}  // namespace prism::bench
