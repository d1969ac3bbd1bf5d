// A ray query's kernels for one acceleration structure, and which of them a
// queue of rays goes to. `extend` and `occlude` give each ray a work-item of
// its own; their `_packets` twins (kernels/accel/packet_queries.h) walk the
// BVH, the octree or the BSP with eight neighbouring rays at once. That pays
// for rays that travel alike, such as camera rays in sample order or the
// shadow rays of one shaded point, and costs for rays that do not (random
// rays run at about half the speed).
// On a GPU each work-item's eight lanes run one after another, so there the
// packets are never used. Both give the same answers to the bit on every ray
// the tests trace (tests/accel/accel_agreement_test.cpp; docs/accel.md,
// "Coherent rays in packets", names the grazing hit where the order of visits
// could still tell).
#pragma once

#include <cstddef>
#include <cstdint>

#include "accel/accel_structure.h"
#include "device/context.h"

namespace prism {

// Whether the rays of a queue travel alike: neighbours in it start near each
// other in nearly the same direction.
enum class RayCoherence { Scattered, Coherent };

// Rays a work-item of a `_packets` kernel walks with (PACKET_RAYS there).
constexpr std::size_t kPacketRays = 8;

// What a RayKernel answers: closest hits (extend.cl) or the light feelers
// carry (occlude.cl).
enum class RayQuery { ClosestHits, Transmittance };

// Packets pay while the scene's bounded primitives are at most
// packetPrimsPerRay(kind, query) per ray of the view (a frame's samples, a
// query's camera rays): with denser geometry, neighbouring rays part in
// different leaves. Measured with `prism-bench accel --packets always
// --structures bvh,bvh-1ray,octree,octree-1ray,bsp,bsp-1ray --camera N`
// (docs/accel.md, "Coherent rays in packets"), packets against one ray a
// work-item:
// - the BVH: camera rays 1.4x faster at 0.066 and 0.265 primitives a ray,
//   1.14-1.21x at 1.06, level at 2.1 and 0.8x at 4.2; shadow rays 1.28x at
//   0.066, level at 0.265, 0.64-0.81x at 1.06;
// - the octree, whose packets test one box a cell where one ray sorts the
//   octants it passes: camera rays 1.7x at 0.265, 1.35-1.48x at 1.06, 1.18x
//   at 2.1 and 0.94x at 4.2; shadow rays 0.92-1.54x at 0.066 (five runs),
//   1.17x at 0.265, 0.99-1.15x at 1.06, 0.89x at 2.1;
// - the BSP, whose packet descends as one with an interval a lane: camera rays
//   1.27-1.44x at 0.066, 1.50x at 0.265, 0.86x at 0.53, 0.96-0.98x at 1.06
//   and 2.1; shadow rays toward a point light 1.03-1.20x at 0.066, 0.88x at
//   0.265, 0.74-0.83x beyond.
// Each limit lies at or below where its rays break even by linear
// interpolation between the medians: the BVH's camera rays at about 2.1, its
// feelers at about 0.27; the octree's camera rays at about 3.6, its feelers
// at about 1.35 (one run of four measured 0.99 at 1.06); the BSP's camera
// rays at about 0.47. The BSP's feelers stay one ray a work-item (limit 0):
// a point's feelers toward an area light differ in sign, which the BSP's
// packet answers ray by ray (kernels/accel/bsp_packets.h), and toward a point
// light they gained 1.03-1.20x at best.
double packetPrimsPerRay(AccelKind kind, RayQuery query);

// Whether coherent rays through `accel` on `device` go in packets: through the
// octree, the BSP or the BVH (without linear motion bounds, whose boxes the
// packet walk reads at one instant, or k-DOP node bounds, whose slabs it does
// not test), on a CPU device.
bool packetsPay(const DeviceAccel& accel, const DeviceDescription& device);

// Where coherent rays go in packets: where they pay, on any device the
// structure allows (the tests check the packet walks on whatever device they
// run on), or nowhere (prism-bench's bvh-1ray, octree-1ray and bsp-1ray, the
// walks a GPU takes).
enum class PacketUse { WherePays, Always, Never };

class RayKernel {
 public:
  RayKernel() = default;
  // The single-ray kernel of `query`, and its `_packets` twin where `use` allows.
  RayKernel(Context& context, const DeviceAccel& accel, RayQuery query, PacketUse use = PacketUse::WherePays);

  // Whether rays of this coherence go in packets, `view_rays` rays sharing the
  // view (packetPrimsPerRay; PacketUse::Always: whatever their number).
  bool packets(RayCoherence coherence, std::uint64_t view_rays) const;
  // A launch: add the kernel's arguments, then run(workItems(rays, packets)).
  KernelLaunch launch(bool packets) const;
  std::size_t workItems(std::size_t rays, bool packets) const;
  bool hasPackets() const { return m_packets != nullptr; }

 private:
  Context* m_context = nullptr;
  cl_kernel m_single = nullptr, m_packets = nullptr;
  std::size_t m_primitives = 0;  // bounded ones, in the structure
  double m_prims_per_ray = 0;    // where packets stop paying (packetPrimsPerRay)
  PacketUse m_use = PacketUse::WherePays;
};

}  // namespace prism
