// SPDX-License-Identifier: MIT
// The clip's metadata as JSON: the sidecar `<clip>.meta.json` next to every written
// clip and the `extras` of its glTF animation hold the same document.
//
// Document (all times in seconds from the first frame):
//   { "generator": "rise-gen 0.1.0", "fps": 30, "frameCount": 91, "duration": 3,
//     "rootMotion": "bake", "removedTravel": [x, y, z], "removedHeading": rad,
//     "seed": 7, "timeToStand": 2.4,
//     "phases":   [ { "name": "roll", "start": 0, "end": 0.8 }, ... ],
//     "contacts": [ { "effector": "foot_l", "start": 1.2, "end": 3, "footLock": true }, ... ],
//     "peakTorques": [ { "joint": "thigh_l", "torque": 180.5 }, ... ],
//     "parameters": { ...the resolved input... } }
#pragma once

#include <string>

#include "export/clip.h"

namespace rise {

// The document for `clip` (compact JSON text).
std::string MetadataToJson(const Clip& clip);

// Fills `metadata` from a document made by MetadataToJson (unknown keys are
// ignored, missing ones keep their defaults). Returns an error message or "".
std::string MetadataFromJson(const std::string& text, ClipMetadata& metadata);

// "out/rise.glb" -> "out/rise.json".
std::string SidecarPath(const std::string& clipPath);

// Writes MetadataToJson(clip) to SidecarPath(clipPath), atomically.
// Returns an error message or "".
std::string WriteMetadataSidecar(const Clip& clip, const std::string& clipPath);

}  // namespace rise
