// The example plugin (plugins/example, ASCII STL in plain C against
// prism_plugin.h alone) loads through the same registry as the others.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>

#include "plugin_test_support.h"

namespace fs = std::filesystem;

TEST_CASE("the example STL plugin reads an ASCII STL", "[plugins][example]") {
  fs::path dir = prism_test::scratchDir("prism_example_stl");
  const fs::path file = dir / "two_facets.stl";
  {
    std::ofstream out(file);
    out << "solid two facets\n"
           "  facet normal 0 0 1\n    outer loop\n      vertex 0 0 0\n      vertex 1 0 0\n      vertex 0 1 0\n"
           "    endloop\n  endfacet\n"
           "  facet normal 0 0 1\n    outer loop\n      vertex 1 0 0\n      vertex 1 1 0\n      vertex 0 1 0\n"
           "    endloop\n  endfacet\n"
           "endsolid two facets\n";
  }
  prism::SharedMesh m = prism::loadMeshFile(file.string(), prism_test::testPluginRegistry());
  CHECK(m->plugin == "stl-example");
  CHECK(m->vertexCount() == 6);  // STL shares no vertices
  CHECK(m->triangleCount() == 2);
  CHECK(m->indices == std::vector<std::uint32_t>{0, 1, 2, 3, 4, 5});
  CHECK(m->normals.size() == 18);
  CHECK(m->positions[9] == 1.0f);

  const fs::path bad = dir / "bad.stl";
  { std::ofstream(bad) << "solid x\n facet normal 0 0 1\n outer loop\n vertex 0 0 zero\n"; }
  CHECK_THROWS_WITH(prism::loadMeshFile(bad.string(), prism_test::testPluginRegistry()),
                    Catch::Contains("bad.stl:4: expected a finite number"));
  fs::remove_all(dir);
}
