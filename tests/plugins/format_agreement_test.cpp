// The same mesh written as OBJ, PLY (ascii, binary little- and big-endian)
// and OFF loads as the same TriangleMesh: positions bit for bit and indices
// in the same order. The files are written here, from one small mesh whose
// coordinates are exact in binary and decimal, with a quad and a pentagon so
// that the shared fan triangulation is exercised too.
#include <catch2/catch.hpp>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <vector>

#include "plugin_test_support.h"

namespace {

struct SmallMesh {
  std::vector<float> xyz;
  std::vector<std::vector<std::uint32_t>> faces;
};

// A square pyramid with its base split into a pentagon-and-quad pair.
SmallMesh pyramid() {
  SmallMesh m;
  m.xyz = {-1, 0, -1, 1, 0, -1, 1, 0, 1, -1, 0, 1, 0, 1.5f, 0, 0, 0, -1.5f, 0, 0, 1.5f, 0.25f, -0.125f, 3.75f};
  m.faces = {{0, 5, 1, 2, 6}, {0, 6, 3}, {0, 4, 5}, {5, 4, 1}, {1, 4, 2}, {2, 4, 3}, {3, 4, 0}, {6, 7, 3, 2}};
  return m;
}

std::string writeObj(const SmallMesh& m, const std::string& path) {
  std::ofstream out(path);
  out << "# written by format_agreement_test\n";
  for (std::size_t v = 0; v < m.xyz.size() / 3; ++v) out << "v " << m.xyz[3 * v] << ' ' << m.xyz[3 * v + 1] << ' ' << m.xyz[3 * v + 2] << '\n';
  // Negative (relative) indices on every other face: same vertices.
  const long n = static_cast<long>(m.xyz.size() / 3);
  for (std::size_t f = 0; f < m.faces.size(); ++f) {
    out << 'f';
    for (std::uint32_t i : m.faces[f]) out << ' ' << (f % 2 ? static_cast<long>(i) - n : static_cast<long>(i) + 1);
    out << '\n';
  }
  return path;
}

std::string writeOff(const SmallMesh& m, const std::string& path) {
  std::ofstream out(path);
  out << "OFF\n# written by format_agreement_test\n" << m.xyz.size() / 3 << ' ' << m.faces.size() << " 0\n";
  for (std::size_t v = 0; v < m.xyz.size() / 3; ++v) out << m.xyz[3 * v] << ' ' << m.xyz[3 * v + 1] << ' ' << m.xyz[3 * v + 2] << '\n';
  for (const auto& f : m.faces) {
    out << f.size();
    for (std::uint32_t i : f) out << ' ' << i;
    out << '\n';
  }
  return path;
}

std::string plyHeader(const SmallMesh& m, const char* format) {
  return std::string("ply\nformat ") + format + " 1.0\ncomment written by format_agreement_test\nelement vertex " +
         std::to_string(m.xyz.size() / 3) + "\nproperty float x\nproperty float y\nproperty float z\nelement face " +
         std::to_string(m.faces.size()) + "\nproperty list uchar int vertex_indices\nend_header\n";
}

std::string writePlyAscii(const SmallMesh& m, const std::string& path) {
  std::ofstream out(path);
  out << plyHeader(m, "ascii");
  for (std::size_t v = 0; v < m.xyz.size() / 3; ++v) out << m.xyz[3 * v] << ' ' << m.xyz[3 * v + 1] << ' ' << m.xyz[3 * v + 2] << '\n';
  for (const auto& f : m.faces) {
    out << f.size();
    for (std::uint32_t i : f) out << ' ' << i;
    out << '\n';
  }
  return path;
}

template <typename T>
void putBinary(std::ofstream& out, T value, bool big_endian) {
  unsigned char raw[sizeof(T)];
  std::memcpy(raw, &value, sizeof(T));
  if (big_endian)  // this test runs on little-endian hosts (x86-64, arm64)
    for (std::size_t i = 0; i < sizeof(T) / 2; ++i) std::swap(raw[i], raw[sizeof(T) - 1 - i]);
  out.write(reinterpret_cast<const char*>(raw), sizeof(T));
}

std::string writePlyBinary(const SmallMesh& m, const std::string& path, bool big_endian) {
  std::ofstream out(path, std::ios::binary);
  out << plyHeader(m, big_endian ? "binary_big_endian" : "binary_little_endian");
  for (float c : m.xyz) putBinary(out, c, big_endian);
  for (const auto& f : m.faces) {
    putBinary(out, static_cast<std::uint8_t>(f.size()), big_endian);
    for (std::uint32_t i : f) putBinary(out, static_cast<std::int32_t>(i), big_endian);
  }
  return path;
}

}  // namespace

TEST_CASE("one mesh written as OBJ, PLY ascii/binary LE/BE and OFF loads identically", "[plugins][agreement]") {
  const SmallMesh m = pyramid();
  const std::filesystem::path dir = prism_test::scratchDir("prism_format_agreement");
  const std::vector<std::string> files = {
      writeObj(m, (dir / "pyramid.obj").string()),
      writePlyAscii(m, (dir / "pyramid_ascii.ply").string()),
      writePlyBinary(m, (dir / "pyramid_le.ply").string(), false),
      writePlyBinary(m, (dir / "pyramid_be.ply").string(), true),
      writeOff(m, (dir / "pyramid.off").string()),
  };
  // The fan (v0, vk, vk+1) of each face, in file order: what every loader must give.
  std::vector<std::uint32_t> fanned;
  for (const auto& f : m.faces)
    for (std::size_t k = 1; k + 1 < f.size(); ++k) fanned.insert(fanned.end(), {f[0], f[k], f[k + 1]});

  for (const std::string& file : files) {
    INFO(file);
    prism::SharedMesh mesh = prism::loadMeshFile(file, prism_test::testPluginRegistry());
    CHECK(mesh->positions == m.xyz);
    CHECK(mesh->indices == fanned);
    CHECK(mesh->face_count == m.faces.size());
    CHECK(mesh->degenerate_count == 0);
  }
  std::filesystem::remove_all(dir);
}
