// Mesh checks; see mesh_validation.h.
#include "mesh/mesh_validation.h"

#include <cmath>
#include <cstdint>
#include <sstream>

#include "mesh/mesh_error.h"

namespace prism {

namespace {

bool allFinite(const std::vector<float>& values) {
  for (float v : values)
    if (!std::isfinite(v)) return false;
  return true;
}

// Drops a per-vertex attribute that does not line up with the vertices.
void checkAttribute(TriangleMesh& mesh, std::vector<float>& values, std::size_t per_vertex, const char* name) {
  if (values.empty()) return;
  std::size_t count = values.size() / per_vertex;
  std::string problem;
  if (values.size() % per_vertex != 0 || count != mesh.vertexCount())
    problem = std::to_string(count) + " " + name + " for " + std::to_string(mesh.vertexCount()) + " vertices";
  else if (!allFinite(values))
    problem = std::string("non-finite ") + name;
  if (problem.empty()) return;
  values.clear();
  mesh.warnings.push_back(problem + ": " + name + " ignored");
}

// Twice the triangle's area is |(b - a) x (c - a)|; in double so that small,
// valid triangles far from the origin are not mistaken for degenerate ones.
bool isDegenerate(const std::vector<float>& p, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  if (a == b || b == c || a == c) return true;
  double ax = p[3 * a], ay = p[3 * a + 1], az = p[3 * a + 2];
  double ux = p[3 * b] - ax, uy = p[3 * b + 1] - ay, uz = p[3 * b + 2] - az;
  double vx = p[3 * c] - ax, vy = p[3 * c + 1] - ay, vz = p[3 * c + 2] - az;
  double nx = uy * vz - uz * vy, ny = uz * vx - ux * vz, nz = ux * vy - uy * vx;
  return nx == 0 && ny == 0 && nz == 0;
}

}  // namespace

void validateMesh(TriangleMesh& mesh, const std::string& what) {
  const std::size_t vertex_count = mesh.vertexCount();
  for (std::size_t v = 0; v < vertex_count; ++v) {
    const float* p = &mesh.positions[3 * v];
    if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2])) {
      std::ostringstream msg;
      msg << what << ": vertex " << v << " (counting from 0) has a non-finite position (" << p[0] << ", " << p[1]
          << ", " << p[2] << ")";
      throw MeshError(msg.str());
    }
  }
  for (std::size_t i = 0; i < mesh.indices.size(); ++i) {
    if (mesh.indices[i] >= vertex_count)
      throw MeshError(what + ": triangle " + std::to_string(i / 3) + " (counting from 0) uses vertex " +
                      std::to_string(mesh.indices[i]) + ", but there are only " + std::to_string(vertex_count) +
                      " vertices");
  }
  if (!mesh.triangle_materials.empty() && mesh.triangle_materials.size() != mesh.triangleCount())
    throw MeshError(what + ": " + std::to_string(mesh.triangle_materials.size()) + " triangle materials for " +
                    std::to_string(mesh.triangleCount()) + " triangles");
  const auto material_count = static_cast<std::int64_t>(mesh.materials.size());
  for (std::size_t t = 0; t < mesh.triangle_materials.size(); ++t) {
    std::int32_t m = mesh.triangle_materials[t];
    if (m < -1 || m >= material_count)
      throw MeshError(what + ": triangle " + std::to_string(t) + " uses material " + std::to_string(m) +
                      ", but there are " + std::to_string(material_count) + " materials");
  }
  checkAttribute(mesh, mesh.normals, 3, "normals");
  checkAttribute(mesh, mesh.texcoords, 2, "texture coordinates");
  checkAttribute(mesh, mesh.colors, 3, "colours");

  mesh.degenerate_count = 0;
  for (std::size_t t = 0; t < mesh.triangleCount(); ++t)
    if (isDegenerate(mesh.positions, mesh.indices[3 * t], mesh.indices[3 * t + 1], mesh.indices[3 * t + 2]))
      ++mesh.degenerate_count;
  if (mesh.degenerate_count > 0)
    mesh.warnings.push_back(std::to_string(mesh.degenerate_count) +
                            " degenerate (zero-area) triangle(s): kept so triangle numbers follow the file, "
                            "but they are never hit");
}

}  // namespace prism
