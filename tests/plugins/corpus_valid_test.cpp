// Every valid file of the corpus (tests/data/formats/{obj,ply,off})
// loads with the vertex, face and triangle counts that tests/data/README.md
// lists. Those numbers come from the curator's independent reference reader,
// so they are copied here by hand, not computed.
#include <catch2/catch.hpp>

#include <filesystem>
#include <set>

#include "plugin_test_support.h"

namespace {

struct Expected {
  const char* path;  // under tests/data/formats/
  long vertices;
  long faces;        // -1: not stated (triangle strips)
  long triangles;
};

// From tests/data/README.md, "Expected (reference reader)" column.
const Expected kExpected[] = {
    {"obj/tinyobjloader/cornell_box.obj", 76, 18, 36},
    {"obj/tinyobjloader/cornell_box_multimaterial.obj", 76, 18, 36},
    {"obj/tinyobjloader/catmark_torus_creases0.obj", 32, 32, 64},
    {"obj/tinyobjloader/cube-vertex-w-component.obj", 8, 6, 12},
    {"obj/tinyobjloader/cube-vertexcol.obj", 8, 6, 12},
    {"obj/tinyobjloader/issue-161-inconsistent-f.obj", 8, 12, 12},
    {"obj/tinyobjloader/issue-319-002.obj", 20, 3, 14},
    {"obj/tinyobjloader/issue-330.obj", 7, 2, 3},
    {"obj/tinyobjloader/leading-decimal-dot-issue-201.obj", 3, 1, 1},
    {"obj/tinyobjloader/leading-zero-in-exponent-notation-issue-210.obj", 3, 1, 1},
    {"obj/tinyobjloader/smoothing-group-two-squares.obj", 6, 2, 3},
    {"obj/tinyobjloader/texture-filename-with-whitespace.obj", 8, 6, 12},
    {"obj/tinyobjloader/mtllib-multiple-files-issue-112.obj", 3, 1, 1},
    {"obj/tinyobjloader/issue-246-usemtl-whitespace.obj", 8, 1, 1},
    {"obj/tinyobjloader/issue-356-leading-spaces-newmtl.obj", 0, 0, 0},
    {"obj/tinyobjloader/tr-and-d-issue-43.obj", 218, 400, 400},
    {"obj/tinyobjloader/refl.obj", 8, 6, 12},
    {"obj/tinyobjloader/pbr-mat-ext.obj", 4, 1, 2},
    {"obj/tinyobjloader/line-prim.obj", 8, 0, 0},
    {"obj/tinyobjloader/points-prim.obj", 8, 0, 0},
    {"obj/tinyobjloader/skin-weight.obj", 8, 6, 12},
    {"obj/tinyobjloader/missing_material_file.obj", 76, 18, 36},
    {"obj/tinyobjloader/usemtl-issue-104.obj", 12, 3, 6},
    {"obj/tinyobjloader/map-bump.obj", 218, 400, 400},
    {"obj/tinyobjloader/texture-options-issue-85.obj", 3, 1, 1},
    {"obj/assimp/box.obj", 8, 6, 12},
    {"obj/assimp/box_without_lineending.obj", 8, 6, 12},
    {"obj/assimp/box_longline.obj", 8, 6, 944},
    {"obj/assimp/box_mat_with_spaces.obj", 8, 6, 12},
    {"obj/assimp/concave_polygon.obj", 64, 1, 64},
    {"obj/assimp/cube_mtllib_after_g.obj", 8, 12, 12},
    {"obj/assimp/cube_usemtl.obj", 8, 12, 12},
    {"obj/assimp/cube_with_vertexcolors.obj", 8, 12, 12},
    {"obj/assimp/empty_mat.obj", 130, 256, 256},
    {"obj/assimp/mtl_different_folder.obj", 8, 6, 12},
    {"obj/assimp/multiple_spaces.obj", 4, 1, 1},
    {"obj/assimp/point_cloud.obj", 3, 0, 0},
    {"obj/assimp/regr01.obj", 2108, 2710, 2710},
    {"obj/assimp/space_in_material_name.obj", 64, 1, 64},
    {"obj/assimp/testmixed.obj", 8, 6, 12},
    {"obj/openmesh/cube-minimal.obj", 8, 12, 12},
    {"obj/openmesh/cube-minimal-texCoords.obj", 8, 12, 12},
    {"obj/openmesh/cube-minimal-vertex-colors-after-vertex-definition.obj", 8, 12, 12},
    {"obj/openmesh/cube-minimal-vertex-colors-as-vc-lines.obj", 8, 12, 12},
    {"obj/openmesh/cube-minimal-degenerated.obj", 8, 14, 16},
    {"obj/openmesh/square_material.obj", 4, 1, 2},
    {"obj/selfmade/line_continuation.obj", 4, 2, 2},
    {"obj/selfmade/all_index_forms.obj", 8, 6, 12},
    {"ply/assimp/cube.ply", 8, 6, 12},
    {"ply/assimp/cube_binary.ply", 8, 12, 12},
    {"ply/assimp/cube_binary_header_with_RN_newline.ply", 8, 12, 12},
    {"ply/assimp/cube_uv.ply", 24, 6, 12},
    {"ply/assimp/float-color.ply", 3, 1, 1},
    {"ply/assimp/points.ply", 4, 0, 0},
    {"ply/openmesh/cube-minimal.ply", 8, 6, 12},
    {"ply/openmesh/cube-minimal-normals.ply", 8, 6, 12},
    {"ply/openmesh/cube-minimal-vertexColors.ply", 8, 12, 12},
    {"ply/openmesh/cube-minimal-faceColors.ply", 8, 12, 12},
    {"ply/openmesh/cube-minimal-texCoords.ply", 8, 12, 12},
    {"ply/openmesh/cube-minimal-custom_props.ply", 8, 6, 12},
    {"ply/openmesh/cube-minimal-extra-elements.ply", 8, 6, 12},
    {"ply/openmesh/cube-minimal-extra-elements-binary.ply", 8, 6, 12},
    {"ply/openmesh/meshlab.ply", 8, 12, 12},
    {"ply/openmesh/pointCloudBadEncoding.ply", 10, 0, 0},
    {"ply/openmesh/pointCloudGoodEncoding.ply", 10, 0, 0},
    {"ply/openmesh/sphere840.ply", 422, 840, 840},
    {"ply/happly/platonic_shelf.ply", 50, 50, 80},
    {"ply/happly/platonic_shelf_big_endian.ply", 50, 50, 80},
    {"ply/tinyply/icosahedron.ply", 12, 20, 20},
    {"ply/tinyply/icosahedron_ascii.ply", 12, 20, 20},
    {"ply/tinyply/elephant.ply", 19753, -1, 39290},
    {"ply/rply/input.ply", 3, 1, 1},
    {"off/geomview/vertcube.off", 8, 6, 12},
    {"off/geomview/facecube.off", 8, 6, 12},
    {"off/geomview/unitcube.off", 8, 6, 12},
    {"off/geomview/abstr.off", 36, 20, 68},
    {"off/geomview/cube1_no_keyword.off", 8, 6, 12},
    {"off/geomview/dodec.off", 20, 12, 36},
    {"off/geomview/mushroom.off", 226, 240, 448},
    {"off/geomview/tref.off", 1280, 320, 640},
    {"off/assimp/Cube.off", 8, 6, 12},
    {"off/assimp/Wuson.off", 3205, 3732, 3732},
    {"off/assimp/formatDetection", 8, 6, 12},  // no extension: recognised by content
    {"off/openmesh/cube1.off", 7526, 15048, 15048},
    {"off/libigl/bunny.off", 3485, 6966, 6966},
    {"off/libigl/decimated-knight.off", 502, 1000, 1000},
    {"off/libigl/2triangles.off", 4, 2, 2},
    {"off/libigl/grid.off", 145, 256, 256},
    {"off/libigl/cow.off", 2762, 5520, 5520},
    {"off/libigl/inspired_mesh_quads_Smooth.off", 1963, 1838, 3676},
    {"off/off-rs/wiki.off", 8, 6, 12},
    {"off/off-rs/cube.off", 8, 6, 12},
    {"off/FileOff.Tests/box.off", 8, 6, 12},
    {"off/FileOff.Tests/banana.off", 468, 156, 156},
    {"off/FileOff.Tests/socket.off", 836, 1696, 1696},
    {"off/FileOff.Tests/cone.off", 22, 40, 40},
    {"off/selfmade/noff_cube.off", 8, 6, 12},
    {"off/selfmade/cnoff_tetra.off", 4, 4, 4},
    {"off/selfmade/stoff_square.off", 4, 1, 2},
    {"off/selfmade/ngon_comments_counts_inline.off", 7, 3, 6},
};

// The README gives no counts for 4-D OFF: "a 3-D renderer should reject or
// project, not misparse". prism rejects it, naming the reason.
const char* const kRefusedValid = "off/geomview/hypercube.off";

std::string formats() { return prism_test::testDataDir() + "/formats/"; }

}  // namespace

