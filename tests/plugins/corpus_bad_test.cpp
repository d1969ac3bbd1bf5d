// Every malformed file of the corpus (tests/data/formats/bad/) is
// refused -- with a message naming the file, in bounded time, without
// crashing the process. OpenMesh 9 hangs on two of them and aborts on one.
#include <catch2/catch.hpp>

#include <filesystem>

#include "plugin_test_support.h"

TEST_CASE("every malformed corpus file is refused, naming the file, in bounded time", "[plugins][corpus][bad]") {
  const std::string bad = prism_test::testDataDir() + "/formats/bad";
  int files = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(bad)) {
    if (!entry.is_regular_file() || entry.path().extension() == ".mtl") continue;  // MTLs come with their OBJ
    const std::string path = entry.path().string();
    INFO(path);
    prism_test::TimedLoad r = prism_test::loadWithin(path, std::chrono::seconds(10));
    REQUIRE(r.finished);
    INFO(r.error);
    CHECK_FALSE(r.mesh);
    CHECK_THAT(r.error, Catch::Contains(entry.path().filename().string()));
    ++files;
  }
  CHECK(files >= 25);
}

TEST_CASE("malformed files are refused for the right reason", "[plugins][corpus][bad]") {
  const std::string bad = prism_test::testDataDir() + "/formats/bad/";
  struct Case {
    const char* path;
    const char* reason;  // a phrase the message must contain
  };
  const Case cases[] = {
      {"off/assimp/OutOfMemory.off", "more than"},
      {"ply/selfmade/missing_end_header.ply", "end_header"},
      {"ply/selfmade/unknown_format.ply", "binary_middle_endian"},
      {"ply/selfmade/nan_inf_coordinates.ply", "not a finite"},
      {"ply/selfmade/face_index_out_of_range.ply", "uses vertex 8"},
      {"off/selfmade/index_out_of_range.off", "uses vertex 8"},
      {"obj/tinyobjloader/issue-140-zero-face-idx.obj", "index 0"},
      {"obj/tinyobjloader/test-nan.obj", "not a finite"},
      {"obj/assimp/empty.obj", "empty"},
      {"obj/assimp/box_UTF16BE.obj", "NUL"},
      {"obj/assimp/number_formats.obj", "3.1+e2"},
  };
  for (const Case& c : cases) {
    INFO(c.path);
    prism_test::TimedLoad r = prism_test::loadWithin(bad + c.path, std::chrono::seconds(10));
    REQUIRE(r.finished);
    CHECK_THAT(r.error, Catch::Contains(c.reason));
  }
}

// Not run by default: `plugin_tests "[dump]"` prints what each corpus file
// gives (counts, warnings, or the error), to review messages by eye.
TEST_CASE("print every corpus file's outcome", "[.][dump]") {
  for (const auto& entry : std::filesystem::recursive_directory_iterator(prism_test::testDataDir() + "/formats")) {
    if (!entry.is_regular_file() || entry.path().extension() == ".mtl") continue;
    prism_test::TimedLoad r = prism_test::loadWithin(entry.path().string(), std::chrono::seconds(10));
    std::string name = std::filesystem::relative(entry.path(), prism_test::testDataDir() + "/formats").string();
    if (!r.finished) {
      WARN(name << ": TIMED OUT");
    } else if (r.mesh) {
      std::string text = name + ": " + std::to_string(r.mesh->vertexCount()) + " v, " +
                         std::to_string(r.mesh->face_count) + " f, " + std::to_string(r.mesh->triangleCount()) +
                         " tris, " + std::to_string(r.mesh->materials.size()) + " materials" +
                         (r.mesh->normals.empty() ? "" : ", normals") + (r.mesh->texcoords.empty() ? "" : ", uv") +
                         (r.mesh->colors.empty() ? "" : ", colours");
      for (const std::string& w : r.mesh->warnings) text += "\n    warning: " + w;
      WARN(text);
    } else {
      WARN(name << ": REFUSED: " << r.error);
    }
  }
}
