// The acceleration structures prism offers (BVH, octree, BSP, or none) behind
// one interface: build one over the flattened primitives, get back the host
// arrays to upload, the kernel build options that select its traversal, and the
// statistics the benchmark and the render summary report.
// What is not here: uploading (accel_buffers.h) and the kernels (kernels/accel/).
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "accel/leaf_packets.h"
#include "kernels/shared/object_gpu.h"
#include "kernels/shared/tri_packet_gpu.h"

namespace prism {

// Auto stands for one of the others, chosen per scene by resolveAccelKind.
enum class AccelKind { None, Bvh, Octree, Bsp, Auto };

// Every structure (Auto is none), in the order the benchmark and the tests list them.
const std::vector<AccelKind>& allAccelKinds();
// "none", "bvh", "octree", "bsp", "auto".
const char* accelName(AccelKind kind);
// The kind named `name`; throws std::invalid_argument naming the valid names.
AccelKind parseAccelKind(const std::string& name);
// Same without throwing; false for an unknown name.
bool tryParseAccelKind(const std::string& name, AccelKind* kind);

struct AccelStats {
  double build_seconds = 0;    // building and flattening, host only
  std::size_t bytes = 0;       // device memory: nodes + leaf packets + unbounded list
  std::size_t node_count = 0;  // every node, inner and leaf (BVH: wide inner nodes + leaves)
  std::size_t leaf_count = 0;  // leaves holding at least one primitive
  std::size_t empty_leaf_count = 0;
  double mean_prims_per_leaf = 0;  // references / non-empty leaves
  // Surface area heuristic of the final structure, traversal and intersection
  // costs 1: sum over inner nodes of A(node)/A(root) + sum over leaves of
  // A(leaf)/A(root) * primitives, with A the node's box (BVH) or cell.
  double sah_cost = 0;
  std::size_t primitives = 0;  // bounded primitives in the structure
  std::size_t unbounded = 0;   // planes (and anything without finite bounds), tested for every ray
  std::size_t references = 0;  // primitive references in all leaves
  std::size_t straddling = 0;  // primitives referenced by more than one leaf
  double duplication = 1;      // references / primitives
  std::size_t exact_tests = 0;  // CGAL primitive/cell overlap tests the builder needed
  int max_depth = 0;
};

// Plain 16-byte word: the node buffer is one array of these, read as float4
// (and as the structure's own node type) by the kernels.
struct alignas(16) AccelWord {
  float v[4];
};

// What a build produces for the device. The buffers are the same list for
// every structure (kernels/accel/accel.h, ACCEL_PARAMS), so the renderer binds
// one set whichever is chosen.
struct DeviceAccel {
  AccelKind kind = AccelKind::None;
  // Build options for extend.cl / occlude.cl: -DPRISM_ACCEL_<KIND>, the
  // traversal stack depth this tree needs, and what the primitives ask
  // (primitiveKernelOptions: kMotionKernelOption, the kinds to compile).
  std::string kernel_options;
  // Of those, what the scene's primitives ask (primitiveKernelOptions), for
  // the other programs that read the geometry (the first-hit pass).
  std::string primitive_options;
  // Words 0 and 1: the scene box of the bounded primitives (lo xyz, hi xyz);
  // from word 2: the structure's nodes (BvhNodeGpu, OctreeNodeGpu, BspNodeGpu).
  std::vector<AccelWord> nodes;
  PacketVector packets;                    // leaf contents
  std::vector<std::int32_t> unbounded;     // object indices tested by every ray
  AccelStats stats;
};


struct AccelBuildOptions {
  int threads = 0;  // 0: std::thread::hardware_concurrency()
  // Octree: a cell splits while it holds more than octree_leaf_prims
  // primitives and its depth is below octree_max_depth, as long as its octants
  // hold at most octree_max_growth times its references (octree_builder.cpp).
  int octree_leaf_prims = 12;
  int octree_max_depth = 12;
  double octree_max_growth = 1.5;
  // BSP: split costs C_T + C_I (A_L N_L + A_R N_R) / A (times the empty bonus
  // when a side is empty) against C_I N for a leaf (bsp_builder.cpp). C_I is
  // per primitive: a 4-wide packet test costs about 0.6 of a node step on
  // PoCL, measured with prism-bench (docs/accel.md).
  double bsp_traversal_cost = 1.0;
  double bsp_intersection_cost = 0.15;
  double bsp_empty_bonus = 0.8;
  // BVH over moving primitives: nodes keep linear bounds (boxes at shutter open
  // and close, interpolated per ray); false keeps only the swept boxes, which
  // prism-bench distributed compares against.
  bool bvh_linear_bounds = true;
  // "Set of normals" slabs along the four diagonals (kdop_bounds.h); the
  // render option `bounds: kdop` sets both. kdop_objects: the analytic objects
  // in every structure's leaves are tested only where the ray meets their
  // slabs (object bounds); kdop_bvh: the BVH bounds its children by slabs as
  // well as by boxes.
  bool kdop_objects = false;
  bool kdop_bvh = false;
};

// Scenes of at most this many primitives are traced by brute force under
// `auto`: with a handful of objects, testing each costs less than any tree's
// set-up and node tests (measured in docs/accel.md, "Small scenes").
constexpr std::size_t kAutoBruteForcePrimitives = 4;

// The structure `kind` stands for over `objects`: itself, or for Auto, none up
// to kAutoBruteForcePrimitives primitives and the BVH above.
AccelKind resolveAccelKind(AccelKind kind, const std::vector<ObjectGpu>& objects);

// Builds `kind` (Auto resolved by resolveAccelKind; DeviceAccel::kind says
// which) over `objects` (the flattened scene, one entry per primitive;
// the index is the primitive id). Never fails on odd input: degenerate and
// non-finite primitives are kept so every structure answers like `none`.
std::unique_ptr<DeviceAccel> buildAccel(AccelKind kind, const std::vector<ObjectGpu>& objects,
                                        const AccelBuildOptions& options = {});

// One line for logs and the render summary: "bvh: 1234 nodes, ... ".
std::string describeAccel(const DeviceAccel& accel);

}  // namespace prism
