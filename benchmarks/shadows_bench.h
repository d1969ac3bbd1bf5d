// `prism-bench shadows`: point lights' shadow feelers through the light buffer
// against the acceleration structure (the BVH), on scenes from a handful of
// primitives to a million triangles: the light buffer's resolution, its mean
// list length and build time, the shade kernel's device time each way (it
// traces the feelers) as a ratio taken in one run, whether the images agree,
// and what --shadows auto picks.
#pragma once

#include <string>
#include <vector>

namespace prism::bench {

// `prism-bench shadows ARGS...` (args[0] is "shadows"): parses its options,
// runs, and returns the exit status (2 for a usage error).
int shadowsMain(const std::vector<std::string>& args);

}  // namespace prism::bench
