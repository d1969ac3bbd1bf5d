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

std::size_t deviceGeometryBytes(const SceneGeometry& geometry) {
  return (geometry.objects.size() - geometry.triangleCount()) * sizeof(ObjectGpu) +
         geometry.triangles.size() * sizeof(std::uint32_t) + geometry.mesh_data.size() * sizeof(float);
}

}  // namespace prism
