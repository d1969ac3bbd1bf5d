// The scene model's two pieces of behaviour: the material that objects fall
// back to, and the texels its images hold together.
#include "scene/scene.h"

#include <set>

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

std::size_t imageTexelsHeld(const Scene& scene) {
  std::set<const ImageTexture*> counted;
  std::size_t texels = 0;
  for (const Material& m : scene.materials) {
    const ImageTexture* image = m.texture.kind == Texture::Kind::Image ? m.texture.image.get() : nullptr;
    if (image && counted.insert(image).second) texels += static_cast<std::size_t>(image->width) * image->height;
  }
  return texels;
}

}  // namespace prism
