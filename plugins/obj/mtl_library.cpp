// MTL through tinyobjloader; see mtl_library.h.
#include "obj/mtl_library.h"

#include <map>
#include <sstream>

#include <tiny_obj_loader.h>

#include "common/file_bytes.h"
#include "common/plugin_failure.h"
#include "common/text_numbers.h"

namespace prism_plugins {

namespace {

// A material library is a few kilobytes; anything near this is not one.
constexpr std::uint64_t kMaxMtlBytes = 64ull << 20;

void copy3(float (&to)[3], const tinyobj::real_t (&from)[3]) {
  for (int i = 0; i < 3; ++i) to[i] = static_cast<float>(from[i]);
}

}  // namespace

MtlLibrary readMtlLibrary(const std::string& path) {
  MtlLibrary lib;
  std::string bytes;
  try {
    bytes = readFileBytes(path, kMaxMtlBytes);
  } catch (const PluginFailure& f) {
    lib.problem = f.what();
    return lib;
  }
  lib.found = true;
  std::istringstream in(bytes);
  std::map<std::string, int> by_name;
  std::vector<tinyobj::material_t> read;
  std::string warn, err;
  tinyobj::LoadMtl(&by_name, &read, &in, &warn, &err);
  for (std::istringstream w(warn + err); std::getline(w, warn);)
    if (!warn.empty()) lib.warnings.push_back(warn);
  for (const tinyobj::material_t& m : read) {
    MtlMaterial out;
    out.name = std::string(trimmed(m.name));
    copy3(out.kd, m.diffuse);
    copy3(out.ka, m.ambient);
    copy3(out.ks, m.specular);
    out.ns = static_cast<float>(m.shininess);
    out.ni = static_cast<float>(m.ior);
    out.d = static_cast<float>(m.dissolve);
    out.illum = m.illum;
    out.map_kd = m.diffuse_texname;
    lib.materials.push_back(std::move(out));
  }
  return lib;
}

}  // namespace prism_plugins
