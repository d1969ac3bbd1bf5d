#include "scene/mesh_objects.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <stdexcept>

#include "scene/camera_check.h"
#include "scene/primitives/polygon_shape.h"
#include "scene/value_check.h"

namespace prism {
namespace {

// The file's materials that name a diffuse map (MTL map_Kd) get it as their
// image texture, each file read once; one that cannot be read is a warning,
// and its material keeps its plain colour.
void attachDiffuseMaps(Scene& scene, std::size_t first, const std::string& source) {
  std::map<std::string, SharedImage> read;
  std::size_t texels_held = imageTexelsHeld(scene);
  for (std::size_t i = first; i < scene.materials.size(); ++i) {
    Material& m = scene.materials[i];
    if (m.diffuse_map.empty() || m.texture.kind != Texture::Kind::None) continue;
    auto it = read.find(m.diffuse_map);
    if (it == read.end()) {
      SharedImage image;
      try {
        image = readImageTexture(m.diffuse_map, std::nullopt, texels_held);
        texels_held += static_cast<std::size_t>(image->width) * image->height;
      } catch (const ImageTextureError& e) {
        scene.warnings.push_back(source + ": material '" + m.name + "': map_Kd not used: " + e.what());
      }
      it = read.emplace(m.diffuse_map, image).first;
    }
    if (!it->second) continue;
    m.texture.kind = Texture::Kind::Image;
    m.texture.image = it->second;
  }
}

}  // namespace

std::string meshPlacementProblem(const TriangleMesh& mesh, const Transform& transform,
                                 const Transform* transform_end, const char* transform_name) {
  // Where the flattening may put them (render/gpu_scene.cpp, appendMesh), and
  // as the file has them: a vertex no face uses is never placed.
  std::vector<char> used(mesh.vertexCount(), 0);
  for (std::uint32_t v : mesh.indices) used[v] = 1;
  struct Placement {
    const Transform* transform;  // none: as the mesh has them
    std::string words;
  };
  const bool placed = !transform.isIdentity();
  std::vector<Placement> placements = {
      placed ? Placement{&transform, std::string(" once placed by the object's ") + transform_name} : Placement{}};
  if (transform_end) {
    if (!transform_end->isIdentity()) placements.push_back({transform_end, " once placed by the object's transform_end"});
    if (placed) placements.push_back({nullptr, " as the mesh has them (a moving mesh's)"});
  }
  for (const Placement& placement : placements)
    for (std::size_t v = 0; v < used.size(); ++v) {
      if (!used[v]) continue;
      const Vec3 raw{mesh.positions[3 * v], mesh.positions[3 * v + 1], mesh.positions[3 * v + 2]};
      const Vec3 p = placement.transform ? placement.transform->applyPoint(raw) : raw;
      const std::string problem = vectorProblem(p, "vertices");
      if (problem.empty()) continue;
      char at[96];
      std::snprintf(at, sizeof at, "(%.9g, %.9g, %.9g)", p.x, p.y, p.z);
      // A mesh from a file names it; one from a caller's arrays is the call's.
      const std::string of = mesh.plugin.empty() ? "" : " of '" + mesh.source + "'";
      return problem + placement.words + ": vertex " + std::to_string(v) + of + " lies at " + at;
    }
  return "";
}

Object& addMeshObject(Scene& scene, const SharedMesh& mesh, int material, const Transform& transform, bool smooth) {
  Object o;
  o.type = ObjectType::Mesh;
  o.mesh = mesh;
  o.transform = transform;
  o.smooth = smooth;
  o.material_override = material >= 0;
  o.material = material >= 0 ? material : 0;
  o.mesh_material_offset = -1;
  for (const Object& other : scene.objects)
    if (other.type == ObjectType::Mesh && other.mesh == mesh) o.mesh_material_offset = other.mesh_material_offset;
  if (o.mesh_material_offset < 0) {
    o.mesh_material_offset = static_cast<int>(scene.materials.size());
    scene.materials.insert(scene.materials.end(), mesh->materials.begin(), mesh->materials.end());
    attachDiffuseMaps(scene, o.mesh_material_offset, mesh->source);
  }
  scene.objects.push_back(std::move(o));
  return scene.objects.back();
}

std::vector<std::uint32_t> faceVertexIndices(const TriangleMesh& mesh, std::size_t first_triangle,
                                             std::uint32_t corners) {
  // The fan (v0, vk, vk+1): v0, then each triangle's second corner, then the last one's third.
  std::vector<std::uint32_t> ids = {mesh.indices[3 * first_triangle]};
  for (std::uint32_t k = 0; k + 2 < corners; ++k) ids.push_back(mesh.indices[3 * (first_triangle + k) + 1]);
  ids.push_back(mesh.indices[3 * (first_triangle + corners - 3) + 2]);
  return ids;
}

std::vector<Vec3> faceVertices(const TriangleMesh& mesh, std::size_t first_triangle, std::uint32_t corners) {
  std::vector<Vec3> verts;
  for (std::uint32_t v : faceVertexIndices(mesh, first_triangle, corners))
    verts.push_back({mesh.positions[3 * v], mesh.positions[3 * v + 1], mesh.positions[3 * v + 2]});
  return verts;
}

std::vector<bool> polygonFacePlan(const TriangleMesh& mesh, std::size_t* kept_as_triangles) {
  *kept_as_triangles = 0;
  std::vector<bool> plan;
  bool any = false;
  std::size_t t = 0;
  for (std::uint32_t corners : mesh.face_corners) {
    bool polygon = false;
    if (corners > 3) {
      polygon = checkPolygon(faceVertices(mesh, t, corners)).problem.empty();
      *kept_as_triangles += !polygon;
    }
    plan.push_back(polygon);
    any = any || polygon;
    t += corners - 2;
  }
  if (!any) plan.clear();
  return plan;
}

Scene sceneForMesh(const SharedMesh& mesh) {
  if (mesh->triangleCount() == 0)
    throw std::invalid_argument(mesh->source + ": holds " + std::to_string(mesh->vertexCount()) +
                                " vertices and no faces (a point cloud?): nothing to render");
  const std::string placement = meshPlacementProblem(*mesh, Transform::identity(), nullptr);
  if (!placement.empty()) throw std::invalid_argument(placement);  // (it names the file)
  Vec3 lo = Vec3::splat(std::numeric_limits<double>::infinity()), hi = -lo;
  for (std::size_t i = 0; i < mesh->indices.size(); ++i) {
    const float* p = &mesh->positions[3 * mesh->indices[i]];
    lo = {std::min(lo.x, double(p[0])), std::min(lo.y, double(p[1])), std::min(lo.z, double(p[2]))};
    hi = {std::max(hi.x, double(p[0])), std::max(hi.y, double(p[1])), std::max(hi.z, double(p[2]))};
  }
  const Vec3 centre = (lo + hi) * 0.5;
  const double radius = std::max(length(hi - lo) * 0.5, 1e-6);

  Scene scene;
  scene.source = mesh->source;
  Material grey = defaultMaterial();
  grey.name = "default";
  grey.diffuse = {0.75, 0.75, 0.75};
  grey.specular = {0.25, 0.25, 0.25};
  grey.shininess = 40;
  scene.materials.push_back(grey);

  scene.camera.fov = 40;
  const double pi = 3.14159265358979323846;
  double distance = radius / std::sin(scene.camera.fov * pi / 360.0) / 0.9;
  const Vec3 away = normalize(Vec3{0.35, 0.4, 1.0});
  // The camera (and the headlight with it) stands about 3.25 bounding radii
  // out, but no farther than the coordinates a camera may have (1e15): a mesh
  // near that size is shown from closer, not refused, since `prism trace` and a
  // render with its own camera flags load it this way too.
  double farthest_allowed = distance;
  for (int i = 0; i < 3; ++i) farthest_allowed = std::min(farthest_allowed, (kMaxCoordinate - centre[i]) / away[i]);
  if (farthest_allowed < distance) {
    distance = farthest_allowed * (1 - 1e-9);
    scene.warnings.push_back(mesh->source +
                             ": too large to show whole from a camera of coordinates within 1e15: the camera stands closer");
  }
  scene.camera.look_at = centre;
  scene.camera.position = centre + away * distance;
  scene.camera.up = {0, 1, 0};
  if (const std::string problem = cameraProblem(scene.camera); !problem.empty())
    throw std::invalid_argument(mesh->source + ": no camera of coordinates within 1e15 can frame it: " + problem);
  scene.film.width = 800;
  scene.film.height = 600;
  scene.render.ambient = {0.15, 0.15, 0.15};
  scene.render.background = {0.12, 0.13, 0.16};
  scene.render.max_depth = 4;

  Light headlight;
  headlight.position = scene.camera.position;
  scene.lights.push_back(headlight);

  addMeshObject(scene, mesh, -1, Transform::identity(), !mesh->normals.empty());
  scene.warnings.insert(scene.warnings.begin(), mesh->warnings.begin(), mesh->warnings.end());
  return scene;
}

}  // namespace prism
