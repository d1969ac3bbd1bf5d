// MeshCache: objects naming the same file share one TriangleMesh; an edited
// file is read again; a mesh nobody holds is let go.
#include <catch2/catch.hpp>

#include <filesystem>
#include <fstream>
#include <thread>

#include "mesh/mesh_cache.h"
#include "plugin_test_support.h"

namespace fs = std::filesystem;

TEST_CASE("MeshCache shares one mesh per file and notices edits", "[plugins][cache]") {
  fs::path dir = prism_test::scratchDir("prism_mesh_cache");
  const fs::path file = dir / "tri.off";
  { std::ofstream(file) << "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"; }

  prism::MeshCache cache(prism_test::testPluginRegistry());
  prism::SharedMesh a = cache.load(file.string());
  prism::SharedMesh b = cache.load(file.string());
  prism::SharedMesh c = cache.load((dir / "." / "tri.off").string());  // another spelling of the same file
  CHECK(a.get() == b.get());
  CHECK(a.get() == c.get());
  CHECK(cache.size() == 1);

  // Edit the file (new size and modification time): read again.
  { std::ofstream(file) << "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n3 1 3 2\n"; }
  fs::last_write_time(file, fs::last_write_time(file) + std::chrono::seconds(2));
  prism::SharedMesh d = cache.load(file.string());
  CHECK(d.get() != a.get());
  CHECK(d->triangleCount() == 2);
  CHECK(a->triangleCount() == 1);  // holders of the old mesh keep it

  // Entries are weak: once nobody holds a mesh, it is freed.
  a.reset();
  b.reset();
  c.reset();
  CHECK(cache.size() == 1);
  d.reset();
  CHECK(cache.size() == 0);

  // Failures are reported, not cached.
  CHECK_THROWS_AS(cache.load((dir / "absent.off").string()), prism::MeshError);
  fs::remove_all(dir);
}
