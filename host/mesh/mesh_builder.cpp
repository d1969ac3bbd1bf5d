// Host-side sink; see mesh_builder.h.
#include "mesh/mesh_builder.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <limits>
#include <new>

#include "mesh/material_mapping.h"

namespace prism {

namespace {

// Indices are 32-bit: vertex numbers must fit, and so must triangle counts
// (the renderer numbers triangles with 32-bit primitive ids).
constexpr std::uint64_t kMaxVertices = std::numeric_limits<std::uint32_t>::max();
constexpr std::uint64_t kMaxTriangles = std::numeric_limits<std::uint32_t>::max() / 3;
// Hints come from untrusted headers: pre-allocate no more than this much.
constexpr std::uint64_t kMaxReserve = 1u << 24;
constexpr std::size_t kMaxWarnings = 100;  // later warnings are counted, not kept

}  // namespace

MeshBuilder::MeshBuilder(std::string base_dir) : m_base_dir(std::move(base_dir)) {
  m_sink.struct_size = sizeof(PrismMeshSink);
  m_sink.host = this;
  m_sink.begin = &MeshBuilder::begin;
  m_sink.add_position = &MeshBuilder::addPosition;
  m_sink.add_normal = &MeshBuilder::addNormal;
  m_sink.add_texcoord = &MeshBuilder::addTexcoord;
  m_sink.add_color = &MeshBuilder::addColor;
  m_sink.add_face = &MeshBuilder::addFace;
  m_sink.add_material = &MeshBuilder::addMaterial;
  m_sink.warning = &MeshBuilder::warning;
}

int MeshBuilder::refuse(std::string reason) {
  if (m_refusal.empty()) m_refusal = std::move(reason);
  return 1;
}

template <typename Fn>
int MeshBuilder::guarded(void* host, Fn&& fn) {
  MeshBuilder& b = self(host);
  if (!b.m_refusal.empty()) return 1;  // the plugin ignored an earlier stop
  try {
    return fn(b);
  } catch (const std::bad_alloc&) {
    return b.refuse("out of memory while building the mesh");
  } catch (const std::exception& e) {
    return b.refuse(std::string("internal error while building the mesh: ") + e.what());
  }
}

int MeshBuilder::begin(void* host, uint64_t vertices, uint64_t faces) {
  return guarded(host, [&](MeshBuilder& b) {
    b.m_mesh.positions.reserve(3 * std::min(vertices, kMaxReserve));
    b.m_mesh.indices.reserve(3 * std::min(faces, kMaxReserve));
    return 0;
  });
}

int MeshBuilder::addPosition(void* host, float x, float y, float z) {
  return guarded(host, [&](MeshBuilder& b) {
    if (b.m_mesh.positions.size() / 3 >= kMaxVertices) return b.refuse("more than 2^32-1 vertices");
    b.m_mesh.positions.insert(b.m_mesh.positions.end(), {x, y, z});
    return 0;
  });
}

int MeshBuilder::addNormal(void* host, float x, float y, float z) {
  return guarded(host, [&](MeshBuilder& b) {
    if (b.m_mesh.normals.size() / 3 >= kMaxVertices) return b.refuse("more than 2^32-1 normals");
    b.m_mesh.normals.insert(b.m_mesh.normals.end(), {x, y, z});
    return 0;
  });
}

int MeshBuilder::addTexcoord(void* host, float u, float v) {
  return guarded(host, [&](MeshBuilder& b) {
    if (b.m_mesh.texcoords.size() / 2 >= kMaxVertices) return b.refuse("more than 2^32-1 texture coordinates");
    b.m_mesh.texcoords.insert(b.m_mesh.texcoords.end(), {u, v});
    return 0;
  });
}

int MeshBuilder::addColor(void* host, float r, float g, float bl) {
  return guarded(host, [&](MeshBuilder& b) {
    if (b.m_mesh.colors.size() / 3 >= kMaxVertices) return b.refuse("more than 2^32-1 colours");
    b.m_mesh.colors.insert(b.m_mesh.colors.end(), {r, g, bl});
    return 0;
  });
}

int MeshBuilder::addFace(void* host, const uint32_t* indices, uint32_t corners, int32_t material) {
  return guarded(host, [&](MeshBuilder& b) {
    TriangleMesh& m = b.m_mesh;
    auto face = [&] { return "face " + std::to_string(m.face_count + 1); };
    if (indices == nullptr || corners < 3)
      return b.refuse(face() + " has " + std::to_string(corners) + " corner(s); a face needs at least 3");
    if (material < -1) return b.refuse(face() + " names material " + std::to_string(material));
    if (m.triangleCount() + (corners - 2) > kMaxTriangles) return b.refuse("more than 2^32/3 triangles");
    // Fan (v0, vk, vk+1): the documented triangulation, so triangle numbers
    // (primid) follow from the file alone.
    for (std::uint32_t k = 1; k + 1 < corners; ++k) {
      m.indices.insert(m.indices.end(), {indices[0], indices[k], indices[k + 1]});
      m.triangle_materials.push_back(material);
    }
    ++m.face_count;
    m.face_corners.push_back(corners);
    return 0;
  });
}

int MeshBuilder::addMaterial(void* host, const PrismMaterialDesc* material) {
  return guarded(host, [&](MeshBuilder& b) {
    if (material == nullptr) return b.refuse("a NULL material was added");
    if (b.m_mesh.materials.size() >= 1u << 20) return b.refuse("more than 2^20 materials");
    b.m_mesh.materials.push_back(materialFromDesc(*material, b.m_base_dir));
    return 0;
  });
}

int MeshBuilder::warning(void* host, const char* message, uint64_t line) {
  return guarded(host, [&](MeshBuilder& b) {
    std::vector<std::string>& w = b.m_mesh.warnings;
    if (w.size() < kMaxWarnings) {
      std::string text = message != nullptr ? std::string(message, strnlen(message, 1024)) : "(no message)";
      w.push_back(line > 0 ? "line " + std::to_string(line) + ": " + text : text);
    } else if (w.size() == kMaxWarnings) {
      w.push_back("more warnings not shown");
    }
    return 0;
  });
}

}  // namespace prism
