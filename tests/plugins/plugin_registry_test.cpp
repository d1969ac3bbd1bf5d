// Plugin discovery and refusal: the built plugins are found and described;
// libraries that are not acceptable plugins are listed with the reason (ABI
// version, missing entry symbol, not loadable); the search path honours
// PRISM_PLUGIN_PATH; extensions pick plugins case-insensitively.
#include <catch2/catch.hpp>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "plugin_test_support.h"

namespace fs = std::filesystem;

namespace {

const prism::PluginCandidate* candidate(const prism::PluginRegistry& r, const std::string& file_name) {
  for (const prism::PluginCandidate& c : r.candidates())
    if (fs::path(c.path).filename() == file_name) return &c;
  return nullptr;
}

}  // namespace

TEST_CASE("the built plugins are found, accepted and described", "[plugins][registry]") {
  const prism::PluginRegistry& r = prism_test::testPluginRegistry();
  for (const char* name : {"obj", "ply", "off", "stl-example"}) {
    INFO(name);
    const prism::LoadedPlugin* p = r.findByName(name);
    REQUIRE(p != nullptr);
    CHECK(p->info->abi_version == PRISM_PLUGIN_ABI_VERSION);
  }
  std::vector<std::string> known = r.knownExtensions();
  CHECK(known == std::vector<std::string>{"obj", "off", "ply", "stl"});
  for (const prism::PluginCandidate& c : r.candidates()) {
    INFO(c.path);
    CHECK(c.accepted);
    CHECK(c.reason.empty());
    CHECK_FALSE(c.description.empty());
  }
}

TEST_CASE("extensions choose the plugin whatever their case", "[plugins][registry]") {
  const prism::PluginRegistry& r = prism_test::testPluginRegistry();
  REQUIRE(r.findByExtension("PLY") != nullptr);
  CHECK(std::string(r.findByExtension("PLY")->info->name) == "ply");
  CHECK(std::string(r.findByExtension(".Obj")->info->name) == "obj");
  CHECK(r.findByExtension("xyz") == nullptr);

  fs::path dir = prism_test::scratchDir("prism_registry_case");
  fs::copy_file(prism_test::testDataDir() + "/formats/ply/openmesh/cube-minimal.ply", dir / "CUBE.PLY");
  prism::SharedMesh mesh = prism::loadMeshFile((dir / "CUBE.PLY").string(), r);
  CHECK(mesh->triangleCount() == 12);
  CHECK(mesh->plugin == "ply");
  fs::remove_all(dir);
}

TEST_CASE("libraries that are not acceptable plugins are refused with the reason", "[plugins][registry]") {
  fs::path dir = prism_test::scratchDir("prism_registry_refusals");
  for (const char* f : {"bad_abi.so", "no_entry.so", "unresolved.so"})
    fs::copy_file(fs::path(prism_test::fixtureDir()) / f, dir / f);
  { std::ofstream(dir / "garbage.so") << "this is not an ELF file\n"; }
  { std::ofstream(dir / "README.txt") << "not a library, not even looked at\n"; }
  // A second copy of a real plugin: the first one found keeps the name.
  fs::create_symlink(fs::path(prism_test::pluginDir()) / "off.so", dir / "zz_off_again.so");

  prism::PluginRegistry r({(dir / "missing-folder").string(), dir.string(), prism_test::pluginDir()});
  const prism::PluginCandidate* c = candidate(r, "bad_abi.so");
  REQUIRE(c != nullptr);
  CHECK_FALSE(c->accepted);
  CHECK(c->reason == "ABI 2, expected 1");

  c = candidate(r, "no_entry.so");
  REQUIRE(c != nullptr);
  CHECK_FALSE(c->accepted);
  CHECK_THAT(c->reason, Catch::StartsWith("missing symbol prism_plugin_entry_v1"));

  c = candidate(r, "unresolved.so");
  REQUIRE(c != nullptr);
  CHECK_FALSE(c->accepted);
  CHECK_THAT(c->reason, Catch::StartsWith("not loadable") && Catch::Contains("prism_fixture_function_that_does_not_exist"));

  c = candidate(r, "garbage.so");
  REQUIRE(c != nullptr);
  CHECK_FALSE(c->accepted);
  CHECK_THAT(c->reason, Catch::StartsWith("not loadable"));

  CHECK(candidate(r, "README.txt") == nullptr);
  c = candidate(r, "zz_off_again.so");
  REQUIRE(c != nullptr);
  CHECK(c->accepted);  // found first, in the scratch folder
  c = candidate(r, "off.so");
  REQUIRE(c != nullptr);
  CHECK_FALSE(c->accepted);
  CHECK_THAT(c->reason, Catch::Contains("already loaded from") && Catch::Contains("zz_off_again.so"));

  // Refused plugins claim nothing.
  CHECK(r.findByExtension("badabi") == nullptr);
  CHECK(r.findByExtension("unresolved") == nullptr);
  fs::remove_all(dir);
}

