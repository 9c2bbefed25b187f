// SPDX-License-Identifier: MIT
#include "export/skeleton.h"

#include <set>

namespace rise {

int Skeleton::Find(const std::string& name) const {
  for (int i = 0; i < JointCount(); ++i) {
    if (joints[i].name == name) return i;
  }
  return -1;
}

std::vector<glm::vec3> Skeleton::BindPositions() const {
  std::vector<glm::vec3> positions(joints.size());
  for (int i = 0; i < JointCount(); ++i) {
    const SkeletonJoint& joint = joints[i];
    positions[i] = joint.parent < 0 ? joint.restOffset : positions[joint.parent] + joint.restOffset;
  }
  return positions;
}

std::string Skeleton::Validate() const {
  if (joints.empty()) return "skeleton has no joints";
  if (joints[0].parent != -1) return "joint 0 must be the root (parent -1)";
  std::set<std::string> names;
  for (int i = 0; i < JointCount(); ++i) {
    const SkeletonJoint& joint = joints[i];
    if (joint.name.empty()) return "joint " + std::to_string(i) + " has no name";
    if (!names.insert(joint.name).second) return "joint name '" + joint.name + "' is used twice";
    if (i > 0 && (joint.parent < 0 || joint.parent >= i)) {
      return "joint '" + joint.name + "' must have a parent listed before it";
    }
  }
  return {};
}

}  // namespace rise
