// Shared by the plugin tests: where the built plugins, the fixtures and the
// test data live, a registry over the build tree's plugins, and loads run
// under a time limit so a hanging reader fails its test instead of the suite.
#pragma once

#include <unistd.h>

#include <chrono>
#include <condition_variable>
#include <filesystem>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "mesh/mesh_loader.h"
#include "mesh/plugin_registry.h"
#include "support/test_data.h"

namespace prism_test {

inline std::string pluginDir() { return std::string(PRISM_BINARY_DIR) + "/plugins"; }
inline std::string fixtureDir() { return std::string(PRISM_BINARY_DIR) + "/plugin-fixtures"; }


// A fresh, empty folder for one test's files; the process id keeps tests
// that run in parallel (ctest -j) apart.
inline std::filesystem::path scratchDir(const std::string& name) {
  std::filesystem::path dir = std::filesystem::temp_directory_path() / (name + "_" + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

struct TimedLoad {
  bool finished = false;   // false: still running after the limit (a hang)
  prism::SharedMesh mesh;  // set on success
  std::string error;       // MeshError's message on failure
};

// Loads on a separate thread and waits at most `limit`. A load that overruns
// is left running (detached): the test fails, the rest of the suite goes on.
inline TimedLoad loadWithin(const std::string& path, std::chrono::seconds limit = std::chrono::seconds(20)) {
  struct Shared {
    TimedLoad result;
    bool done = false;
    std::mutex mutex;
    std::condition_variable cv;
  };
  auto shared = std::make_shared<Shared>();
  std::thread([shared, path] {
    TimedLoad r;
    r.finished = true;
    try {
      r.mesh = prism::loadMeshFile(path, testPluginRegistry());
    } catch (const prism::MeshError& e) {
      r.error = e.what();
    } catch (const std::exception& e) {
      r.error = std::string("unexpected exception: ") + e.what();
    }
    std::lock_guard<std::mutex> lock(shared->mutex);
    shared->result = r;
    shared->done = true;
    shared->cv.notify_all();
  }).detach();
  std::unique_lock<std::mutex> lock(shared->mutex);
  shared->cv.wait_for(lock, limit, [&] { return shared->done; });
  return shared->done ? shared->result : TimedLoad{};
}

}  // namespace prism_test
