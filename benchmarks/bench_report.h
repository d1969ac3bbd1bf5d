// The rows prism-bench measures and the three ways it reports them: a table
// on stdout (a row as soon as it is measured), CSV and JSON files.
#pragma once

#include <cmath>
#include <cstddef>
#include <ostream>
#include <string>
#include <vector>

namespace prism::bench {

constexpr double kNaN = NAN;

// One structure (or Embree) on one scene. NaN: not measured / not applicable.
struct BenchRow {
  std::string scene;
  std::size_t triangles = 0;    // triangles (primitives) in the scene
  std::string structure;        // bvh, octree, bsp, none, embree
  double build_seconds = kNaN;  // host build, or Embree's rtcCommitScene
  double bytes_per_triangle = kNaN;
  double nodes = kNaN, leaves = kNaN, prims_per_leaf = kNaN, sah = kNaN, duplication = kNaN;
  double primary_mrays = kNaN, shadow_mrays = kNaN, random_mrays = kNaN;
  // This row against Embree's in the same run: throughput ratios (> 1 faster
  // than Embree) and build-time ratio (> 1 slower than Embree).
  double primary_ratio = kNaN, shadow_ratio = kNaN, random_ratio = kNaN, build_ratio = kNaN;
  double agreement = kNaN;  // % of primary rays with the same primitive as Embree (or as the BVH)
  // BVH rows: wide nodes and leaves per ray whose bounds meet the ray before
  // its closest hit (workloads' bvhNodeVisits), camera and random rays.
  double visits_primary = kNaN, visits_random = kNaN;
  double objects_primary = kNaN;  // analytic objects tested per camera ray (the same walk)
};

struct BenchMeta {
  std::string command;  // the command line, for reproducing
  std::string device;   // OpenCL device name and driver
  int embree_threads = 0;
  int camera_width = 0, camera_height = 0;
  std::size_t random_rays = 0;
  int repeats = 0;
};

void printTableHeader(std::ostream& out);
void printTableRow(std::ostream& out, const BenchRow& row);

void writeCsv(const std::string& path, const std::vector<BenchRow>& rows);
void writeJson(const std::string& path, const BenchMeta& meta, const std::vector<BenchRow>& rows);

}  // namespace prism::bench
