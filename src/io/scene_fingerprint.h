// scene_fingerprint.h - what a resumed run must share with the run that wrote the checkpoint.
//
// The fingerprint is a list of (section, 64-bit FNV-1a hash of its JSON text) over the scene as resolved
// (--set overrides applied, parameter expressions evaluated), one entry per second-level key ("materials.water",
// "bodies[0]", "time") or per top-level value ("dim", "name"). The keys a resume may change are left out:
// time.end, time.frame_interval and probes.interval. It is stored in the checkpoint and compared on --resume,
// so a resume with another scene or another --set of the physics is refused, naming the sections that differ.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "scene/scene.h"

namespace cdmpm {

using SceneFingerprint = std::vector<std::pair<std::string, uint64_t>>;

SceneFingerprint scene_fingerprint(const Scene& scene);

// "" when equal; otherwise e.g. "materials.water differs; bodies[1] only in the checkpoint's scene".
std::string fingerprint_difference(const SceneFingerprint& checkpoint, const SceneFingerprint& scene);

// 64-bit FNV-1a hash of `text`.
uint64_t fnv1a64(const std::string& text);

}  // namespace cdmpm
