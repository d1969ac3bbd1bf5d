// Mesh files through plugins, and meshes from arrays; see mesh_loader.h.
#include "mesh/mesh_loader.h"

#include <cstdio>
#include <cstring>
#include <filesystem>
#include <system_error>

#include "mesh/mesh_builder.h"
#include "mesh/mesh_validation.h"

namespace fs = std::filesystem;

namespace prism {

namespace {

std::string joined(const std::vector<std::string>& items) {
  std::string out;
  for (const std::string& s : items) out += (out.empty() ? "" : ", ") + s;
  return out;
}

// The plugin claiming the file's extension; for a file without one, the
// first plugin that recognises its first bytes.
const LoadedPlugin& pluginFor(const std::string& path, const PluginRegistry& registry) {
  if (registry.plugins().empty())
    throw MeshError(path + ": no mesh plugins were found (searched: " + joined(registry.searchPath()) +
                    "; set PRISM_PLUGIN_PATH to the folder that holds them)");
  std::string known = "known:";
  for (const std::string& e : registry.knownExtensions()) known += " ." + e;
  std::string ext = fs::path(path).extension().string();
  if (ext.size() < 2) {
    unsigned char head[4096];
    std::size_t n = 0;
    if (std::FILE* f = std::fopen(path.c_str(), "rb")) {
      n = std::fread(head, 1, sizeof head, f);
      std::fclose(f);
    }
    if (const LoadedPlugin* plugin = registry.findByContent(head, n)) return *plugin;
    throw MeshError(path + ": no file extension, and no plugin recognises its contents (" + known + ")");
  }
  const LoadedPlugin* plugin = registry.findByExtension(ext);
  if (plugin == nullptr) throw MeshError(path + ": unknown mesh file extension '" + ext + "' (" + known + ")");
  return *plugin;
}

// The file must be a non-empty regular file: a FIFO or a device could make a
// plugin wait forever, and an empty file is never a mesh.
void checkFile(const std::string& path) {
  std::error_code ec;
  fs::file_status st = fs::status(path, ec);
  if (ec || !fs::exists(st)) throw MeshError(path + ": cannot open: no such file");
  if (fs::is_directory(st)) throw MeshError(path + ": is a folder, not a mesh file");
  if (!fs::is_regular_file(st)) throw MeshError(path + ": is not a regular file");
  if (fs::file_size(path, ec) == 0 && !ec) throw MeshError(path + ": the file is empty");
}

std::string pluginMessage(const std::string& path, const LoadedPlugin& plugin, int status,
                          const PrismPluginError& err, const MeshBuilder& builder) {
  std::string where = path;
  if (err.line > 0) where += ":" + std::to_string(err.line);
  std::string text(err.message, strnlen(err.message, sizeof err.message));
  if (status == PRISM_PLUGIN_ERROR_SINK && !builder.refusal().empty()) text = builder.refusal();
  if (text.empty()) text = "the " + std::string(plugin.info->name) + " plugin failed (status " + std::to_string(status) + ")";
  if (err.line == 0 && err.offset > 0) text += " (at byte " + std::to_string(err.offset) + ")";
  return where + ": " + text;
}

}  // namespace

SharedMesh loadMeshFile(const std::string& path) { return loadMeshFile(path, PluginRegistry::global()); }

SharedMesh loadMeshFile(const std::string& path, const PluginRegistry& registry) {
  checkFile(path);
  const LoadedPlugin& plugin = pluginFor(path, registry);
  MeshBuilder builder(fs::path(path).parent_path().string());
  PrismPluginError err;
  std::memset(&err, 0, sizeof err);
  int status;
  try {
    status = plugin.info->load(path.c_str(), builder.sink(), &err);
  } catch (...) {
    // The ABI forbids it, but a C++ plugin that lets an exception escape
    // should cost the user an error message, not the process.
    throw MeshError(path + ": the " + std::string(plugin.info->name) + " plugin threw an exception (a plugin bug)");
  }
  err.message[sizeof err.message - 1] = '\0';
  if (status != PRISM_PLUGIN_OK) throw MeshError(pluginMessage(path, plugin, status, err, builder));
  if (!builder.refusal().empty()) throw MeshError(path + ": " + builder.refusal());
  TriangleMesh& mesh = builder.mesh();
  mesh.source = path;
  mesh.plugin = plugin.info->name;
  validateMesh(mesh, path);
  return std::make_shared<const TriangleMesh>(std::move(mesh));
}

SharedMesh meshFromArrays(const float* positions, std::size_t vertex_count, const std::uint32_t* indices,
                          std::size_t triangle_count, const std::string& name, std::size_t position_stride_bytes) {
  if (vertex_count > 0 && positions == nullptr) throw MeshError(name + ": positions are NULL");
  if (triangle_count > 0 && indices == nullptr) throw MeshError(name + ": indices are NULL");
  if (position_stride_bytes == 0) position_stride_bytes = 3 * sizeof(float);
  if (position_stride_bytes < 3 * sizeof(float) || position_stride_bytes % sizeof(float) != 0)
    throw MeshError(name + ": position stride " + std::to_string(position_stride_bytes) +
                    " bytes is not a multiple of 4 of at least 12");
  if (vertex_count > 0xffffffffull) throw MeshError(name + ": more than 2^32-1 vertices");
  if (triangle_count > 0xffffffffull / 3) throw MeshError(name + ": more than 2^32/3 triangles");
  auto mesh = std::make_shared<TriangleMesh>();
  mesh->source = name;
  mesh->positions.resize(3 * vertex_count);
  const std::size_t step = position_stride_bytes / sizeof(float);
  for (std::size_t v = 0; v < vertex_count; ++v)
    std::memcpy(&mesh->positions[3 * v], positions + v * step, 3 * sizeof(float));
  mesh->indices.assign(indices, indices + 3 * triangle_count);
  mesh->face_count = triangle_count;
  validateMesh(*mesh, name);
  return mesh;
}

}  // namespace prism
