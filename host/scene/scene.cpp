// The scene model's one piece of behaviour: the material that objects fall back to.
#include "scene/scene.h"

namespace prism {

Material defaultMaterial() {
  Material m;
  m.name = "default";
  m.model = ShadingModel::Phong;
  m.ambient = Vec3::splat(1);
  m.diffuse = Vec3::splat(0.8);
  m.specular = Vec3::splat(0);
  return m;
}

}  // namespace prism
