// meshFromArrays: a caller's arrays go through the same validation as files.
#include <catch2/catch.hpp>

#include <cmath>
#include <limits>

#include "mesh/mesh_loader.h"

TEST_CASE("meshFromArrays copies a valid mesh", "[plugins][arrays]") {
  const float xyz[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 0, 0, 1};
  const std::uint32_t tri[] = {0, 1, 2, 0, 2, 3};
  prism::SharedMesh m = prism::meshFromArrays(xyz, 4, tri, 2, "two triangles");
  CHECK(m->vertexCount() == 4);
  CHECK(m->triangleCount() == 2);
  CHECK(m->face_count == 2);
  CHECK(m->source == "two triangles");
  CHECK(m->degenerate_count == 0);
  CHECK(m->warnings.empty());
  CHECK(m->positions == std::vector<float>(xyz, xyz + 12));
}

TEST_CASE("meshFromArrays honours a position stride", "[plugins][arrays]") {
  // xyz plus one unrelated float per vertex.
  const float interleaved[] = {0, 0, 0, 9, 1, 0, 0, 9, 0, 1, 0, 9};
  const std::uint32_t tri[] = {0, 1, 2};
  prism::SharedMesh m = prism::meshFromArrays(interleaved, 3, tri, 1, "strided", 4 * sizeof(float));
  CHECK(m->positions == std::vector<float>{0, 0, 0, 1, 0, 0, 0, 1, 0});
  CHECK_THROWS_WITH(prism::meshFromArrays(interleaved, 3, tri, 1, "strided", 6), Catch::Contains("stride"));
}

TEST_CASE("meshFromArrays refuses bad input, naming the vertex or triangle", "[plugins][arrays]") {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  const float with_nan[] = {0, 0, 0, 1, nan, 0, 0, 1, 0};
  const float with_inf[] = {0, 0, 0, 1, 0, 0, 0, -inf, 0};
  const float ok[] = {0, 0, 0, 1, 0, 0, 0, 1, 0};
  const std::uint32_t tri[] = {0, 1, 2};
  const std::uint32_t out_of_range[] = {0, 1, 3};
  CHECK_THROWS_WITH(prism::meshFromArrays(with_nan, 3, tri, 1, "nan mesh"),
                    Catch::StartsWith("nan mesh: vertex 1 ") && Catch::Contains("non-finite"));
  CHECK_THROWS_WITH(prism::meshFromArrays(with_inf, 3, tri, 1, "inf mesh"), Catch::Contains("vertex 2 "));
  CHECK_THROWS_WITH(prism::meshFromArrays(ok, 3, out_of_range, 1, "idx"),
                    Catch::Contains("triangle 0") && Catch::Contains("uses vertex 3") && Catch::Contains("only 3 vertices"));
  CHECK_THROWS_WITH(prism::meshFromArrays(nullptr, 3, tri, 1, "null"), Catch::Contains("positions are NULL"));
  CHECK_THROWS_WITH(prism::meshFromArrays(ok, 3, nullptr, 1, "null"), Catch::Contains("indices are NULL"));
  CHECK_THROWS_AS(prism::meshFromArrays(ok, 3, out_of_range, 1), prism::MeshError);
}

TEST_CASE("degenerate triangles are kept in place and counted", "[plugins][arrays]") {
  // Triangle 1 repeats a vertex, triangle 2 is collinear: both zero-area.
  const float xyz[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 2, 0, 0};
  const std::uint32_t tris[] = {0, 1, 2, 0, 1, 1, 0, 1, 3, 2, 1, 0};
  prism::SharedMesh m = prism::meshFromArrays(xyz, 4, tris, 4, "degenerate");
  CHECK(m->triangleCount() == 4);  // numbering still follows the input
  CHECK(m->degenerate_count == 2);
  REQUIRE(m->warnings.size() == 1);
  CHECK_THAT(m->warnings[0], Catch::StartsWith("2 degenerate"));
  CHECK(std::vector<std::uint32_t>(m->indices.begin() + 3, m->indices.begin() + 6) == std::vector<std::uint32_t>{0, 1, 1});
}

TEST_CASE("a point cloud is a valid mesh of zero triangles", "[plugins][arrays]") {
  const float xyz[] = {0, 0, 0, 1, 2, 3};
  prism::SharedMesh m = prism::meshFromArrays(xyz, 2, nullptr, 0, "points");
  CHECK(m->vertexCount() == 2);
  CHECK(m->triangleCount() == 0);
}
