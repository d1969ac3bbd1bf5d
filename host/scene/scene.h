// The host-side scene model: camera, film, render settings, materials, lights and
// objects, as read from a scene file or built through the C API. Plain data; the
// renderer flattens it into device buffers (render/gpu_scene.h).
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "scene/mesh.h"
#include "scene/patches/bezier_patch.h"
#include "scene/scene_material.h"
#include "scene/transform.h"
#include "scene/vec3.h"

namespace prism {

struct Camera {
  Vec3 position{0, 0, 5};
  Vec3 look_at{0, 0, 0};
  Vec3 up{0, 1, 0};
  double fov = 45;  // vertical field of view, degrees
  // Depth of field: the lens radius (0: a pinhole) and the distance of the plane
  // in focus along the view direction (0: the distance to look_at).
  double aperture = 0;
  double focus_distance = 0;
  // Motion blur: the shutter interval, and where the camera is and looks at
  // shutter close (moving = false: where it is at open).
  double shutter_open = 0, shutter_close = 0;
  bool moving = false;
  Vec3 position_end, look_at_end;

  bool hasShutterInterval() const { return shutter_close > shutter_open; }
  // Whether every primary ray leaves one point at one instant, which is what the
  // first-hit (Z-buffer) pass can serve: no aperture, no shutter interval.
  bool isPinhole() const { return aperture == 0 && !hasShutterInterval(); }
};

struct Film {
  int width = 640;
  int height = 480;
  int spp = 1;
  // Anti-aliasing (docs/sampling.md): a mode name, or "" for the default (none at
  // spp 1, jitter above); the reconstruction filter; adaptive sampling's threshold
  // and maximum subdivision level.
  std::string aa;
  std::string filter = "box";
  double aa_threshold = 0.1;
  int aa_max_level = 2;
};

struct RenderSettings {
  int max_depth = 5;         // levels of secondary rays after the primary one
  double min_weight = 0.01;  // adaptive depth control threshold on a ray's weight
  Vec3 ambient{0.1, 0.1, 0.1};
  Vec3 background{0, 0, 0};
  unsigned long long seed = 0;
  std::string accel = "auto";  // spatial index: auto, bvh, octree, bsp or none
  std::string first_hit = "auto";  // primary visibility: auto, zbuffer or trace
  std::string inside_test = "crossing";  // polygons that name none: crossing, radial or left-right
  std::string shadows = "auto";  // point lights' feelers: auto, accel or lightbuffer
  std::string bounds = "aabb";   // the BVH children's bounds: aabb or kdop
  // The devices to render on when the caller names none (--device): a selector
  // of device/device_selector.h ("all", "0,2", "gpu"); "" for the default.
  std::string device;
};

enum class LightType { Point = 0, Quad = 1, Disk = 2, Sphere = 3 };

// A point light (position) or an area light of uniform emitted radiance
// color * intensity: a quad (corner, edge1, edge2: a parallelogram), a disk
// (center, normal, radius) or a sphere (center, radius).
struct Light {
  LightType type = LightType::Point;
  Vec3 position{0, 10, 0};
  Vec3 color{1, 1, 1};
  double intensity = 1;
  Vec3 corner, edge1, edge2;
  Vec3 center, normal{0, -1, 0};
  double radius = 1;
  // Shadow feelers per pixel this light wants: a hit sends ceil(samples / spp)
  // of them, so the pixel's samples together send at least `samples`.
  int samples = 1;
};

enum class ObjectType { Sphere = 0, Box = 1, Plane = 2, Triangle = 3, Mesh = 4, Quadric = 5, Polygon = 6, Polyhedron = 7,
                        Patches = 8 };

struct Object {
  ObjectType type = ObjectType::Sphere;
  int material = 0;  // index into Scene::materials
  Transform transform;  // object to world (at shutter open, when moving)
  // Motion blur: the object-to-world transform at shutter close; time
  // interpolates between the two (scene/motion.h).
  bool moving = false;
  Transform transform_end;
  // Sphere: center, radius. Box: box_min, box_max. Plane: point, normal.
  // Triangle: vertices (already in world space when the transform was applied).
  Vec3 center;
  double radius = 1;
  Vec3 box_min, box_max;
  Vec3 point, normal{0, 1, 0};
  Vec3 vertices[3];
  // Parameters of the kinds that lay them out themselves (scene/primitives/):
  // quadric: coefficients A..J, then the clip box's min and max; polygon: its
  // vertices, xyz each; polyhedron: its planes, a b c d each; patches: the
  // tolerance of Newton iteration.
  std::vector<double> params;
  bool capped = false;  // quadric: close the solid with the clip box's faces
  std::string inside_test;  // polygon: its point-in-polygon test, or "" for render.inside_test
  // Patches (the analytic method): the pieces the patches were cut into, each
  // one primitive (scene/patches/patch_subdivision.h).
  std::shared_ptr<const std::vector<PatchPiece>> pieces;
  // Mesh: its triangles (shared with other objects naming the same file), drawn
  // through `transform`; `material` is used for triangles whose file gives none,
  // or for all of them when `material_override` is set. The file's own materials
  // start at Scene::materials[mesh_material_offset].
  SharedMesh mesh;
  bool material_override = false;
  int mesh_material_offset = 0;
  bool smooth = false;  // interpolate vertex normals (when the file has them)
  // Mesh: faces of more than 3 corners kept as polygons where polygon_faces[f]
  // is set (planar, simple ones; the rest stay their fan of triangles). Empty:
  // every face is triangles.
  std::vector<bool> polygon_faces;

  // Primitives this object contributes to the scene's numbering (primid): one
  // for an analytic object, one per piece for patches, one per triangle for a
  // mesh, or, with polygon faces, one per polygon and per triangle of the
  // other faces.
  std::size_t primitiveCount() const {
    if (type == ObjectType::Patches) return pieces ? pieces->size() : 0;
    if (type != ObjectType::Mesh || !mesh) return 1;
    if (polygon_faces.empty()) return mesh->triangleCount();
    std::size_t n = 0;
    for (std::size_t f = 0; f < polygon_faces.size(); ++f) n += polygon_faces[f] ? 1 : mesh->face_corners[f] - 2;
    return n;
  }
};

// A sequence of frames (scene/animation.h): frame k's shutter is the camera's
// moved by k x step; the scene's motion spans all of them.
struct Animation {
  int frames = 1;
  double step = 1;
};

struct Scene {
  std::string source;  // file path or the name given to the loader
  Camera camera;
  Animation animation;
  Film film;
  RenderSettings render;
  std::vector<Material> materials;  // index 0 is always present (the default material)
  std::vector<Light> lights;
  std::vector<Object> objects;
  std::vector<std::string> warnings;
};

// The material objects use when they name none.
Material defaultMaterial();

// The texels of the images the scene's materials hold, each image once
// (as the flattening stores them): what kMaxTextureTexels bounds.
std::size_t imageTexelsHeld(const Scene& scene);

}  // namespace prism
