// Where prism-bench finds its meshes. The benchmark ladder (tests/data/README.md
// and shared/data/README.md list the files) is looked up, file by file, in
//   1. the folder given with --data, else $PRISM_BENCH_DATA,
//   2. ../shared/data/meshes beside the source tree (the development data set),
//   3. tests/data/meshes (the small meshes the repository ships),
// and the 1.1M-triangle bunny, when none of them has it, is derived from the
// 69k Stanford bunny by two steps of Loop subdivision (OpenMesh) and cached
// in the build tree. A ladder file found nowhere is skipped, with a note.
#pragma once

#include <string>
#include <vector>

namespace prism::bench {

struct BenchLadder {
  std::vector<std::string> files;    // found or derived, smallest first
  std::vector<std::string> skipped;  // ladder names found nowhere
  std::vector<std::string> notes;    // one line each: what was derived, what was skipped and why
};

// The folders searched, in order; `data_dir` (from --data) may be empty.
std::vector<std::string> benchDataDirs(const std::string& data_dir);

// The ladder's files resolved through benchDataDirs(data_dir).
BenchLadder benchLadder(const std::string& data_dir);

// One ladder mesh by its name under a data folder (e.g. "bunny/bun_zipper.ply"),
// deriving the 1.1M bunny if needed; throws with the folders searched if absent.
std::string findBenchMesh(const std::string& name, const std::string& data_dir);

}  // namespace prism::bench
