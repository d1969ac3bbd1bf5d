// `prism-bench firsthit`: primary visibility two ways on the same sample
// positions: the first-hit Z-buffer pass (render/firsthit.h: primitives binned
// into screen tiles on the host, one kernel over the samples) against primary rays
// traced through the BVH (extend), on the shared meshes from about 1k to 1M
// triangles. docs/sampling.md has a run's figures.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace prism::bench {

struct FirstHitBenchOptions {
  std::string device;                 // OpenCL device selector ("" = first GPU, else first device)
  std::vector<std::string> files;     // mesh files; empty = the shared benchmark ladder
  std::string data_dir;               // shared meshes folder
  std::string out_dir = "bench-out";  // firsthit.csv and firsthit.png go here
  int width = 1024, height = 1024;    // one primary sample per pixel, through the centre
  int repeats = 3;                    // timings are the median of this many runs
  std::string command;                // for the report
};

struct FirstHitRow {
  std::string scene;
  std::size_t triangles = 0;
  double bin_seconds = 0;       // Z-buffer set-up: binning on the host and upload
  double zbuffer_seconds = 0;   // the firsthit kernel over every sample
  double build_seconds = 0;     // trace set-up: BVH build on the host
  double trace_seconds = 0;     // the extend kernel over every primary ray
  double tile_size = 0;         // pixels per tile side
  double entries_per_tile = 0;  // mean candidates per tile (tile lists + global list)
  double agreement = 0;         // % of samples with the same primitive both ways
  double max_depth_error = 0;   // largest |t_zbuffer - t_trace| / t_trace where both hit the same primitive
};

std::vector<FirstHitRow> runFirstHitBench(const FirstHitBenchOptions& options);

// `prism-bench firsthit ARGS...` (args[0] is "firsthit"): parses its options,
// runs, and returns the exit status (2 for a usage error).
int firstHitMain(const std::vector<std::string>& args);

}  // namespace prism::bench
