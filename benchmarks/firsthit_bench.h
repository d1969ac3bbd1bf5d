// `prism-bench firsthit`: primary visibility two ways on the same sample
// positions: the first-hit Z-buffer pass (render/firsthit.h: samples sorted by
// pixel, primitives projected and scan-converted on the device) against primary rays
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
  std::string data_dir;               // --data: searched first for the ladder (bench_data.h)
  std::string out_dir = "bench-out";  // firsthit.csv and firsthit.png go here
  int width = 1024, height = 1024;    // the film
  int spp = 1;                        // samples per pixel, in pixel order: the centre, or a grid over the pixel
  int repeats = 3;                    // timings are the median of this many runs
  bool profile = false;               // print the z-buffer's kernel times
  std::string command;                // for the report
};

struct FirstHitRow {
  std::string scene;
  std::size_t triangles = 0;
  std::size_t samples = 0;      // film pixels x samples per pixel
  double setup_seconds = 0;     // Z-buffer set-up on the host: FirstHitPass::prepare
  double zbuffer_seconds = 0;   // the whole pass on the device: sort, bound, raster, resolve
  double build_seconds = 0;     // trace set-up: BVH build on the host
  double trace_seconds = 0;     // the extend kernel over every primary ray
  double pairs_per_prim = 0;    // (primitive, 8x8-pixel block) pairs rasterised per primitive
  double agreement = 0;         // % of samples with the same primitive both ways
  double identical = 0;         // % of samples whose hit (primitive, t, u, v) is the same bits both ways
  double max_depth_error = 0;   // largest |t_zbuffer - t_trace| / t_trace where both hit the same primitive
};

std::vector<FirstHitRow> runFirstHitBench(const FirstHitBenchOptions& options);

// `prism-bench firsthit ARGS...` (args[0] is "firsthit"): parses its options,
// runs, and returns the exit status (2 for a usage error).
int firstHitMain(const std::vector<std::string>& args);

}  // namespace prism::bench
