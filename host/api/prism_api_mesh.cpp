// C API: meshes (files and caller arrays), mesh reports for `prism info`, and
// the plugin list for `prism plugins`.
#include <algorithm>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

#include "api/api_boundary.h"
#include "api/api_handles.h"
#include "mesh/mesh_cache.h"
#include "mesh/mesh_loader.h"
#include "mesh/plugin_registry.h"
#include "scene/mesh_objects.h"

using namespace prism;

struct PrismMeshReportImpl {
  SharedMesh mesh;
};

namespace {

#define PRISM_REQUIRE(cond, message) \
  if (!(cond)) return fail(PRISM_ERROR_INVALID_ARGUMENT, message)

// A caller's 4x4 row-major matrix; its last row must be 0 0 0 1.
Transform transformFrom(const float* m) {
  if (!m) return Transform::identity();
  if (m[12] != 0 || m[13] != 0 || m[14] != 0 || m[15] != 1)
    throw std::invalid_argument("object_to_world: the last row must be 0 0 0 1");
  Transform t;
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) t.m[r][c] = m[4 * r + c];
  const std::string problem = transformProblem(t);
  if (!problem.empty()) throw std::invalid_argument("object_to_world: " + problem);
  return t;
}

int materialIndex(const Scene& scene, const char* name) {
  if (!name) return -1;
  for (std::size_t i = 0; i < scene.materials.size(); ++i)
    if (scene.materials[i].name == name) return static_cast<int>(i);
  throw std::invalid_argument(std::string("unknown material '") + name + "'");
}

PrismStatus addMesh(PrismScene scene, const SharedMesh& mesh, const char* material, const float* matrix, int smooth,
                    uint32_t* out_object) {
  if (mesh->triangleCount() == 0)
    return fail(PRISM_ERROR_INVALID_ARGUMENT,
                mesh->source + ": holds no faces (a point cloud?): nothing to render");
  Transform t = transformFrom(matrix);
  const std::string placement = meshPlacementProblem(*mesh, t, nullptr);
  if (!placement.empty()) throw std::invalid_argument(placement);  // named after the call, as the transform's
  int m = materialIndex(scene->scene, material);
  addMeshObject(scene->scene, mesh, m, t, smooth != 0);
  scene->changed();
  if (out_object) *out_object = static_cast<uint32_t>(scene->scene.objects.size() - 1);
  return PRISM_OK;
}

// Joined lists built once, so the C strings handed out live as long as the process.
const std::vector<std::string>& extensionLists() {
  static const std::vector<std::string> lists = [] {
    std::vector<std::string> out;
    for (const PluginCandidate& c : PluginRegistry::global().candidates()) {
      std::string joined;
      for (const std::string& e : c.extensions) joined += (joined.empty() ? "" : " ") + e;
      out.push_back(joined);
    }
    return out;
  }();
  return lists;
}

}  // namespace

