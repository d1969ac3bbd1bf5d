// MTL fields -> prism Material; see material_mapping.h for the mapping.
#include "mesh/material_mapping.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstring>
#include <filesystem>

namespace prism {

namespace {

double clampFinite(float v, double lo, double hi, double fallback) {
  if (!std::isfinite(v)) return fallback;
  return std::min(hi, std::max(lo, static_cast<double>(v)));
}

Vec3 color(const float* c, const Vec3& fallback) {
  return {clampFinite(c[0], 0, 1, fallback.x), clampFinite(c[1], 0, 1, fallback.y), clampFinite(c[2], 0, 1, fallback.z)};
}

// True if the plugin's struct is large enough to hold `field`.
#define PRISM_DESC_HAS(desc, field) \
  ((desc).struct_size >= offsetof(PrismMaterialDesc, field) + sizeof((desc).field))

}  // namespace

Material materialFromDesc(const PrismMaterialDesc& desc, const std::string& base_dir) {
  Material m;
  if (PRISM_DESC_HAS(desc, name) && desc.name != nullptr) m.name.assign(desc.name, strnlen(desc.name, 1024));
  if (PRISM_DESC_HAS(desc, kd)) m.diffuse = color(desc.kd, m.diffuse);
  if (PRISM_DESC_HAS(desc, ka)) m.ambient = color(desc.ka, m.ambient);
  if (PRISM_DESC_HAS(desc, ks)) m.specular = color(desc.ks, m.specular);
  if (PRISM_DESC_HAS(desc, ns)) m.shininess = clampFinite(desc.ns, 0, 1e4, m.shininess);
  if (PRISM_DESC_HAS(desc, ni)) {
    m.ior = clampFinite(desc.ni, 0, 10, 1);
    if (m.ior <= 0) m.ior = 1;  // Ni 0 is how some exporters say "not set"
  }
  double dissolve = PRISM_DESC_HAS(desc, d) ? clampFinite(desc.d, 0, 1, 1) : 1;
  m.transmit = 1 - dissolve;
  int illum = PRISM_DESC_HAS(desc, illum) ? desc.illum : -1;
  double ks_max = std::max({m.specular.x, m.specular.y, m.specular.z});
  if (illum == 3) {
    m.reflect = ks_max > 0 ? ks_max : 1;
  } else if (illum == 4 || illum == 6 || illum == 7) {
    double r0 = (m.ior - 1) / (m.ior + 1);
    r0 *= r0;
    if (m.transmit == 0) m.transmit = 1;  // glass that says nothing about how much passes
    m.transmit *= 1 - r0;
    m.reflect = r0;
  }
  if (PRISM_DESC_HAS(desc, map_kd) && desc.map_kd != nullptr && desc.map_kd[0] != '\0') {
    std::filesystem::path p(std::string(desc.map_kd, strnlen(desc.map_kd, 4096)));
    if (p.is_relative() && !base_dir.empty()) p = std::filesystem::path(base_dir) / p;
    m.diffuse_map = p.lexically_normal().string();
  }
  return m;
}

#undef PRISM_DESC_HAS

}  // namespace prism
