// Writes a leaf's primitives as TriPacketGpu packets (kernels/shared/tri_packet_gpu.h):
// triangles first, four to a packet, then the other bounded primitives, which
// the kernels test one by one through prim_intersect (with their diagonal
// slabs in their lanes, for k-DOP object bounds).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "accel/uninitialised_vector.h"
#include "kernels/shared/object_gpu.h"
#include "kernels/shared/tri_packet_gpu.h"

namespace prism {

struct PacketRange {
  std::uint32_t start = 0;
  std::uint32_t count = 0;
};

// A structure's packets, which its builder's threads may write in place
// (uninitialised_vector.h).
using PacketVector = UninitialisedVector<TriPacketGpu>;

// Appends the leaf's packets to `out` and returns where they are.
PacketRange appendLeafPackets(const std::vector<ObjectGpu>& objects, const std::int32_t* ids, std::size_t n,
                              PacketVector& out);

// Writes a leaf of n packet triangles (isPacketTriangle, every one) to out,
// four to a packet, as appendLeafPackets would: ceil(n / 4) packets.
void writeTrianglePackets(const std::vector<ObjectGpu>& objects, const std::int32_t* ids, std::size_t n,
                          TriPacketGpu* out);

// A packet-friendly triangle: stored in world space, intersected by the
// vectorised Moller-Trumbore test.
inline bool isPacketTriangle(const ObjectGpu& ob) { return ob.type == OBJECT_TRIANGLE && !ob.has_transform; }

// A moving triangle (object space): it shares packets with the triangles of its
// own motion record, tested with the ray moved into their object space.
inline bool isMovingPacketTriangle(const ObjectGpu& ob) {
  return ob.type == OBJECT_TRIANGLE && ob.has_transform == OBJECT_MOVING;
}

}  // namespace prism
