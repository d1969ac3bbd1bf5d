// The checks every mesh passes before prism uses it, whoever produced it (a
// plugin, or a caller's arrays): one place, so the rules cannot drift apart.
//   errors (MeshError): a non-finite position (names the vertex), an index out
//     of range, a triangle material out of range;
//   repaired with a warning: per-vertex normals, texture coordinates or colours
//     whose count does not match the vertices or that hold non-finite values
//     are dropped;
//   counted with a warning: degenerate (zero-area) triangles, kept in place so
//     triangle numbers still follow the file, in degenerate_count.
#pragma once

#include <string>

#include "scene/mesh.h"

namespace prism {

// `what` names the mesh in messages (its file, or the caller's name for arrays).
void validateMesh(TriangleMesh& mesh, const std::string& what);

}  // namespace prism
