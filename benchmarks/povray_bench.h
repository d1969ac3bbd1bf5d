// `prism-bench povray`: the classic Whitted scene (scenes/whitted.json: a
// checkered plane, a mirror and a glass sphere, two point lights) rendered by
// prism and by POV-Ray 3.7 (benchmarks/povray/whitted.pov, the same scene term
// for term) at the same size, depth and weight cut-off, on as many threads as
// the OpenCL device has compute units. It reports POV-Ray's trace time over
// prism's render time, each the median of runs taken in turns, and how far the
// two images are apart.
#pragma once

#include <string>
#include <vector>

namespace prism::bench {

// `prism-bench povray ARGS...` (args[0] is "povray"): parses its options,
// runs, and returns the exit status (2 for a usage error; 0 with a message
// when POV-Ray is not installed).
int povrayMain(const std::vector<std::string>& args);

}  // namespace prism::bench
