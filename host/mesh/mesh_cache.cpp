// Mesh sharing by file identity; see mesh_cache.h.
#include "mesh/mesh_cache.h"

#include <filesystem>
#include <system_error>

#include "mesh/mesh_loader.h"

namespace fs = std::filesystem;

namespace prism {

SharedMesh MeshCache::load(const std::string& path) {
  std::error_code ec;
  fs::path canonical = fs::canonical(path, ec);
  std::uintmax_t size = ec ? 0 : fs::file_size(canonical, ec);
  std::int64_t mtime = 0;
  if (!ec) mtime = fs::last_write_time(canonical, ec).time_since_epoch().count();
  // A file we cannot identify is not cached; loadMeshFile gives the error.
  const PluginRegistry& registry = m_registry != nullptr ? *m_registry : PluginRegistry::global();
  if (ec) return loadMeshFile(path, registry);

  Key key{canonical.string(), size, mtime};
  {
    std::lock_guard<std::mutex> lock(m_mutex);
    auto it = m_entries.find(key);
    if (it != m_entries.end()) {
      if (SharedMesh alive = it->second.lock()) return alive;
      m_entries.erase(it);
    }
  }
  // Read outside the lock, so one slow file does not hold up the others. Two
  // threads asking for the same new file may both read it; the first to
  // finish is kept and the other's copy is dropped.
  SharedMesh mesh = loadMeshFile(path, registry);
  std::lock_guard<std::mutex> lock(m_mutex);
  std::weak_ptr<const TriangleMesh>& slot = m_entries[key];
  if (SharedMesh winner = slot.lock()) return winner;
  slot = mesh;
  return mesh;
}

std::size_t MeshCache::size() const {
  std::lock_guard<std::mutex> lock(m_mutex);
  std::size_t alive = 0;
  for (const auto& entry : m_entries)
    if (!entry.second.expired()) ++alive;
  return alive;
}

void MeshCache::clear() {
  std::lock_guard<std::mutex> lock(m_mutex);
  m_entries.clear();
}

MeshCache& MeshCache::global() {
  static MeshCache cache;
  return cache;
}

}  // namespace prism
