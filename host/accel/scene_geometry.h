// The flattened primitives of a scene, as the builders and the kernels read
// them (kernels/shared/mesh_gpu.h, kernels/geometry/primitive.h).
//
// On the host every primitive has an ObjectGpu record, its index the primitive
// id: the builders, the exact predicates and the host first-hit set-up read
// those. On the device a mesh's triangles are compact instead, three vertex
// indices each into shared vertex positions; their host records are left out
// of the device's object array (deviceRecords).
//
// Host records, in order: the analytic primitives [0, triangle_base), the
// compact triangles' records [triangle_base, primitive_count), the mesh
// headers (MeshGpu), then the motion and data records.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "kernels/shared/mesh_gpu.h"
#include "kernels/shared/object_gpu.h"

namespace prism {

struct SceneGeometry {
  std::vector<ObjectGpu> objects;
  std::size_t primitive_count = 0;
  // Compact triangles: ids [triangle_base, primitive_count); their meshes'
  // headers are the mesh_count records from primitive_count on.
  std::size_t triangle_base = 0;
  std::size_t mesh_count = 0;
  std::vector<std::uint32_t> triangles;  // 3 vertex indices per compact triangle
  std::vector<float> mesh_data;          // positions, then normals, texcoords, materials (mesh_gpu.h)

  std::size_t triangleCount() const { return primitive_count - triangle_base; }
};

// Records alone, every triangle among them kept as a record (test scenes and
// callers that build ObjectGpu arrays themselves).
SceneGeometry geometryFromRecords(std::vector<ObjectGpu> objects);

// The object array the kernels get: the host records without the compact
// triangles', offsets to motion and data records shortened to match.
std::vector<ObjectGpu> deviceRecords(const SceneGeometry& geometry);

// The ids of the primitives that are not plain triangles (a triangle record in
// world space: isPacketTriangle), ascending. Of the compact triangles only a
// moving mesh's are read, a static mesh's being in world space by
// construction (flattenScene), so a mesh scene costs its headers rather than a
// walk over every triangle's record. Throws std::logic_error for compact
// triangles without any mesh header.
std::vector<std::size_t> notPlainTriangles(const SceneGeometry& geometry);

// Bytes the geometry takes on the device (object records, triangles, mesh data).
std::size_t deviceGeometryBytes(const SceneGeometry& geometry);

}  // namespace prism
