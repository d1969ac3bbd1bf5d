// A triangle mesh as read from a file (through a format plugin) or handed over
// through the C API. Shared between every scene object that names the same file.
#pragma once

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "scene/scene_material.h"

namespace prism {

struct TriangleMesh {
  std::string source;                  // the file it came from, or a name given by the caller
  std::string plugin;                  // the plugin that read it ("" when built in memory)
  std::vector<float> positions;        // xyz per vertex
  std::vector<float> normals;          // xyz per vertex, or empty
  std::vector<float> texcoords;        // uv per vertex, or empty
  std::vector<float> colors;           // rgb per vertex, or empty
  std::vector<std::uint32_t> indices;  // 3 per triangle, in file order; polygons fanned (v0, vk, vk+1)
  // Per triangle: index into `materials`, or -1 for the object's material.
  std::vector<std::int32_t> triangle_materials;
  std::vector<Material> materials;     // from the file (MTL), in file order
  std::size_t face_count = 0;          // faces as written, before triangulation
  // Corners of each face in file order (its triangles are the next corners - 2
  // of the fan); empty when every face is a triangle (meshes from arrays).
  std::vector<std::uint32_t> face_corners;
  std::size_t degenerate_count = 0;    // zero-area triangles: kept, so numbering holds, but never hit
  std::vector<std::string> warnings;

  std::size_t vertexCount() const { return positions.size() / 3; }
  std::size_t triangleCount() const { return indices.size() / 3; }
};

using SharedMesh = std::shared_ptr<const TriangleMesh>;

}  // namespace prism
