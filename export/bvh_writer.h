// SPDX-License-Identifier: MIT
// BVH output that MotionBuilder and Blender read as-is.
//
// - HIERARCHY: one ROOT (the clip's root joint) with OFFSET = its bind-pose
//   position; every other joint's OFFSET is its rest offset. A leaf joint
//   without a box that is its parent's only child (head_end, hand_*_end,
//   foot_*_end) becomes that parent's `End Site`, so bones get their length.
// - Channels: the root (and any joint with a translation track) has
//   `Xposition Yposition Zposition Zrotation Xrotation Yrotation`, every other
//   joint `Zrotation Xrotation Yrotation` (the common mocap order: R = Rz Rx Ry).
//   Position channels hold the joint's absolute local position (for the root:
//   its world position), which is how Blender and MotionBuilder read them.
// - MOTION: `Frames:` = frame count, `Frame Time:` = 1 / fps. Euler angles are
//   in degrees, unwrapped from frame to frame so curves never jump by 360.
// - Units and up axis per BvhFormat (metres / Y-up by default).
#pragma once

#include <string>

#include "export/bvh_format.h"
#include "export/clip.h"
#include "export/joint_names.h"

namespace rise {

struct BvhOptions {
  BvhFormat format;
  NamingPreset naming = NamingPreset::kDefault;
  // Also write the metadata sidecar `<clip>.meta.json` (clip_metadata_json.h).
  bool writeSidecar = true;
};

// The BVH text of `clip` (valid).
std::string FormatBvh(const Clip& clip, const BvhOptions& options = {});

// Writes FormatBvh(clip) to `path` atomically (atomic_file.h). Returns an empty
// string on success, otherwise a message; on failure no partial file is left.
std::string WriteBvh(const Clip& clip, const std::string& path, const BvhOptions& options = {});

}  // namespace rise
