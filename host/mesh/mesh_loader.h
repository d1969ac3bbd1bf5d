// Turning a mesh file, or a caller's arrays, into a validated TriangleMesh.
// The file's extension (any case) picks the plugin; every failure is a
// MeshError whose message names the file and the reason (and the line, where
// the plugin knows it). A file with vertices but no faces is a valid mesh of
// 0 triangles (a point cloud); it is up to the caller to refuse rendering it.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

#include "mesh/mesh_error.h"
#include "mesh/plugin_registry.h"
#include "scene/mesh.h"

namespace prism {

// Reads `path` with the plugin of the global registry that claims its extension.
SharedMesh loadMeshFile(const std::string& path);
// The same, with a given registry (tests, tools that scan their own folders).
SharedMesh loadMeshFile(const std::string& path, const PluginRegistry& registry);

// A mesh from caller-owned arrays, copied. positions: vertex_count xyz float
// triples, each position_stride_bytes apart (0 = tightly packed, 12);
// indices: 3 per triangle. `name` stands for the file in messages and in
// TriangleMesh::source. Same validation as loadMeshFile.
SharedMesh meshFromArrays(const float* positions, std::size_t vertex_count, const std::uint32_t* indices,
                          std::size_t triangle_count, const std::string& name = "mesh arrays",
                          std::size_t position_stride_bytes = 0);

}  // namespace prism