TEST_CASE("the default search path is PRISM_PLUGIN_PATH, then prism/plugins/ and plugins/ next to the library",
          "[plugins][registry]") {
  const char* old = std::getenv("PRISM_PLUGIN_PATH");
  std::string saved = old != nullptr ? old : "";
  setenv("PRISM_PLUGIN_PATH", "/first:/second::/third", 1);
  std::vector<std::string> dirs = prism::PluginRegistry::defaultSearchPath();
  if (old != nullptr) setenv("PRISM_PLUGIN_PATH", saved.c_str(), 1);
  else unsetenv("PRISM_PLUGIN_PATH");
  REQUIRE(dirs.size() == 5);
  CHECK(dirs[0] == "/first");
  CHECK(dirs[1] == "/second");
  CHECK(dirs[2] == "/third");
  // This test binary holds the library code itself (linked statically).
  const fs::path here = fs::canonical("/proc/self/exe").parent_path();
  const fs::path installed(dirs[3]), build_tree(dirs[4]);
  CHECK(installed.filename() == "plugins");
  CHECK(installed.parent_path().filename() == "prism");
  CHECK(fs::equivalent(installed.parent_path().parent_path(), here));
  CHECK(build_tree.filename() == "plugins");
  CHECK(fs::equivalent(build_tree.parent_path(), here));
}

TEST_CASE("files the loader cannot use are refused with the file and the reason", "[plugins][registry]") {
  const prism::PluginRegistry& r = prism_test::testPluginRegistry();
  fs::path dir = prism_test::scratchDir("prism_registry_files");
  { std::ofstream(dir / "mesh.xyz") << "1 2 3\n"; }
  { std::ofstream(dir / "no_extension") << "hello\n"; }
  { std::ofstream(dir / "empty.ply"); }
  { std::ofstream(dir / "broken.obj") << "v 0 0 0\nv 1 0 0\nf 1 2 3\n"; }
  auto errorWith = [](const fs::path& p, const prism::PluginRegistry& registry) {
    try {
      prism::loadMeshFile(p.string(), registry);
    } catch (const prism::MeshError& e) {
      return std::string(e.what());
    }
    return std::string("(loaded)");
  };
  auto error = [&](const fs::path& p) { return errorWith(p, r); };
  CHECK_THAT(error(dir / "mesh.xyz"), Catch::Contains("mesh.xyz") && Catch::Contains("unknown mesh file extension '.xyz'") &&
                                         Catch::Contains(".obj .off .ply .stl"));
  CHECK_THAT(error(dir / "no_extension"), Catch::Contains("no file extension"));
  CHECK_THAT(error(dir / "empty.ply"), Catch::Contains("empty.ply: the file is empty"));
  CHECK_THAT(error(dir / "absent.ply"), Catch::Contains("absent.ply: cannot open"));
  CHECK_THAT(error(dir), Catch::Contains("is a folder"));
  CHECK_THAT(error(dir / "broken.obj"), Catch::Contains("broken.obj:3: vertex index 3, but 2 vertices"));
  prism::PluginRegistry nothing({(dir / "no-plugins-here").string()});
  CHECK_THAT(errorWith(dir / "broken.obj", nothing), Catch::Contains("no mesh plugins were found"));
  fs::remove_all(dir);
}
