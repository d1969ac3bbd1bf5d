#include "accel/accel_structure.h"

#include <chrono>
#include <stdexcept>

#include "accel/builders.h"

namespace prism {
namespace {

struct AccelEntry {
  AccelKind kind;
  const char* name;
  void (*build)(const std::vector<ObjectGpu>&, const PrimitiveSet&, const AccelBuildOptions&, DeviceAccel&);
};

void buildNone(const std::vector<ObjectGpu>&, const PrimitiveSet&, const AccelBuildOptions&, DeviceAccel& out) {
  out.kernel_options = "-DPRISM_ACCEL_NONE";
}

// The explicit name -> builder table (STYLE 7.6 habit 7).
const AccelEntry kAccels[] = {
    {AccelKind::Bvh, "bvh", buildBvh},
    {AccelKind::Octree, "octree", buildOctree},
    {AccelKind::Bsp, "bsp", buildBsp},
    {AccelKind::None, "none", buildNone},
    {AccelKind::Auto, "auto", nullptr},  // resolved before building
};

const AccelEntry& entry(AccelKind kind) {
  for (const AccelEntry& e : kAccels)
    if (e.kind == kind) return e;
  throw std::invalid_argument("unknown acceleration structure " + std::to_string(static_cast<int>(kind)));
}

}  // namespace

const std::vector<AccelKind>& allAccelKinds() {
  static const std::vector<AccelKind> kinds = {AccelKind::Bvh, AccelKind::Octree, AccelKind::Bsp, AccelKind::None};
  return kinds;
}

const char* accelName(AccelKind kind) { return entry(kind).name; }

bool tryParseAccelKind(const std::string& name, AccelKind* kind) {
  for (const AccelEntry& e : kAccels)
    if (name == e.name) {
      *kind = e.kind;
      return true;
    }
  return false;
}

AccelKind parseAccelKind(const std::string& name) {
  AccelKind kind;
  if (tryParseAccelKind(name, &kind)) return kind;
  std::string valid;
  for (const AccelEntry& e : kAccels) valid += std::string(valid.empty() ? "" : ", ") + e.name;
  throw std::invalid_argument("unknown acceleration structure '" + name + "' (expected one of: " + valid + ")");
}

void writeSceneHeader(const Aabb& scene, DeviceAccel& out) {
  out.nodes.clear();
  out.nodes.push_back(AccelWord{{scene.lo[0], scene.lo[1], scene.lo[2], 0}});
  out.nodes.push_back(AccelWord{{scene.hi[0], scene.hi[1], scene.hi[2], 0}});
}

std::string stackOption(int entries) {
  // Rounded up to a multiple of 32, so most scenes share one compiled program.
  int rounded = (std::max(entries, 1) + 31) / 32 * 32;
  return "-DPRISM_ACCEL_STACK=" + std::to_string(rounded);
}

void finishReferenceStats(const std::vector<int>& refs_per_prim, AccelStats& stats) {
  std::size_t refs = 0, straddling = 0;
  for (int r : refs_per_prim) {
    refs += static_cast<std::size_t>(r);
    if (r > 1) ++straddling;
  }
  stats.references = refs;
  stats.straddling = straddling;
  stats.duplication = refs_per_prim.empty() ? 1.0 : double(refs) / double(refs_per_prim.size());
  stats.mean_prims_per_leaf = stats.leaf_count ? double(refs) / double(stats.leaf_count) : 0.0;
}

AccelKind resolveAccelKind(AccelKind kind, const std::vector<ObjectGpu>& objects) {
  if (kind != AccelKind::Auto) return kind;
  return primitiveCount(objects) <= kAutoBruteForcePrimitives ? AccelKind::None : AccelKind::Bvh;
}

std::unique_ptr<DeviceAccel> buildAccel(AccelKind kind, const std::vector<ObjectGpu>& objects,
                                        const AccelBuildOptions& options) {
  kind = resolveAccelKind(kind, objects);
  const AccelEntry& e = entry(kind);
  auto start = std::chrono::steady_clock::now();
  auto accel = std::make_unique<DeviceAccel>();
  accel->kind = kind;
  if (kind == AccelKind::None) {
    // Brute force needs no tree: every primitive, planes included, is tested
    // (not the motion and data records after them).
    e.build(objects, PrimitiveSet{}, options, *accel);
    const std::size_t primitives = primitiveCount(objects);
    accel->stats.primitives = primitives;
    accel->stats.references = primitives;
    accel->stats.leaf_count = primitives == 0 ? 0 : 1;
    accel->stats.node_count = accel->stats.leaf_count;
    accel->stats.mean_prims_per_leaf = static_cast<double>(primitives);
    accel->stats.sah_cost = static_cast<double>(primitives);
    writeSceneHeader(Aabb(), *accel);
    accel->primitive_options = primitiveKernelOptions(objects);
    accel->kernel_options += " " + accel->primitive_options;
  } else {
    PrimitiveSet prims = gatherPrimitives(objects, options.threads);
    e.build(objects, prims, options, *accel);
    // Moving objects' code is compiled only into the programs of scenes that
    // have some, and so is each larger kind's (quadrics, polygons, polyhedra, patches).
    accel->primitive_options = primitiveKernelOptions(prims.kinds, prims.any_moving);
    accel->kernel_options += " " + accel->primitive_options;
    accel->unbounded = prims.unbounded;
    accel->stats.primitives = prims.bounded.size();
    accel->stats.unbounded = prims.unbounded.size();
  }
  if (options.kdop_objects && kind != AccelKind::None) accel->kernel_options += " -DPRISM_OBJECT_KDOP";
  accel->stats.bytes = accel->nodes.size() * sizeof(AccelWord) + accel->packets.size() * sizeof(TriPacketGpu) +
                       accel->unbounded.size() * sizeof(std::int32_t);
  accel->stats.build_seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return accel;
}

std::string describeAccel(const DeviceAccel& accel) {
  const AccelStats& s = accel.stats;
  char line[512];
  std::snprintf(line, sizeof line,
                "%s: %zu primitives (+%zu unbounded), built in %.3f s, %.1f MB, %zu nodes, %zu leaves, "
                "%.2f prims/leaf, SAH %.2f, duplication %.2f (%zu straddling), depth %d",
                accelName(accel.kind), s.primitives, s.unbounded, s.build_seconds, s.bytes / 1e6, s.node_count,
                s.leaf_count, s.mean_prims_per_leaf, s.sah_cost, s.duplication, s.straddling, s.max_depth);
  return line;
}

}  // namespace prism
