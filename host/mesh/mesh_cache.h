// Shares one TriangleMesh between every user of the same file: scene objects
// naming one file (or several scenes alive at once) hold the same SharedMesh.
// Keyed by the file's canonical path, size and modification time, so an edited
// file is read again. Entries are weak: a mesh no one holds any more is freed,
// and the next request reads the file again. Thread-safe.
#pragma once

#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <tuple>

#include "mesh/plugin_registry.h"
#include "scene/mesh.h"

namespace prism {

class MeshCache {
 public:
  MeshCache() = default;  // uses PluginRegistry::global()
  explicit MeshCache(const PluginRegistry& registry) : m_registry(&registry) {}

  // The mesh of `path`, read through loadMeshFile on a miss (which may throw
  // MeshError; failures are not cached).
  SharedMesh load(const std::string& path);

  // Meshes currently alive in the cache.
  std::size_t size() const;
  void clear();

  // The process-wide cache.
  static MeshCache& global();

 private:
  using Key = std::tuple<std::string, std::uintmax_t, std::int64_t>;  // canonical path, size, mtime
  const PluginRegistry* m_registry = nullptr;
  mutable std::mutex m_mutex;
  std::map<Key, std::weak_ptr<const TriangleMesh>> m_entries;
};

}  // namespace prism
