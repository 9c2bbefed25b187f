// SPDX-License-Identifier: MIT
// Whole-body pose from the plan's few numbers: the trunk (pelvis, chest, head)
// orientations and pelvis position, plus a target for each wrist and ankle.
// The abdomen takes half the pelvis-to-chest rotation.
//
// Limbs are solved analytically in the body's own joint coordinates, so the
// pose is one the servos can reach: hips and shoulders are 2-DOF (flexion,
// abduction; no twist), knees and elbows 1-DOF hinges, ankles and wrists 2-DOF.
// The hinge angle follows from the root-to-target distance (law of cosines,
// clamped to the hinge's range); the two root angles then turn the limb onto
// the target (each a closed-form solution of a rotation about a known axis).
// With no twist DOF the bend plane is not free: it follows from the root's
// two angles, so there is no pole or swivel parameter here. The end
// (hand or foot) matches one key direction of the wanted end rotation -- the
// palm's normal, the sole's normal -- which its 2 DOF can always do.
#pragma once

#include "core/biped_def.h"
#include "export/skeleton.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <optional>
#include <vector>

namespace rise {

enum class Limb { kHandLeft = 0, kHandRight, kFootLeft, kFootRight };
constexpr int kLimbCount = 4;
const char* LimbName(Limb limb);  // "hand_l", "hand_r", "foot_l", "foot_r"
inline bool IsArm(Limb limb) { return limb == Limb::kHandLeft || limb == Limb::kHandRight; }
inline bool IsLeft(Limb limb) { return limb == Limb::kHandLeft || limb == Limb::kFootLeft; }
inline Limb OtherHand(Limb hand) { return hand == Limb::kHandLeft ? Limb::kHandRight : Limb::kHandLeft; }

struct LimbGoal {
  glm::vec3 target{0.0f};                           // wrist or ankle joint position, world
  glm::quat endRotation{1.0f, 0.0f, 0.0f, 0.0f};    // hand or foot world rotation (its key direction counts)
  // When set, the limb takes these angles (root axis 0, root axis 1, hinge; radians) as they are
  // and `target` is only where they put the wrist or ankle: at 90 deg of shoulder abduction the
  // target no longer tells how the arm is turned about itself.
  std::optional<glm::vec3> angles;
  // When set (a swing in the joints lifted toward `target`, which the IK solves for): the angles
  // the swing is at. A solution whose root turns the limb more than kMaxSwingTwist about its first
  // axis from them (at 90 deg of shoulder abduction, where the target leaves that turn open and
  // the solution flips) is dropped for these angles as they are.
  std::optional<glm::vec3> swingAngles;
};

// See LimbGoal::swingAngles.
inline constexpr float kMaxSwingTwist = glm::radians(90.0f);

struct PoseGoal {
  glm::vec3 pelvisPosition{0.0f};  // the pelvis (root) joint, world
  glm::quat pelvisRotation{1.0f, 0.0f, 0.0f, 0.0f};
  glm::quat chestRotation{1.0f, 0.0f, 0.0f, 0.0f};
  glm::quat headRotation{1.0f, 0.0f, 0.0f, 0.0f};
  std::array<LimbGoal, kLimbCount> limbs;
};

// The joints of the character skeleton the IK works on, found once by name,
// with the DOF axes (in the parent joint frame) and ranges of each limb joint.
struct BodyRig {
  struct Axis {
    glm::vec3 axis{1.0f, 0.0f, 0.0f};
    float lower = 0.0f, upper = 0.0f;  // radians
  };
  int pelvis = -1, abdomen = -1, chest = -1, head = -1;
  std::array<int, kLimbCount> upper{};  // upper_arm / thigh (2 DOF)
  std::array<int, kLimbCount> lower{};  // forearm / shin (hinge)
  std::array<int, kLimbCount> end{};    // hand / foot (2 DOF)
  std::array<std::array<Axis, 2>, kLimbCount> rootDofs{};
  std::array<Axis, kLimbCount> hinge{};
  std::array<std::array<Axis, 2>, kLimbCount> endDofs{};
  std::array<glm::vec3, kLimbCount> endKey{};  // hand: palm normal; foot: sole normal (up), end frame

  // Finds the joints by their canonical names; asserts that they exist and
  // that limbs are 2-DOF / hinge / 2-DOF as biped_def.h describes.
  static BodyRig FromDef(const BipedDef& def);
};

struct BodyPose {
  std::vector<glm::quat> worldRotations;  // per skeleton joint
  std::vector<glm::vec3> worldPositions;  // per skeleton joint
  std::array<bool, kLimbCount> reached{};     // each limb target met without clamping
  std::array<bool, kLimbCount> endMatched{};  // each end's key direction met (within 2 deg)
};

// Solves the pose; a pure function of its inputs.
BodyPose SolveBodyPose(const Skeleton& skeleton, const BodyRig& rig, const PoseGoal& goal);

// How SolveTwoAxes keeps a turn beyond its joints' ranges within them.
enum class RangeClamp {
  kBySign,   // each angle to the limit on its side in (-pi, pi]: across the half turn it jumps to the other
  kClosest,  // both together: the in-range pair that turns v closest to t (on the edge of the ranges)
};

// The angles (a, b) with R(axis0, a) R(axis1, b) v closest to t (unit vectors;
// axis0 perpendicular to axis1), kept in their ranges as `clamp` says.
glm::vec2 SolveTwoAxes(const BodyRig::Axis& axis0, const BodyRig::Axis& axis1, const glm::vec3& v, const glm::vec3& t,
                       RangeClamp clamp = RangeClamp::kBySign);

// World position of the shoulder or hip joint of `limb` for the given trunk.
glm::vec3 LimbRoot(const Skeleton& skeleton, const BodyRig& rig, const PoseGoal& goal, Limb limb);

// Local (parent-relative) rotations of a pose: what each joint servo tracks.
std::vector<glm::quat> LocalRotations(const Skeleton& skeleton, const std::vector<glm::quat>& world);

}  // namespace rise
