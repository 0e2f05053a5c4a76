// scene_loader.h - reads a JSON scene file, applies --set overrides and validates it strictly into a Scene.
//
// Every problem (unreadable file, JSON syntax, unknown key, wrong type, value out of range, inconsistent
// references) throws SceneError with a message of the form
//   <file>: <json.path>: expected <what>, got <value>
// e.g. "scenes/x.json: bodies[0].particles_per_cell: expected an integer n^2 (1, 4, 9, 16, ...), got 5".
// The accepted keys, defaults and ranges are documented in docs/scenes.md.
#pragma once

#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "scene/scene.h"
#include "scene/scene_reader.h"

namespace cdmpm {

// Reads `path`, applies `overrides` (each "key.path=value", see apply_override), validates and returns the
// scene. Throws SceneError on any problem.
Scene load_scene(const std::string& path, const std::vector<std::string>& overrides = {});

// Same from an already-parsed json; `path` is used in messages and for the default scene name.
Scene scene_from_json(nlohmann::json j, const std::string& path,
                      const std::vector<std::string>& overrides = {});

// Applies one override "a.b.0.c=value" to `j`: components are separated by '.', numeric components index
// arrays, others are object keys. All components but the last must exist; the last may be a new object key.
// The value is parsed as JSON when possible, otherwise taken as a plain string. `file` is used in messages.
void apply_override(nlohmann::json& j, const std::string& override_text, const std::string& file);

}  // namespace cdmpm
