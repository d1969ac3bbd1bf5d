// MTL materials reach prism's Whitted materials as documented in
// docs/plugins.md: colours and exponents as written, d/Tr to transmission,
// illum 3 to a mirror, illum 4/6/7 to glass, map_Kd to a resolved path; and
// faces point at the material named by the usemtl before them.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "plugin_test_support.h"

namespace fs = std::filesystem;

namespace {

const prism::Material& named(const prism::TriangleMesh& m, const std::string& name) {
  for (const prism::Material& mat : m.materials)
    if (mat.name == name) return mat;
  FAIL("no material " << name);
  return m.materials.front();
}

}  // namespace

TEST_CASE("MTL fields map onto prism materials", "[plugins][materials]") {
  fs::path dir = prism_test::scratchDir("prism_mtl_mapping");
  fs::create_directories(dir / "textures");
  { std::ofstream(dir / "textures" / "wood.png") << "not really a PNG"; }
  {
    std::ofstream mtl(dir / "mats.mtl");
    mtl << "newmtl plain\nKa 0.1 0.2 0.3\nKd 0.5 0.25 0.125\nKs 0.75 0.5 0.25\nNs 64\nillum 2\n"
           "map_Kd textures/wood.png\n"
           "newmtl mirror\nKd 0 0 0\nKs 0.5 0.8 0.25\nillum 3\n"
           "newmtl black_mirror\nKs 0 0 0\nillum 3\n"
           "newmtl glass\nKs 1 1 1\nNi 1.5\nillum 7\n"
           "newmtl tinted\nKd 1 0 0\nd 0.25\nNi 1.3\nillum 2\n"
           "newmtl tr_only\nTr 0.4\n";
  }
  {
    std::ofstream obj(dir / "quad.obj");
    obj << "mtllib mats.mtl\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
           "f 1 2 3\nusemtl glass\nf 1 3 4\nusemtl unknown\nf 1 2 4\nusemtl mirror\nf 2 3 4\n";
  }
  prism::SharedMesh m = prism::loadMeshFile((dir / "quad.obj").string(), prism_test::testPluginRegistry());
  REQUIRE(m->materials.size() == 6);

  const prism::Material& plain = named(*m, "plain");
  CHECK(plain.ambient == prism::Vec3(0.1f, 0.2f, 0.3f));
  CHECK(plain.diffuse == prism::Vec3(0.5, 0.25, 0.125));
  CHECK(plain.specular == prism::Vec3(0.75, 0.5, 0.25));
  CHECK(plain.shininess == 64);
  CHECK(plain.reflect == 0);
  CHECK(plain.transmit == 0);
  CHECK(plain.diffuse_map == (dir / "textures" / "wood.png").string());

  CHECK(named(*m, "mirror").reflect == Approx(0.8));          // max(Ks)
  CHECK(named(*m, "black_mirror").reflect == 1);              // Ks black: a perfect mirror
  const prism::Material& glass = named(*m, "glass");
  CHECK(glass.ior == Approx(1.5));
  CHECK(glass.reflect == Approx(0.04));                       // ((1.5-1)/(1.5+1))^2
  CHECK(glass.transmit == Approx(0.96));
  const prism::Material& tinted = named(*m, "tinted");
  CHECK(tinted.transmit == Approx(0.75));                     // 1 - d
  CHECK(tinted.ior == Approx(1.3f));
  CHECK(tinted.reflect == 0);
  CHECK(named(*m, "tr_only").transmit == Approx(0.4));        // Tr = 1 - d

  // Triangles follow usemtl; unknown names fall back to the object's material (-1).
  CHECK(m->triangle_materials == std::vector<std::int32_t>{-1, 3, -1, 1});
  bool warned = false;
  for (const std::string& w : m->warnings) warned = warned || w.find("'unknown'") != std::string::npos;
  CHECK(warned);
  fs::remove_all(dir);
}

TEST_CASE("the Mori knob's materials load from its MTL", "[plugins][materials]") {
  prism::SharedMesh m =
      prism::loadMeshFile(prism_test::testDataDir() + "/meshes/mori_knob/testObj.obj", prism_test::testPluginRegistry());
  CHECK(m->triangleCount() == 11970);
  REQUIRE(m->materials.size() == 5);
  CHECK(named(*m, "InnerMat").reflect == Approx(0.3));    // illum 3, Ks .3
  CHECK(named(*m, "OuterMat").transmit > 0.9);             // illum 4: glass
  CHECK(named(*m, "OuterMat").ior == Approx(1.01f));
  CHECK(named(*m, "BackGroundMat").diffuse == prism::Vec3(0.6f, 0.6f, 0.6f));
}
