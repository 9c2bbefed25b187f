// SPDX-License-Identifier: MIT
// Whole-body pose from the plan's few numbers: the trunk (pelvis, chest, head)
// orientations and pelvis position, plus a target for each wrist and ankle.
// Knees and elbows come from the analytic two-bone IK; the abdomen takes half
// the pelvis-to-chest rotation. The result is the pose the PD servos track.
#pragma once

#include "core/two_bone_ik.h"
#include "export/skeleton.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <vector>

namespace rise {

enum class Limb { kHandLeft = 0, kHandRight, kFootLeft, kFootRight };
constexpr int kLimbCount = 4;
const char* LimbName(Limb limb);  // "hand_l", "hand_r", "foot_l", "foot_r"

struct LimbGoal {
  glm::vec3 target{0.0f};                           // wrist or ankle joint position, world
  glm::quat endRotation{1.0f, 0.0f, 0.0f, 0.0f};    // hand or foot world rotation
  glm::vec3 pole{0.0f, 0.0f, 1.0f};                 // elbow/knee direction hint, world
  float swivel = 0.0f;                              // radians about shoulder/hip -> target
};

struct PoseGoal {
  glm::vec3 pelvisPosition{0.0f};  // the pelvis (root) joint, world
  glm::quat pelvisRotation{1.0f, 0.0f, 0.0f, 0.0f};
  glm::quat chestRotation{1.0f, 0.0f, 0.0f, 0.0f};
  glm::quat headRotation{1.0f, 0.0f, 0.0f, 0.0f};
  std::array<LimbGoal, kLimbCount> limbs;
};

// The joints of the character skeleton the IK works on, found once by name.
struct BodyRig {
  int pelvis = -1, abdomen = -1, chest = -1, head = -1;
  std::array<int, kLimbCount> upper{};  // upper_arm / thigh
  std::array<int, kLimbCount> lower{};  // forearm / shin
  std::array<int, kLimbCount> end{};    // hand / foot
  std::array<float, kLimbCount> maxFlexion{};  // elbow / knee limit, radians

  // Finds the joints by their canonical names; asserts that they exist.
  static BodyRig FromSkeleton(const Skeleton& skeleton, float maxElbowFlexion, float maxKneeFlexion);
};

struct BodyPose {
  std::vector<glm::quat> worldRotations;  // per skeleton joint
  std::vector<glm::vec3> worldPositions;  // per skeleton joint
  std::array<bool, kLimbCount> reached{};  // each limb target met without clamping
};

// Solves the pose; a pure function of its inputs.
BodyPose SolveBodyPose(const Skeleton& skeleton, const BodyRig& rig, const PoseGoal& goal);

// World position of the shoulder or hip joint of `limb` for the given trunk.
glm::vec3 LimbRoot(const Skeleton& skeleton, const BodyRig& rig, const PoseGoal& goal, Limb limb);

// Local (parent-relative) rotations of a pose: what each joint servo tracks.
std::vector<glm::quat> LocalRotations(const Skeleton& skeleton, const std::vector<glm::quat>& world);

}  // namespace rise
