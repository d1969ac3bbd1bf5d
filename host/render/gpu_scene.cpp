#include "render/gpu_scene.h"

#include <cmath>

namespace prism {
namespace {

void put3(float* dst, const Vec3& v) {
  dst[0] = static_cast<float>(v.x);
  dst[1] = static_cast<float>(v.y);
  dst[2] = static_cast<float>(v.z);
}

void put4(float* dst, const Vec3& v, double w = 0) {
  put3(dst, v);
  dst[3] = static_cast<float>(w);
}

ObjectGpu flattenObject(const Object& ob) {
  ObjectGpu g{};
  g.type = static_cast<int>(ob.type);
  g.material = ob.material;
  switch (ob.type) {
    case ObjectType::Sphere:
      put3(g.p, ob.center);
      g.p[3] = static_cast<float>(ob.radius);
      break;
    case ObjectType::Box:
      put3(g.p, ob.box_min);
      put3(g.p + 3, ob.box_max);
      break;
    case ObjectType::Plane:
      put3(g.p, ob.point);
      put3(g.p + 3, normalize(ob.normal));
      break;
    case ObjectType::Triangle:
      for (int i = 0; i < 3; ++i) put3(g.p + 3 * i, ob.vertices[i]);
      break;
  }
  g.has_transform = ob.transform.isIdentity() ? 0 : 1;
  Transform inv = g.has_transform ? ob.transform.inverse() : Transform::identity();
  for (int r = 0; r < 3; ++r)
    for (int c = 0; c < 4; ++c) g.world_to_object[4 * r + c] = static_cast<float>(inv.m[r][c]);
  return g;
}

MaterialGpu flattenMaterial(const Material& m) {
  MaterialGpu g{};
  put4(g.ambient, m.ambient);
  put4(g.diffuse, m.diffuse);
  put4(g.specular, m.specular);
  put4(g.checker1, m.texture.color1);
  put4(g.checker2, m.texture.color2);
  g.shininess = static_cast<float>(m.shininess);
  g.reflect = static_cast<float>(m.reflect);
  g.transmit = static_cast<float>(m.transmit);
  g.ior = static_cast<float>(m.ior);
  g.model = static_cast<int>(m.model);
  g.texture = static_cast<int>(m.texture.kind);
  g.texture_scale = static_cast<float>(m.texture.scale);
  return g;
}

}  // namespace

CameraBasis cameraBasis(const Camera& camera, int width, int height) {
  CameraBasis b;
  b.origin = camera.position;
  b.forward = normalize(camera.look_at - camera.position);
  Vec3 right = normalize(cross(b.forward, camera.up));
  Vec3 up = cross(right, b.forward);
  const double pi = 3.14159265358979323846;
  double tan_half = std::tan(camera.fov * pi / 360.0);
  double aspect = static_cast<double>(width) / height;
  b.right = right * (tan_half * aspect);
  b.up = up * tan_half;
  return b;
}

GpuScene flattenScene(const Scene& scene, const RenderOptions& options) {
  GpuScene g;
  for (const Object& ob : scene.objects) g.objects.push_back(flattenObject(ob));
  for (const Material& m : scene.materials) g.materials.push_back(flattenMaterial(m));
  for (const Light& l : scene.lights) {
    LightGpu lg{};
    put4(lg.position, l.position);
    put4(lg.color, l.color * l.intensity);
    g.lights.push_back(lg);
  }
  put4(g.ambient, scene.render.ambient);
  put4(g.background, scene.render.background);
  CameraBasis b = cameraBasis(scene.camera, options.width, options.height);
  put4(g.camera.origin, b.origin);
  put4(g.camera.forward, b.forward);
  put4(g.camera.right, b.right);
  put4(g.camera.up, b.up);
  g.camera.width = options.width;
  g.camera.height = options.height;
  g.camera.spp = options.spp;
  g.camera.seed = static_cast<int>(static_cast<std::uint32_t>(options.seed ^ (options.seed >> 32)));
  return g;
}

}  // namespace prism
