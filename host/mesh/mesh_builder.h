// The host side of PrismMeshSink: collects what a plugin pushes into a
// TriangleMesh, fanning polygons into triangles in file order. It never trusts
// the plugin: every callback is bounded (vertex and triangle counts must fit
// 32-bit indices), catches its own exceptions (a C callback must not throw), and
// on any refusal remembers the reason and asks the plugin to stop.
// Index ranges, finite coordinates and degenerate triangles are checked later,
// in one place, by validateMesh (mesh_validation.h).
#pragma once

#include <string>

#include "prism_plugin.h"
#include "scene/mesh.h"

namespace prism {

class MeshBuilder {
 public:
  // base_dir: the mesh file's folder, against which texture paths are resolved.
  explicit MeshBuilder(std::string base_dir = {});

  // The callback table to hand to a plugin; valid while this builder lives.
  const PrismMeshSink* sink() const { return &m_sink; }

  // Why a callback refused (empty if none did).
  const std::string& refusal() const { return m_refusal; }

  TriangleMesh& mesh() { return m_mesh; }

 private:
  static MeshBuilder& self(void* host) { return *static_cast<MeshBuilder*>(host); }
  static int begin(void* host, uint64_t vertices, uint64_t faces);
  static int addPosition(void* host, float x, float y, float z);
  static int addNormal(void* host, float x, float y, float z);
  static int addTexcoord(void* host, float u, float v);
  static int addColor(void* host, float r, float g, float b);
  static int addFace(void* host, const uint32_t* indices, uint32_t corners, int32_t material);
  static int addMaterial(void* host, const PrismMaterialDesc* material);
  static int warning(void* host, const char* message, uint64_t line);

  // Runs `fn` and turns any exception into a refusal (return 1).
  template <typename Fn>
  static int guarded(void* host, Fn&& fn);
  int refuse(std::string reason);

  PrismMeshSink m_sink{};
  TriangleMesh m_mesh;
  std::string m_base_dir;
  std::string m_refusal;
};

}  // namespace prism
