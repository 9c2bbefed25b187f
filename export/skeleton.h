// SPDX-License-Identifier: MIT
// The joint hierarchy shared by the biped builder (core/) and the writers (export/).
//
// Conventions (world: +Y up, metres, right-handed, facing +Z in the bind pose):
// - The bind pose is the standing pose. Every joint's frame is aligned with the
//   world axes in the bind pose, so each rest rotation is the identity and a
//   joint's local rotation in a clip is parent_world^-1 * child_world.
// - restOffset is the joint's position relative to its parent joint in the bind
//   pose (for the root: its world position in the bind pose).
// - A joint with hasBox carries one box of the body, given in the joint frame.
//   End joints (head top, finger tips, toes) carry no box; they give importers
//   the bone's true length.
#pragma once

#include <glm/vec3.hpp>

#include <string>
#include <vector>

namespace rise {

struct BoneBox {
  glm::vec3 center{0.0f};       // box centre in the joint frame, metres
  glm::vec3 halfExtents{0.0f};  // half sizes along the joint frame axes, metres

  // Corner 0-7: bit 0, 1, 2 of the index pick +x, +y, +z. CornerSign is the
  // corner's direction from the centre (each component +-1); Corner, the
  // corner in the joint frame.
  static glm::vec3 CornerSign(int corner) {
    return {(corner & 1) ? 1.0f : -1.0f, (corner & 2) ? 1.0f : -1.0f, (corner & 4) ? 1.0f : -1.0f};
  }
  glm::vec3 Corner(int corner) const { return center + CornerSign(corner) * halfExtents; }
};

struct SkeletonJoint {
  std::string name;
  int parent = -1;  // index into Skeleton::joints; -1 only for the root
  glm::vec3 restOffset{0.0f};
  bool hasBox = false;
  BoneBox box;
};

// Parents always come before their children (index order is a valid
// root-to-leaf traversal); there is exactly one root, at index 0.
struct Skeleton {
  std::vector<SkeletonJoint> joints;

  int JointCount() const { return static_cast<int>(joints.size()); }
  // Index of the joint named `name`, or -1.
  int Find(const std::string& name) const;
  // Bind-pose world position of every joint.
  std::vector<glm::vec3> BindPositions() const;
  // Empty when the hierarchy is well formed, otherwise what is wrong.
  std::string Validate() const;
};

}  // namespace rise
