// Adding meshes to a scene: as objects of a scene file or the C API, and as a
// whole "quick-render" scene around one mesh file.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "scene/scene.h"

namespace prism {

// Appends a mesh object. Its file's materials join scene.materials once per
// mesh, however many objects share it. `material` < 0 keeps the file's materials
// (and the default material where the file gives none); otherwise it overrides them.
Object& addMeshObject(Scene& scene, const SharedMesh& mesh, int material, const Transform& transform, bool smooth);

// "" when every vertex of the mesh's faces lies within the coordinates the
// kernels take (scene/value_check.h) wherever the object may put it: placed in
// world space by `transform`, and, for a moving object (`transform_end` given),
// by `transform_end` and as the mesh has it too (with the shutter open its
// triangles stay in object space and the kernels move the rays; with it closed,
// or on a frame held still, the flattening places them). Else the problem,
// naming the first vertex past the limit. The scene loader, the C API and an
// animation's frames all ask before a mesh object is rendered.
// `transform_name` names `transform` in the message.
std::string meshPlacementProblem(const TriangleMesh& mesh, const Transform& transform,
                                 const Transform* transform_end, const char* transform_name = "transform");

// The vertex indices, and the positions, of the face that starts at triangle
// `first_triangle` of the mesh's fan, in file order.
std::vector<std::uint32_t> faceVertexIndices(const TriangleMesh& mesh, std::size_t first_triangle,
                                             std::uint32_t corners);
std::vector<Vec3> faceVertices(const TriangleMesh& mesh, std::size_t first_triangle, std::uint32_t corners);

// Which faces of the mesh stay polygons when it is loaded with "polygons":
// those of more than 3 corners that are planar, simple and of non-zero area
// (scene/primitives/polygon_shape.h); *kept_as_triangles counts the other
// faces of more than 3 corners. Empty for a mesh of triangles only.
std::vector<bool> polygonFacePlan(const TriangleMesh& mesh, std::size_t* kept_as_triangles);

// A scene that shows one mesh: a camera on the +Z side, a little above and to the
// right of the bounding box's centre, looking at it, far enough for the bounding
// sphere to fill 90% of a 40-degree vertical field of view; a white headlight at
// the camera; a light grey Phong material unless the file brings its own; vertex
// normals interpolated when the file has them. Throws std::invalid_argument for a
// mesh without triangles.
Scene sceneForMesh(const SharedMesh& mesh);

}  // namespace prism
