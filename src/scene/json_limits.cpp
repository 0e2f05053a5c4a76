// json_limits.cpp - the input bounds of json_limits.h.
#include "scene/json_limits.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "scene/scene_loader.h"

namespace cdmpm {

size_t json_nesting_depth(std::string_view text) {
  size_t depth = 0, deepest = 0;
  bool in_string = false, escaped = false;
  for (const char c : text) {
    if (in_string) {
      if (escaped) escaped = false;
      else if (c == '\\') escaped = true;
      else if (c == '"') in_string = false;
    } else if (c == '"') {
      in_string = true;
    } else if (c == '[' || c == '{') {
      deepest = std::max(deepest, ++depth);
      if (deepest > kMaxJsonDepth) break;
    } else if ((c == ']' || c == '}') && depth > 0) {
      --depth;
    }
  }
  return deepest;
}

void check_json_depth(std::string_view text, const std::string& where) {
  if (json_nesting_depth(text) > kMaxJsonDepth)
    throw SceneError(where + ": JSON nested more than " + std::to_string(kMaxJsonDepth) +
                     " levels deep (the limit; arrays and objects count)");
}

std::string read_scene_text(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status st = fs::status(path, ec);
  if (ec || !fs::exists(st)) throw SceneError(path + ": cannot open file (no such file)");
  if (fs::is_directory(st)) throw SceneError(path + ": is a directory, expected a scene file (JSON)");
  if (!fs::is_regular_file(st)) throw SceneError(path + ": not a regular file, expected a scene file (JSON)");
  const uintmax_t size = fs::file_size(path, ec);
  if (ec || size > kMaxSceneFileBytes)
    throw SceneError(path + ": scene file larger than " + std::to_string(kMaxSceneFileBytes >> 20) +
                     " MiB (the limit)");
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  if (!in || !(text << in.rdbuf())) {
    if (size == 0) return "";
    throw SceneError(path + ": cannot read file");
  }
  return text.str();
}

void check_scene_name(const std::string& name, const std::string& file) {
  const bool control = std::any_of(name.begin(), name.end(), [](unsigned char c) { return c < 0x20 || c == 0x7f; });
  const bool bad = name.empty() || name.size() > 128 || name.find_first_of("/\\") != std::string::npos || control ||
                   name.front() == '.' || name.front() == '-';
  if (bad)
    throw SceneError(file + ": name: expected a plain folder name (no '/', '\\', control characters, leading '.' or "
                     "'-', at most 128 characters), got \"" + name.substr(0, 60) + "\"");
}

}  // namespace cdmpm
