#include "accel/scene_geometry.h"

#include <cstring>
#include <utility>

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

std::vector<std::size_t> notPlainTriangles(const SceneGeometry& geometry) {
  std::vector<std::size_t> ids;
  auto walk = [&](std::size_t begin, std::size_t end) {
    for (std::size_t k = begin; k < end; ++k) {
      const ObjectGpu& ob = geometry.objects[k];
      if (ob.type != OBJECT_TRIANGLE || ob.has_transform != 0) ids.push_back(k);
    }
  };
  static_assert(sizeof(MeshGpu) == sizeof(ObjectGpu), "a mesh header is kept in an object record");
  walk(0, geometry.triangle_base);
  // The headers follow the triangles, in the order of their first triangles.
  for (std::size_t m = 0; m < geometry.mesh_count; ++m) {
    MeshGpu header;
    std::memcpy(&header, &geometry.objects[geometry.primitive_count + m], sizeof header);
    if (header.has_transform == 0) continue;
    MeshGpu next{};
    next.first_triangle = static_cast<int>(geometry.primitive_count);
    if (m + 1 < geometry.mesh_count)
      std::memcpy(&next, &geometry.objects[geometry.primitive_count + m + 1], sizeof next);
    walk(static_cast<std::size_t>(header.first_triangle), static_cast<std::size_t>(next.first_triangle));
  }
  return ids;
}

std::size_t deviceGeometryBytes(const SceneGeometry& geometry) {
  return (geometry.objects.size() - geometry.triangleCount()) * sizeof(ObjectGpu) +
         geometry.triangles.size() * sizeof(std::uint32_t) + geometry.mesh_data.size() * sizeof(float);
}

}  // namespace prism
