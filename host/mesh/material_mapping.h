// Maps a plugin's material description (MTL fields) onto prism's Whitted
// material. The mapping is documented in docs/plugins.md:
//   Kd -> diffuse, Ka -> ambient, Ks -> specular, Ns -> shininess, Ni -> ior,
//   d (or 1 - Tr) -> transmit = 1 - d,
//   illum 3 -> mirror: reflect = max(Ks), or 1 when Ks is black,
//   illum 4, 6, 7 -> glass: refraction with ior; the kernels have no Fresnel
//   term, so the normal-incidence reflectance R0 = ((n-1)/(n+1))^2 is the
//   reflected weight and (1 - R0) scales the transmitted one,
//   map_Kd -> diffuse_map, resolved against the mesh file's folder.
#pragma once

#include <string>

#include "prism_plugin.h"
#include "scene/scene_material.h"

namespace prism {

// Reads only the fields that desc->struct_size says exist; non-finite or
// out-of-range numbers are clamped to the nearest sensible value.
Material materialFromDesc(const PrismMaterialDesc& desc, const std::string& base_dir);

}  // namespace prism
