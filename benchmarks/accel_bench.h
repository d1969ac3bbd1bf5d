// `prism-bench accel`: every acceleration structure on every scene (the shared
// meshes, generated bumpy tori from 1k to 1M triangles, or the files given),
// timed against Embree on the same rays in the same run.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "accel/accel_structure.h"
#include "bench_report.h"

namespace prism::bench {

struct AccelBenchOptions {
  std::string device;                 // --device: OpenCL device selector ("" = first GPU, else first device)
  std::vector<std::string> files;     // mesh files or JSON scenes; empty = the shared benchmark ladder
  std::vector<std::size_t> sizes;     // generated tori (triangles)
  bool sizes_given = false;
  std::string data_dir;               // --data: searched first for the ladder (bench_data.h)
  std::string out_dir = "bench-out";  // CSV, JSON and PNG go here
  std::vector<AccelKind> structures = {AccelKind::Bvh, AccelKind::Octree, AccelKind::Bsp};
  bool bvh_kdop = false;          // a BVH with "set of normals" bounds too (--structures bvh-kdop)
  bool bvh_kdop_objects = false;  // ... on the objects alone, not the nodes (--structures bvh-kobj)
  // structures walked one ray a work-item on every column (--structures bvh-1ray,octree-1ray,bsp-1ray)
  std::vector<AccelKind> one_ray;
  bool packets_always = false;  // --packets always: the density limits lifted (PacketUse::Always)
  int camera = 1024;                  // primary rays: camera x camera
  std::size_t random_rays = std::size_t(1) << 20;
  int repeats = 3;                    // timings are the median of this many runs
  bool embree = true;
  // Embree's packets as a contender too (--structures embree-8): rtcIntersect8 /
  // rtcOccluded8 on the camera and shadow rays, rtcIntersect1 on random rays.
  bool embree_packets = false;
  std::string command;                // for the report
};

// Runs the benchmark, printing the table as it goes; returns the rows (also
// written to out_dir). Throws on unusable input (the message names the file).
std::vector<BenchRow> runAccelBench(const AccelBenchOptions& options);

}  // namespace prism::bench
