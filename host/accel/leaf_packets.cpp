#include "accel/leaf_packets.h"

#include <limits>

#include "accel/kdop_bounds.h"
#include "accel/prim_ref.h"

namespace prism {
namespace {

TriPacketGpu emptyPacket() {
  TriPacketGpu p{};
  for (int k = 0; k < PACKET_LANES; ++k) p.prim[k] = PACKET_EMPTY;
  return p;
}

void putTriangle(TriPacketGpu& p, int lane, const ObjectGpu& ob, std::int32_t id) {
  const float* v = ob.p;
  p.v0x[lane] = v[0];
  p.v0y[lane] = v[1];
  p.v0z[lane] = v[2];
  // Float subtraction, as the kernel's scalar triangle_intersect does it.
  p.e1x[lane] = v[3] - v[0];
  p.e1y[lane] = v[4] - v[1];
  p.e1z[lane] = v[5] - v[2];
  p.e2x[lane] = v[6] - v[0];
  p.e2y[lane] = v[7] - v[1];
  p.e2z[lane] = v[8] - v[2];
  p.prim[lane] = id;
}

// An object lane's diagonal slabs (kdop_bounds.h) in the eight floats its
// lane leaves free: lo and hi of diagonal j in float4 words 2j and 2j + 1
// (kernels/accel/leaf_packets.h, packet_lane_slabs_meet); unbounded (the
// whole line) when the object has no finite box.
void putObjectSlabs(TriPacketGpu& p, int lane, const ObjectGpu& ob) {
  DiagonalSlabs s = DiagonalSlabs::empty();
  Aabb box;
  if (objectBounds(ob, &box)) {
    s = primitiveDiagonalSlabs(ob, box);
  } else {
    for (int j = 0; j < BVH_KDOP_DIAGONALS; ++j) {
      s.lo[j] = -std::numeric_limits<float>::infinity();
      s.hi[j] = std::numeric_limits<float>::infinity();
    }
  }
  float* words[2 * BVH_KDOP_DIAGONALS] = {p.v0x, p.v0y, p.v0z, p.e1x, p.e1y, p.e1z, p.e2x, p.e2y};
  for (int j = 0; j < BVH_KDOP_DIAGONALS; ++j) {
    words[2 * j][lane] = s.lo[j];
    words[2 * j + 1][lane] = s.hi[j];
  }
}

// The motion record a moving triangle points to (its index in `objects`).
std::size_t motionRecord(const ObjectGpu& ob, std::int32_t id) {
  return static_cast<std::size_t>(id) + static_cast<std::size_t>(ob.flags >> OBJECT_MOTION_SHIFT);
}

}  // namespace

void writeTrianglePackets(const std::vector<ObjectGpu>& objects, const std::int32_t* ids, std::size_t n,
                          TriPacketGpu* out) {
  for (std::size_t i = 0; i < n; ++i) {
    if (i % PACKET_LANES == 0) out[i / PACKET_LANES] = emptyPacket();
    putTriangle(out[i / PACKET_LANES], static_cast<int>(i % PACKET_LANES), objects[ids[i]], ids[i]);
  }
}

PacketRange appendLeafPackets(const std::vector<ObjectGpu>& objects, const std::int32_t* ids, std::size_t n,
                              PacketVector& out) {
  PacketRange range;
  range.start = static_cast<std::uint32_t>(out.size());
  // Static triangles four to a packet.
  int lane = PACKET_LANES;
  std::size_t others = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const ObjectGpu& ob = objects[ids[i]];
    if (!isPacketTriangle(ob)) {
      ++others;
      continue;
    }
    if (lane == PACKET_LANES) {
      out.push_back(emptyPacket());
      lane = 0;
    }
    putTriangle(out.back(), lane++, ob, ids[i]);
  }
  // A mesh's leaves hold nothing else: done without the passes below.
  if (others == 0) {
    range.count = static_cast<std::uint32_t>(out.size() - range.start);
    return range;
  }
  // Moving triangles, four of one motion record to a packet.
  std::vector<bool> placed(n, false);
  for (std::size_t i = 0; i < n; ++i) {
    const ObjectGpu& first = objects[ids[i]];
    if (placed[i] || !isMovingPacketTriangle(first) || ids[i] >= PACKET_MOVING) continue;
    const std::size_t record = motionRecord(first, ids[i]);
    lane = PACKET_LANES;
    for (std::size_t j = i; j < n; ++j) {
      const ObjectGpu& ob = objects[ids[j]];
      if (placed[j] || !isMovingPacketTriangle(ob) || ids[j] >= PACKET_MOVING || motionRecord(ob, ids[j]) != record)
        continue;
      if (lane == PACKET_LANES) {
        out.push_back(emptyPacket());
        lane = 0;
      }
      putTriangle(out.back(), lane++, ob, ids[j] | PACKET_MOVING);
      placed[j] = true;
    }
  }
  // Everything else, tested one by one.
  lane = PACKET_LANES;
  for (std::size_t i = 0; i < n; ++i) {
    const ObjectGpu& ob = objects[ids[i]];
    if (isPacketTriangle(ob) || (isMovingPacketTriangle(ob) && ids[i] < PACKET_MOVING)) continue;
    if (lane == PACKET_LANES) {
      out.push_back(emptyPacket());
      lane = 0;
    }
    putObjectSlabs(out.back(), lane, ob);
    out.back().prim[lane++] = -(ids[i] + 2);
  }
  range.count = static_cast<std::uint32_t>(out.size() - range.start);
  return range;
}

}  // namespace prism
