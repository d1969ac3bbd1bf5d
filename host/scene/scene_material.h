// Materials of the Whitted model, shared by the scene model and meshes.
#pragma once

#include <string>

#include "scene/vec3.h"

namespace prism {

enum class ShadingModel { Phong = 0, Blinn = 1, CookTorrance = 2 };
enum class MicrofacetDistribution { Beckmann = 0, Ggx = 1 };

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
