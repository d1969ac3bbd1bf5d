#include "accel/scene_geometry.h"

#include <cstring>
#include <stdexcept>
#include <utility>

#include "accel/leaf_packets.h"
#include "accel/prim_ref.h"
#include "scene/primitives/primitive_kind.h"

namespace prism {

SceneGeometry geometryFromRecords(std::vector<ObjectGpu> objects) {
  SceneGeometry g;
  g.objects = std::move(objects);
  g.primitive_count = primitiveCount(g.objects);
  g.triangle_base = g.primitive_count;
  return g;
}

std::vector<ObjectGpu> deviceRecords(const SceneGeometry& geometry) {
  const std::size_t base = geometry.triangle_base, gap = geometry.triangleCount();
  std::vector<ObjectGpu> out;
  out.reserve(geometry.objects.size() - gap);
  out.insert(out.end(), geometry.objects.begin(), geometry.objects.begin() + static_cast<std::ptrdiff_t>(base));
  out.insert(out.end(), geometry.objects.begin() + static_cast<std::ptrdiff_t>(base + gap), geometry.objects.end());
  if (gap == 0) return out;
  // Every motion and data record lies after the gap; the analytic primitives'
  // offsets to theirs lose its length (the headers' do not cross it).
  for (std::size_t i = 0; i < base; ++i) {
    ObjectGpu& ob = out[i];
    if (ob.has_transform == OBJECT_MOVING) ob.flags -= static_cast<int>(gap << OBJECT_MOTION_SHIFT);
    const PrimitiveKind* kind = primitiveKindOfGpu(ob.type);
    if (kind && kind->has_side_data) {
      int offset;
      std::memcpy(&offset, &ob.p[OBJECT_DATA_WORD], sizeof offset);
      setSideDataOffset(ob, offset - static_cast<int>(gap));
    }
  }
  return out;
}

static_assert(sizeof(MeshGpu) == sizeof(ObjectGpu), "a mesh header is kept in an object record");

std::vector<std::size_t> notPlainTriangles(const SceneGeometry& geometry) {
  if (geometry.triangleCount() > 0 && geometry.mesh_count == 0)
    throw std::logic_error("notPlainTriangles: compact triangles without a mesh header");
  std::vector<std::size_t> ids;
  auto walk = [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k)
      if (!isPacketTriangle(geometry.objects[k])) ids.push_back(k);
  };
  walk(0, geometry.triangle_base);
  // The headers follow the triangles, in the order of their first triangles.
  auto header = [&](std::size_t m) {
    MeshGpu h;
    std::memcpy(&h, &geometry.objects[geometry.primitive_count + m], sizeof h);
    return h;
  };
  for (std::size_t m = 0; m < geometry.mesh_count; ++m) {
    const MeshGpu h = header(m);
    if (h.has_transform == 0) continue;
    const std::size_t end =
        m + 1 < geometry.mesh_count ? static_cast<std::size_t>(header(m + 1).first_triangle) : geometry.primitive_count;
    walk(static_cast<std::size_t>(h.first_triangle), end);
  }
  return ids;
}

std::size_t deviceGeometryBytes(const SceneGeometry& geometry) {
  return (geometry.objects.size() - geometry.triangleCount()) * sizeof(ObjectGpu) +
         geometry.triangles.size() * sizeof(std::uint32_t) + geometry.mesh_data.size() * sizeof(float);
}

}  // namespace prism
