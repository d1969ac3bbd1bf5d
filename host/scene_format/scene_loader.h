// Reads the JSON scene format (docs/scene-format.md) into a Scene.
#pragma once

#include <nlohmann/json_fwd.hpp>
#include <string>

#include "scene/scene.h"
#include "scene/scene_error.h"

namespace prism {

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
