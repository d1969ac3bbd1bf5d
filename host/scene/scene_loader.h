// Reads the JSON scene format (docs/scene-format.md) into a Scene.
#pragma once

#include <nlohmann/json_fwd.hpp>
#include <stdexcept>
#include <string>

#include "scene/scene.h"

namespace prism {

// A bad scene: the message names the file, the JSON path (objects[3].radius) or
// line:column, and what was expected.
class SceneError : public std::runtime_error {
 public:
  explicit SceneError(const std::string& message) : std::runtime_error(message) {}
};

// Thrown when the file itself cannot be opened or read.
class SceneIoError : public SceneError {
 public:
  using SceneError::SceneError;
};

Scene loadSceneFile(const std::string& path);
// `name` stands for the file in messages.
Scene parseScene(const std::string& json_text, const std::string& name);

// Adds a fragment of the scene format (any of camera, film, render, materials,
// lights, objects) to `scene`, with the loader's own checks and messages: this
// is how the C API builds scenes, so a value a file may not hold, a call may
// not pass either. `name` stands for the fragment in messages; relative mesh
// files are found from `base_dir`. Lights and objects are appended (messages
// give the index each would have had: objects[7]), materials are added by name
// (a name may not be taken twice, except "default", which replaces the built-in
// material), and the camera, film and render keys given replace the scene's.
// On an error the scene is left as it was.
void addSceneJson(Scene& scene, const std::string& json_text, const std::string& name, const std::string& base_dir);
// The same for a fragment already in memory; its materials are added in key order.
void addSceneFragment(Scene& scene, const nlohmann::json& fragment, const std::string& name,
                      const std::string& base_dir);

}  // namespace prism
