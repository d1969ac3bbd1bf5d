// The one exception type of the mesh layer: a mesh file or array that cannot be
// turned into a TriangleMesh. what() names the file (or the caller's name for
// in-memory arrays) and the reason, with the line where the format has lines,
// so callers (scene loader, CLI, C API) can show it unchanged.
#pragma once

#include <stdexcept>
#include <string>

namespace prism {

class MeshError : public std::runtime_error {
 public:
  explicit MeshError(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace prism