extern "C" {

PRISM_API PrismStatus prismNewScene(PrismScene* out_scene) {
  PRISM_REQUIRE(out_scene, "prismNewScene: out_scene is NULL");
  return guarded(__func__, [&] {
    auto impl = new PrismSceneImpl;
    impl->scene.source = "<api>";
    impl->scene.materials.push_back(defaultMaterial());
    *out_scene = impl;
    return PRISM_OK;
  });
}

PRISM_API PrismStatus prismLoadMeshAsScene(const char* path, PrismScene* out_scene) {
  PRISM_REQUIRE(out_scene, "prismLoadMeshAsScene: out_scene is NULL");
  *out_scene = nullptr;
  PRISM_REQUIRE(path, "prismLoadMeshAsScene: path is NULL");
  return guarded(__func__, [&] {
    SharedMesh mesh = MeshCache::global().load(path);
    *out_scene = new PrismSceneImpl{sceneForMesh(mesh)};
    return PRISM_OK;
  });
}

PRISM_API PrismStatus prismAddMeshFile(PrismScene scene, const char* path, const char* material,
                                       const float* object_to_world, int smooth, uint32_t* out_object) {
  PRISM_REQUIRE(scene && path, "prismAddMeshFile: NULL scene or path");
  return guarded(__func__, [&] {
    return addMesh(scene, MeshCache::global().load(path), material, object_to_world, smooth, out_object);
  });
}

PRISM_API PrismStatus prismAddMeshArrays(PrismScene scene, const float* positions, size_t vertex_count,
                                         const uint32_t* indices, size_t triangle_count, const char* material,
                                         const float* object_to_world, uint32_t* out_object) {
  PRISM_REQUIRE(scene && positions && indices, "prismAddMeshArrays: NULL scene, positions or indices");
  return guarded(__func__, [&] {
    SharedMesh mesh;
    try {
      mesh = meshFromArrays(positions, vertex_count, indices, triangle_count, "prismAddMeshArrays");
    } catch (const MeshError& e) {  // the caller's arrays, not a file: a bad argument
      throw std::invalid_argument(e.what());
    }
    return addMesh(scene, mesh, material, object_to_world, 0, out_object);
  });
}

PRISM_API PrismStatus prismInspectMeshFile(const char* path, PrismMeshReport* out_report) {
  PRISM_REQUIRE(out_report, "prismInspectMeshFile: out_report is NULL");
  *out_report = nullptr;
  PRISM_REQUIRE(path, "prismInspectMeshFile: path is NULL");
  return guarded(__func__, [&] {
    *out_report = new PrismMeshReportImpl{loadMeshFile(path)};
    return PRISM_OK;
  });
}

PRISM_API PrismStatus prismGetMeshCounts(PrismMeshReport report, PrismMeshCounts* counts) {
  PRISM_REQUIRE(report && counts, "prismGetMeshCounts: NULL argument");
  PRISM_REQUIRE(counts->struct_size >= sizeof(PrismMeshCounts), "prismGetMeshCounts: struct_size is too small");
  const TriangleMesh& m = *report->mesh;
  size_t size = counts->struct_size;
  std::memset(counts, 0, size);
  counts->struct_size = size;
  counts->vertices = m.vertexCount();
  counts->faces = m.face_count;
  counts->triangles = m.triangleCount();
  counts->degenerate_triangles = m.degenerate_count;
  counts->materials = static_cast<uint32_t>(m.materials.size());
  counts->has_normals = !m.normals.empty();
  counts->has_texcoords = !m.texcoords.empty();
  counts->has_colors = !m.colors.empty();
  if (m.vertexCount() > 0) {
    for (int k = 0; k < 3; ++k) {
      counts->bounds_min[k] = std::numeric_limits<float>::infinity();
      counts->bounds_max[k] = -std::numeric_limits<float>::infinity();
    }
    for (std::size_t v = 0; v < m.vertexCount(); ++v)
      for (int k = 0; k < 3; ++k) {
        counts->bounds_min[k] = std::min(counts->bounds_min[k], m.positions[3 * v + k]);
        counts->bounds_max[k] = std::max(counts->bounds_max[k], m.positions[3 * v + k]);
      }
  }
  return PRISM_OK;
}

PRISM_API const char* prismGetMeshPlugin(PrismMeshReport report) {
  return report ? report->mesh->plugin.c_str() : "";
}

PRISM_API const char* prismGetMeshMaterialName(PrismMeshReport report, uint32_t index) {
  if (!report || index >= report->mesh->materials.size()) return nullptr;
  return report->mesh->materials[index].name.c_str();
}

PRISM_API uint32_t prismGetMeshWarningCount(PrismMeshReport report) {
  return report ? static_cast<uint32_t>(report->mesh->warnings.size()) : 0;
}

PRISM_API const char* prismGetMeshWarning(PrismMeshReport report, uint32_t index) {
  if (!report || index >= report->mesh->warnings.size()) return nullptr;
  return report->mesh->warnings[index].c_str();
}

PRISM_API void prismReleaseMeshReport(PrismMeshReport report) { delete report; }

PRISM_API PrismStatus prismGetPluginCount(uint32_t* count) {
  PRISM_REQUIRE(count, "prismGetPluginCount: count is NULL");
  return guarded(__func__, [&] {
    *count = static_cast<uint32_t>(PluginRegistry::global().candidates().size());
    return PRISM_OK;
  });
}

PRISM_API PrismStatus prismGetPluginInfo(uint32_t index, PrismPluginCandidateInfo* info) {
  PRISM_REQUIRE(info && info->struct_size >= sizeof(PrismPluginCandidateInfo),
                "prismGetPluginInfo: NULL info or struct_size too small");
  return guarded(__func__, [&] {
    const auto& candidates = PluginRegistry::global().candidates();
    if (index >= candidates.size())
      return fail(PRISM_ERROR_INVALID_ARGUMENT, "prismGetPluginInfo: no plugin " + std::to_string(index));
    const PluginCandidate& c = candidates[index];
    info->path = c.path.c_str();
    info->name = c.name.c_str();
    info->extensions = extensionLists()[index].c_str();
    info->accepted = c.accepted ? 1 : 0;
    info->reason = c.reason.c_str();
    return PRISM_OK;
  });
}

}  // extern "C"
