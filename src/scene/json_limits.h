// json_limits.h - bounds on scene input checked before any recursive processing of it.
//
// nlohmann::json copies, compares, dumps and walks values recursively, and so do the scene loader and the
// parameter substitution: a file or a --set value nested 100,000 levels deep overflows the stack. Every
// scene text is therefore scanned (iteratively) for its bracket depth first and refused past kMaxJsonDepth.
// The scene file itself must be a regular file of at most kMaxSceneFileBytes. Scene names become a folder
// under output/, so they must be a single, plain path component. All refusals throw SceneError.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace cdmpm {

// Deepest allowed nesting of JSON arrays/objects in a scene file or a --set value (the shipped scenes use 5).
constexpr size_t kMaxJsonDepth = 256;
// Largest scene file read (the shipped scenes are a few kB).
constexpr uintmax_t kMaxSceneFileBytes = uintmax_t(16) << 20;

// Deepest nesting of '[' and '{' in `text`, outside JSON strings; stops counting at kMaxJsonDepth + 1.
size_t json_nesting_depth(std::string_view text);

// Throws SceneError "<where>: JSON nested more than 256 levels deep (the limit)" when `text` is too deep.
void check_json_depth(std::string_view text, const std::string& where);

// The contents of the scene file `path`; throws SceneError naming it when it is missing, not a regular file
// (a directory, a device, a FIFO), larger than kMaxSceneFileBytes or unreadable.
std::string read_scene_text(const std::string& path);

// Throws SceneError unless `name` is usable as one folder name under output/: non-empty, at most 128
// characters, no '/' or '\\', no control characters, not "." or "..", not starting with '-' or '.'.
void check_scene_name(const std::string& name, const std::string& file);

}  // namespace cdmpm
