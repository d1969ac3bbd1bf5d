// The errors of a bad scene, thrown by the scene format's reader and by the
// JSON reading that each primitive kind does for its own keys.
#pragma once

#include <stdexcept>
#include <string>

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

}  // namespace prism
