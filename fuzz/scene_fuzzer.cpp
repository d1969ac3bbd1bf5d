// libFuzzer target for the JSON scene loader: any bytes as a scene file's text.
// A SceneError (or a MeshError from a mesh the text names) is the expected
// answer to a bad scene; anything else -- a crash, a sanitizer report, another
// exception type, a hang -- is a finding. Mesh paths are resolved against an
// empty folder, so the loader's own checks answer them.
#include <cstddef>
#include <cstdint>
#include <string>

#include "mesh/mesh_error.h"
#include "scene_format/scene_loader.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    prism::Scene scene = prism::parseScene(text, "/nonexistent-fuzz-dir/scene.json");
    (void)scene;
  } catch (const prism::SceneError&) {
  } catch (const prism::MeshError&) {
  }
  return 0;
}