TEST_CASE("every valid corpus file loads with the counts the data README lists", "[plugins][corpus]") {
  for (const Expected& e : kExpected) {
    INFO(e.path);
    prism_test::TimedLoad r = prism_test::loadWithin(formats() + e.path);
    REQUIRE(r.finished);
    INFO(r.error);
    REQUIRE(r.mesh);
    CHECK(static_cast<long>(r.mesh->vertexCount()) == e.vertices);
    if (e.faces >= 0) CHECK(static_cast<long>(r.mesh->face_count) == e.faces);
    CHECK(static_cast<long>(r.mesh->triangleCount()) == e.triangles);
  }
}

TEST_CASE("4-D OFF is refused with its reason", "[plugins][corpus]") {
  prism_test::TimedLoad r = prism_test::loadWithin(formats() + kRefusedValid);
  REQUIRE(r.finished);
  CHECK_FALSE(r.mesh);
  CHECK_THAT(r.error, Catch::Contains("hypercube.off") && Catch::Contains("4OFF"));
}

TEST_CASE("the table covers every mesh file of the valid corpus", "[plugins][corpus]") {
  // A file added to the corpus must be added to the table (with its README
  // counts), or this fails.
  std::set<std::string> listed{kRefusedValid};
  for (const Expected& e : kExpected) listed.insert(e.path);
  for (const char* folder : {"obj", "ply", "off"}) {
    for (const auto& entry : std::filesystem::recursive_directory_iterator(formats() + folder)) {
      if (!entry.is_regular_file() || entry.path().extension() == ".mtl") continue;
      std::string relative = std::filesystem::relative(entry.path(), formats()).string();
      INFO(relative);
      CHECK(listed.count(relative) == 1);
    }
  }
}
