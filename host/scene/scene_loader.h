// Reads the JSON scene format (docs/scene-format.md) into a Scene.
#pragma once

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

}  // namespace prism
