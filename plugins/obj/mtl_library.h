// Reads Wavefront MTL material libraries with tinyobjloader (Debian's
// libtinyobjloader-dev), which knows the whole MTL vocabulary: illum, Ni, d
// and Tr (d wins when both are given), texture statements with options and
// file names containing spaces, PBR extensions it skips. This file only
// bounds the input (a regular file of limited size, read by us, so a library
// named /dev/zero cannot hang the load) and converts tinyobjloader's
// material_t into the plugin ABI's PrismMaterialDesc fields.
#pragma once

#include <string>
#include <vector>

namespace prism_plugins {

struct MtlMaterial {
  std::string name;  // trimmed of surrounding blanks
  float kd[3], ka[3], ks[3];
  float ns, ni, d;
  int illum;
  std::string map_kd;  // as written in the MTL, "" if none
};

struct MtlLibrary {
  bool found = false;                 // false: missing or unreadable (see problem)
  std::string problem;
  std::vector<MtlMaterial> materials;
  std::vector<std::string> warnings;  // tinyobjloader's, one per line
};

// path: the library's path as the OBJ's folder sees it.
MtlLibrary readMtlLibrary(const std::string& path);

}  // namespace prism_plugins
