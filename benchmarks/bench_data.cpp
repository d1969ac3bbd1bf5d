#include "bench_data.h"

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <sstream>
#include <stdexcept>

#include "loop_subdivision.h"

namespace prism::bench {
namespace {

// The benchmark ladder, smallest first (shared/data/README.md, "Benchmark ladder").
const char* const kLadder[] = {"bunny/bun_zipper_res4.ply",     "bunny/bun_zipper_res3.ply", "spot/spot.obj",
                               "teapot/teapot.obj",             "mori_knob/testObj.obj",     "bunny/bun_zipper_res2.ply",
                               "dragon/dragon_vcg_43k.ply",     "bunny/bun_zipper.ply",      "armadillo/armadillo.obj",
                               "dragon/dragon_100k_vcgflags.ply", "bunny/bunny_loop2_1.1M.ply"};

// The one ladder mesh prism-bench can make: the 69k bunny Loop-subdivided twice
// (69,451 x 16 = 1,111,216 triangles), as the shared data set's copy was made.
const char* const kDerivedName = "bunny/bunny_loop2_1.1M.ply";
const char* const kDerivedFrom = "bunny/bun_zipper.ply";
constexpr int kDerivedSteps = 2;

std::string derivedPath() { return PRISM_BINARY_DIR "/bench-data/" + std::string(kDerivedName); }

std::string firstFound(const std::string& name, const std::vector<std::string>& dirs) {
  for (const std::string& d : dirs) {
    const std::string p = d + "/" + name;
    if (std::filesystem::is_regular_file(p)) return p;
  }
  return {};
}

std::string searched(const std::vector<std::string>& dirs) {
  std::string s;
  for (const std::string& d : dirs) s += (s.empty() ? "" : ", ") + d;
  return s;
}

// The derived mesh, made now if it is not cached; empty if its source is absent.
std::string derive(const std::vector<std::string>& dirs, std::vector<std::string>* notes) {
  const std::string out = derivedPath();
  if (std::filesystem::is_regular_file(out)) return out;
  const std::string source = firstFound(kDerivedFrom, dirs);
  if (source.empty()) return {};
  const auto start = std::chrono::steady_clock::now();
  writeLoopSubdivided(source, out, kDerivedSteps);
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::ostringstream note;
  note << "made " << out << " from " << source << " by " << kDerivedSteps << " steps of Loop subdivision (OpenMesh) in "
       << seconds << " s";
  if (notes) notes->push_back(note.str());
  return out;
}

}  // namespace

std::vector<std::string> benchDataDirs(const std::string& data_dir) {
  std::vector<std::string> dirs;
  const char* env = std::getenv("PRISM_BENCH_DATA");
  if (!data_dir.empty())
    dirs.push_back(data_dir);
  else if (env && *env)
    dirs.push_back(env);
  const std::string shared = PRISM_SOURCE_DIR "/../shared/data/meshes";
  if (std::filesystem::is_directory(shared)) dirs.push_back(std::filesystem::canonical(shared).string());
  dirs.push_back(PRISM_SOURCE_DIR "/tests/data/meshes");
  return dirs;
}

BenchLadder benchLadder(const std::string& data_dir) {
  const std::vector<std::string> dirs = benchDataDirs(data_dir);
  BenchLadder ladder;
  for (const char* name : kLadder) {
    std::string path = firstFound(name, dirs);
    if (path.empty() && std::string(name) == kDerivedName) path = derive(dirs, &ladder.notes);
    if (path.empty())
      ladder.skipped.push_back(name);
    else
      ladder.files.push_back(path);
  }
  if (!ladder.skipped.empty()) {
    std::string names;
    for (const std::string& n : ladder.skipped) names += (names.empty() ? "" : ", ") + n;
    ladder.notes.push_back("skipped " + names + ": not under " + searched(dirs) +
                           " (point --data or PRISM_BENCH_DATA at a folder that has them)");
  }
  return ladder;
}

std::string findBenchMesh(const std::string& name, const std::string& data_dir) {
  const std::vector<std::string> dirs = benchDataDirs(data_dir);
  std::string path = firstFound(name, dirs);
  if (path.empty() && name == kDerivedName) path = derive(dirs, nullptr);
  if (path.empty()) throw std::runtime_error(name + ": not under " + searched(dirs));
  return path;
}

}  // namespace prism::bench
