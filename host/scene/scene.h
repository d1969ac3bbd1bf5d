// The host-side scene model: camera, film, render settings, materials, lights and
// objects, as read from a scene file or built through the C API. Plain data; the
// renderer flattens it into device buffers (render/gpu_scene.h).
#pragma once

#include <string>
#include <vector>

#include "scene/transform.h"
#include "scene/vec3.h"

namespace prism {

struct Camera {
  Vec3 position{0, 0, 5};
  Vec3 look_at{0, 0, 0};
  Vec3 up{0, 1, 0};
  double fov = 45;  // vertical field of view, degrees
};

struct Film {
  int width = 640;
  int height = 480;
  int spp = 1;
};

struct RenderSettings {
  int max_depth = 5;         // levels of secondary rays after the primary one
  double min_weight = 0.01;  // adaptive depth control threshold on a ray's weight
  Vec3 ambient{0.1, 0.1, 0.1};
  Vec3 background{0, 0, 0};
  unsigned long long seed = 0;
};

enum class ShadingModel { Phong = 0, Blinn = 1 };

struct Texture {
  enum class Kind { None = 0, Checker = 1 };
  Kind kind = Kind::None;
  Vec3 color1{1, 1, 1};
  Vec3 color2{0, 0, 0};
  double scale = 1;  // size of one checker square in surface units
};

struct Material {
  std::string name;
  ShadingModel model = ShadingModel::Phong;
  Vec3 ambient{1, 1, 1};  // multiplies render.ambient
  Vec3 diffuse{0.8, 0.8, 0.8};
  Vec3 specular{0, 0, 0};
  double shininess = 32;  // specular exponent
  double reflect = 0;     // k_refl: weight of the mirror-reflected ray
  double transmit = 0;    // k_trans: weight of the refracted ray and shadow transmission
  double ior = 1;         // index of refraction of the object's inside
  Texture texture;        // multiplies ambient and diffuse
};

struct Light {
  Vec3 position{0, 10, 0};
  Vec3 color{1, 1, 1};
  double intensity = 1;
};

enum class ObjectType { Sphere = 0, Box = 1, Plane = 2, Triangle = 3 };

struct Object {
  ObjectType type = ObjectType::Sphere;
  int material = 0;  // index into Scene::materials
  Transform transform;  // object to world
  // Sphere: center, radius. Box: box_min, box_max. Plane: point, normal.
  // Triangle: vertices (already in world space when the transform was applied).
  Vec3 center;
  double radius = 1;
  Vec3 box_min, box_max;
  Vec3 point, normal{0, 1, 0};
  Vec3 vertices[3];
};

struct Scene {
  std::string source;  // file path or the name given to the loader
  Camera camera;
  Film film;
  RenderSettings render;
  std::vector<Material> materials;  // index 0 is always present (the default material)
  std::vector<Light> lights;
  std::vector<Object> objects;
  std::vector<std::string> warnings;
};

// The material objects use when they name none.
Material defaultMaterial();

}  // namespace prism
