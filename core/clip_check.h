// SPDX-License-Identifier: MIT
// `rise-gen check`: the quality bars of clip_quality.h measured on clip files (ours or another
// tool's), plus the agreement of a BVH file with its glTF twin.
#pragma once

#include <nlohmann/json.hpp>
#include <string>

#include "core/clip_quality.h"
#include "export/bvh_format.h"
#include "export/clip.h"

namespace rise {

// A BVH and the glTF of the same clip may differ by at most this much at any joint on any
// frame (metres): both are written from one clip, so only rounding and Euler conversion differ.
inline constexpr double kMaxBvhDistance = 0.01;

struct ClipCheck {
  std::string error;  // non-empty when a file cannot be read or measured; nothing else is then set
  Clip clip;          // as read from the glTF file
  QualityReport quality;

  bool hasBvh = false;
  double bvhDistance = 0.0;  // metres, largest over frames and the joints both files name
  int bvhJoints = 0;         // joints compared
  std::string bvhProblem;    // why the files could not be compared (frame counts, no shared joints)
  bool bvhOk = true;

  bool passed = false;  // every quality bar and (with a BVH) the distance bar hold

  nlohmann::json ToJson() const;
  std::string Summary() const;
};

// The bars for a clip: the ground of its resolved input (terrain.slope_deg in the metadata of a
// rise-gen clip); the level ground y = 0 for anyone else's clip.
QualityOptions QualityOptionsFor(const Clip& clip);

// The bars a report misses, by name, e.g. "ends standing, contact slip"; "" when it passes.
std::string MissedBars(const QualityReport& quality);

// Reads the glTF (.glb/.gltf) at gltfPath and, when bvhPath is not empty, the BVH at bvhPath
// (assuming bvhFormat), and measures them.
ClipCheck CheckClipFiles(const std::string& gltfPath, const std::string& bvhPath = "", const BvhFormat& bvhFormat = {});

}  // namespace rise
