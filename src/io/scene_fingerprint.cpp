// scene_fingerprint.cpp - the scene fingerprint of scene_fingerprint.h.
#include "io/scene_fingerprint.h"

#include <map>

#include "scene/parameters.h"

namespace cdmpm {
namespace {

using json = nlohmann::json;

// The scene json as the loader saw it, without the keys a resumed run may change.
json comparable_scene(const Scene& scene) {
  json j = scene.json;
  substitute_parameters(j, scene.path);
  auto erase = [&](const char* section, const char* key) {
    if (j.is_object() && j.contains(section) && j[section].is_object()) j[section].erase(key);
  };
  erase("time", "end");
  erase("time", "frame_interval");
  erase("probes", "interval");
  return j;
}

}  // namespace

uint64_t fnv1a64(const std::string& text) {
  uint64_t h = 0xcbf29ce484222325ull;
  for (const unsigned char c : text) h = (h ^ c) * 0x100000001b3ull;
  return h;
}

SceneFingerprint scene_fingerprint(const Scene& scene) {
  const json j = comparable_scene(scene);
  SceneFingerprint fp;
  if (!j.is_object()) return {{"(root)", fnv1a64(j.dump())}};
  for (const auto& [key, value] : j.items()) {
    if (value.is_object() && !value.empty()) {
      for (const auto& [child, v] : value.items()) fp.emplace_back(key + "." + child, fnv1a64(v.dump()));
    } else if (value.is_array() && !value.empty() && value.at(0).is_structured()) {
      for (size_t i = 0; i < value.size(); ++i)
        fp.emplace_back(key + "[" + std::to_string(i) + "]", fnv1a64(value[i].dump()));
    } else {
      fp.emplace_back(key, fnv1a64(value.dump()));
    }
  }
  return fp;
}

std::string fingerprint_difference(const SceneFingerprint& checkpoint, const SceneFingerprint& scene) {
  const std::map<std::string, uint64_t> a(checkpoint.begin(), checkpoint.end()), b(scene.begin(), scene.end());
  std::string out;
  auto add = [&](const std::string& what) { out += (out.empty() ? "" : "; ") + what; };
  for (const auto& [name, h] : a) {
    const auto it = b.find(name);
    if (it == b.end()) add(name + " only in the checkpoint's scene");
    else if (it->second != h) add(name + " differs");
  }
  for (const auto& [name, h] : b)
    if (!a.count(name)) add(name + " only in this scene");
  return out;
}

}  // namespace cdmpm
