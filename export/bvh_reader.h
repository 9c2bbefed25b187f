// SPDX-License-Identifier: MIT
// A small BVH reader: joint hierarchy and per-frame world joint positions, in
// rise-gen's world (metres, Y-up). Used by the tests and `rise-gen check`.
//
// It reads any BVH with ROOT/JOINT/End Site blocks and position/rotation
// channels in any order (rotations compose in channel order: R = R1 R2 R3).
// Position channels replace the joint's OFFSET (Blender's and MotionBuilder's
// reading). End Sites become joints named "<parent>_end". Units and up axis
// are not stored in BVH files, so the caller says which to assume.
#pragma once

#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "export/bvh_format.h"

namespace rise {

struct BvhMotion {
  std::vector<std::string> names;  // joints in file order, End Sites included
  std::vector<int> parents;        // -1 for the root
  double frameTime = 0.0;          // seconds
  // positions[frame][joint]: world position, metres, Y-up.
  std::vector<std::vector<glm::vec3>> positions;

  int FrameCount() const { return static_cast<int>(positions.size()); }
  // Index of the joint named `name`, or -1.
  int Find(const std::string& name) const;
};

// Reads `path` assuming `format`. Returns an empty string on success,
// otherwise a message naming the file and what is wrong.
std::string ReadBvh(const std::string& path, const BvhFormat& format, BvhMotion& motion);

// The same from BVH text in memory; `source` names it in messages.
std::string ParseBvh(const std::string& text, const BvhFormat& format, const std::string& source, BvhMotion& motion);

}  // namespace rise
