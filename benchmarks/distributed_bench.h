// `prism-bench distributed`: the cost of distributed ray tracing. Each effect's
// example scene (scenes/penumbra, glossy, dof, motion and cook, which has them
// all) rendered at 1 and at N samples per pixel: samples per second, rays per
// sample, and how much N spp costs against 1 spp; and the motion scene against
// the same scene held still (no shutter interval, primary rays traced either
// way). Ratios are taken in one run.
#pragma once

#include <string>
#include <vector>

namespace prism::bench {

// `prism-bench distributed ARGS...` (args[0] is "distributed"): parses its
// options, runs, and returns the exit status (2 for a usage error).
int distributedMain(const std::vector<std::string>& args);

}  // namespace prism::bench
