// Materials of the Whitted model, shared by the scene model and meshes.
#pragma once

#include <string>

#include "scene/image_texture.h"
#include "scene/vec3.h"

namespace prism {

enum class ShadingModel { Phong = 0, Blinn = 1, CookTorrance = 2 };
enum class MicrofacetDistribution { Beckmann = 0, Ggx = 1 };

struct Texture {
  enum class Kind { None = 0, Checker = 1, Image = 2 };
  // How an image repeats beyond [0, 1] (TEXTURE_WRAP_* in kernels/shared/material_gpu.h).
  enum class Wrap { Repeat = 0, Clamp = 1, Mirror = 2 };
  Kind kind = Kind::None;
  Vec3 color1{1, 1, 1};
  Vec3 color2{0, 0, 0};
  // Checker: the size of one square in surface units; image: the size of
  // the whole image in texture coordinates.
  double scale = 1;
  SharedImage image;  // Image: its linear texels
  Wrap wrap = Wrap::Repeat;
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
  // Phong-lobe exponents of the reflected and refracted rays around the ideal
  // directions (distributed ray tracing); 0: the ideal direction (mirror, clear).
  double gloss = 0;
  double translucency = 0;
  // Cook-Torrance (kernels/shading/microfacet.h): the microfacets' roughness
  // (Beckmann's RMS slope m, or GGX's alpha) and their distribution; the Fresnel
  // factor comes from `ior`.
  double roughness = 0.3;
  MicrofacetDistribution distribution = MicrofacetDistribution::Beckmann;
  Texture texture;        // multiplies ambient and diffuse
  std::string diffuse_map;  // image file a mesh's material names for diffuse (MTL map_Kd), or ""
};

}  // namespace prism
