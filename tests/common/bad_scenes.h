// bad_scenes.h - the malformed scenes of tests/bad_scenes/patches.json, written to a folder: each row is a base
// scene (tests/bad_scenes/base/) with keys set and deleted, or a file kept as it is (tests/bad_scenes/raw/), and
// carries the exit code and the message fragment the program must answer it with.
#pragma once

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "cli_helpers.h"

namespace cdmpm::testing {

struct BadScene {
  std::string name;     // the row's name; its scene is written as NAME.json, which the message must name
  std::string path;     // where it was written
  std::string message;  // a fragment of the message that refuses it
  int exit_code = 2;
};

inline const fs::path& bad_scenes_dir() {
  static const fs::path dir = fs::path(CDMPM_SOURCE_DIR) / "tests" / "bad_scenes";
  return dir;
}

// The node at the dotted `path` of `doc` ("bodies.0.shape": a number indexes an array, which must hold it); with
// `create`, a missing object key on the way is created as an empty object.
inline nlohmann::json& bad_scene_node(nlohmann::json& doc, const std::vector<std::string>& path, bool create,
                                      const std::string& row) {
  nlohmann::json* node = &doc;
  for (const std::string& c : path) {
    if (node->is_array()) {
      const size_t i = std::stoul(c);
      if (i >= node->size()) throw std::runtime_error(row + ": index " + c + " past the end of its array");
      node = &(*node)[i];
    } else if (node->is_object() && (create || node->contains(c))) {
      if (!node->contains(c)) (*node)[c] = nlohmann::json::object();
      node = &(*node)[c];
    } else {
      throw std::runtime_error(row + ": no key \"" + c + "\" to follow");
    }
  }
  return *node;
}

inline std::vector<std::string> bad_scene_path(const std::string& dotted) {
  std::vector<std::string> out;
  std::stringstream ss(dotted);
  for (std::string c; std::getline(ss, c, '.');) out.push_back(c);
  return out;
}

// Applies a row's `delete` ("key.path") and then its `set` ("key.path=JSON value"; an array index one past the end
// appends) to `doc`.
inline void patch_bad_scene(nlohmann::json& doc, const nlohmann::json& row) {
  const std::string name = row.at("name").get<std::string>();
  for (const nlohmann::json& d : row.value("delete", nlohmann::json::array())) {
    const std::string del = d.get<std::string>();
    std::vector<std::string> path = bad_scene_path(del);
    const std::string last = path.back();
    path.pop_back();
    nlohmann::json& parent = bad_scene_node(doc, path, false, name);
    if (parent.is_array()) {
      parent.erase(std::stoul(last));
    } else if (parent.erase(last) != 1) {
      throw std::runtime_error(name + ": nothing to delete at " + del);
    }
  }
  for (const nlohmann::json& a : row.value("set", nlohmann::json::array())) {
    const std::string set = a.get<std::string>();
    const size_t eq = set.find('=');
    if (eq == std::string::npos) throw std::runtime_error(name + ": \"" + set + "\" is not key.path=value");
    std::vector<std::string> path = bad_scene_path(set.substr(0, eq));
    const std::string last = path.back();
    path.pop_back();
    nlohmann::json& parent = bad_scene_node(doc, path, true, name);
    const nlohmann::json value = nlohmann::json::parse(set.substr(eq + 1));
    if (parent.is_array() && std::stoul(last) == parent.size()) {
      parent.push_back(value);
    } else if (parent.is_array()) {
      bad_scene_node(parent, {last}, false, name) = value;
    } else {
      parent[last] = value;
    }
  }
}

inline std::string read_text(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw std::runtime_error("cannot read " + path.string());
  std::stringstream ss;
  ss << in.rdbuf();
  return ss.str();
}

// Writes every row of the table (or only the row named `only`) into `dir` as NAME.json and returns them. A row
// that cannot be built, or a name used twice, is a test failure naming the row.
inline std::vector<BadScene> write_bad_scenes(const fs::path& dir, const std::string& only = "") {
  const nlohmann::json table = nlohmann::json::parse(read_text(bad_scenes_dir() / "patches.json"));
  std::vector<BadScene> out;
  std::set<std::string> names;
  for (const nlohmann::json& row : table.at("scenes")) {
    BadScene s;
    s.name = row.at("name").get<std::string>();
    if (!only.empty() && s.name != only) continue;
    EXPECT_TRUE(names.insert(s.name).second) << s.name << ": a second row of that name";
    s.message = row.at("message").get<std::string>();
    s.exit_code = table.at("exit_code").get<int>();
    s.path = (dir / (s.name + ".json")).string();
    try {
      std::string text;
      if (row.contains("file")) {
        text = read_text(bad_scenes_dir() / row.at("file").get<std::string>());
      } else {
        nlohmann::json doc = nlohmann::json::parse(read_text(bad_scenes_dir() / row.at("base").get<std::string>()));
        patch_bad_scene(doc, row);
        text = doc.dump(2) + "\n";
      }
      std::ofstream(s.path, std::ios::binary) << text;
    } catch (const std::exception& e) {
      ADD_FAILURE() << s.name << ": the row cannot be built: " << e.what();
      continue;
    }
    out.push_back(s);
  }
  EXPECT_TRUE(only.empty() || out.size() == 1) << "no row named " << only;
  return out;
}

// The base scenes the rows patch (each a valid scene, so that a row is refused for its change alone).
inline std::vector<std::string> bad_scene_bases() {
  std::vector<std::string> out;
  for (const auto& e : fs::directory_iterator(bad_scenes_dir() / "base")) out.push_back(e.path().string());
  return out;
}

// The files of tests/bad_scenes/base and raw that no row uses.
inline std::vector<std::string> unused_bad_scene_files() {
  const nlohmann::json table = nlohmann::json::parse(read_text(bad_scenes_dir() / "patches.json"));
  std::set<std::string> used;
  for (const nlohmann::json& row : table.at("scenes")) used.insert(row.value("file", row.value("base", "")));
  std::vector<std::string> out;
  for (const char* sub : {"base", "raw"}) {
    for (const auto& e : fs::directory_iterator(bad_scenes_dir() / sub)) {
      const std::string rel = std::string(sub) + "/" + e.path().filename().string();
      if (!used.count(rel)) out.push_back(rel);
    }
  }
  return out;
}

}  // namespace cdmpm::testing
