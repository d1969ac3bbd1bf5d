// `prism-bench devices`: one frame over several OpenCL devices against each
// device alone, taken in turns in one run: each device's solo throughput, the
// frame's throughput over all of them, that against the sum of the solos (the
// goal where devices do not share hardware) and against the fastest solo (the
// goal where they do, as several PoCL devices on one CPU), how the units were
// shared, and whether the images are the same bit for bit.
#pragma once

#include <string>
#include <vector>

namespace prism::bench {

// `prism-bench devices ARGS...` (args[0] is "devices"): parses its options,
// runs, and returns the exit status (2 for a usage error).
int devicesMain(const std::vector<std::string>& args);

}  // namespace prism::bench
