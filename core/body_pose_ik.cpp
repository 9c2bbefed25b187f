// SPDX-License-Identifier: MIT
#include "core/body_pose_ik.h"

#include "base/assert.h"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>

#include <algorithm>
#include <cmath>
#include <utility>

namespace rise {
namespace {

// An end counts as matching its goal when its key direction is within 2 deg.
const float kEndKeyCos = std::cos(glm::radians(2.0f));

int RequireJoint(const Skeleton& skeleton, const char* name) {
  const int index = skeleton.Find(name);
  RISE_ASSERT_MSG(index >= 0, name);
  return index;
}

// World rotation of the abdomen: halfway between pelvis and chest, so the
// spine bends evenly over its two joints.
glm::quat Abdomen(const PoseGoal& goal) { return glm::slerp(goal.pelvisRotation, goal.chestRotation, 0.5f); }

float ClampToRange(float angle, const BodyRig::Axis& axis, RangeClamp clamp) {
  if (clamp == RangeClamp::kBySign || (angle >= axis.lower && angle <= axis.upper)) {
    return std::clamp(angle, axis.lower, axis.upper);
  }
  const float turn = 2.0f * glm::pi<float>();
  const float toLower = std::fabs(std::remainder(angle - axis.lower, turn));
  const float toUpper = std::fabs(std::remainder(angle - axis.upper, turn));
  return toLower <= toUpper ? axis.lower : axis.upper;
}

}  // namespace

const char* LimbName(Limb limb) {
  static const char* const kNames[kLimbCount] = {"hand_l", "hand_r", "foot_l", "foot_r"};
  return kNames[static_cast<int>(limb)];
}

BodyRig BodyRig::FromDef(const BipedDef& def) {
  const Skeleton& skeleton = def.skeleton;
  BodyRig rig;
  rig.pelvis = RequireJoint(skeleton, "pelvis");
  rig.abdomen = RequireJoint(skeleton, "abdomen");
  rig.chest = RequireJoint(skeleton, "chest");
  rig.head = RequireJoint(skeleton, "head");
  static const char* const kUpper[kLimbCount] = {"upper_arm_l", "upper_arm_r", "thigh_l", "thigh_r"};
  static const char* const kLower[kLimbCount] = {"forearm_l", "forearm_r", "shin_l", "shin_r"};
  static const char* const kEnd[kLimbCount] = {"hand_l", "hand_r", "foot_l", "foot_r"};
  auto axis = [](const JointDof& dof) { return Axis{dof.axis, glm::radians(dof.minDeg), glm::radians(dof.maxDeg)}; };
  for (int i = 0; i < kLimbCount; ++i) {
    rig.upper[i] = RequireJoint(skeleton, kUpper[i]);
    rig.lower[i] = RequireJoint(skeleton, kLower[i]);
    rig.end[i] = RequireJoint(skeleton, kEnd[i]);
    const BoneDef& upper = def.bones[rig.upper[i]];
    const BoneDef& lower = def.bones[rig.lower[i]];
    const BoneDef& end = def.bones[rig.end[i]];
    RISE_ASSERT(upper.dofs.size() == 2 && lower.dofs.size() == 1 && end.dofs.size() == 2);
    rig.rootDofs[i] = {axis(upper.dofs[0]), axis(upper.dofs[1])};
    rig.hinge[i] = axis(lower.dofs[0]);
    rig.endDofs[i] = {axis(end.dofs[0]), axis(end.dofs[1])};
    // The palm faces the thigh in the bind pose (-X on the left, +X on the right).
    const bool left = i == 0;
    rig.endKey[i] = IsArm(static_cast<Limb>(i)) ? glm::vec3(left ? -1.0f : 1.0f, 0.0f, 0.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
  }
  return rig;
}

glm::vec2 SolveTwoAxes(const BodyRig::Axis& axis0, const BodyRig::Axis& axis1, const glm::vec3& v, const glm::vec3& t,
                       RangeClamp clamp) {
  const glm::vec3 a0 = axis0.axis, a1 = axis1.axis;
  // Turning v about a1 by b must give it t's component along a0 (a rotation
  // about a0 keeps that component): A cos b + B sin b = C.
  const float A = glm::dot(v, a0) - glm::dot(v, a1) * glm::dot(a1, a0);
  const float B = glm::dot(glm::cross(a1, v), a0);
  const float C = glm::dot(t, a0);
  const float radius = std::sqrt(A * A + B * B);
  float b = 0.0f;
  if (radius > 1e-6f) {
    const float phase = std::atan2(B, A);
    const float spread = std::acos(std::clamp(C / radius, -1.0f, 1.0f));
    // Of the two solutions (each already in [-pi, pi]), the one nearer the
    // joint's range (then the smaller turn).
    const auto cost = [&](float angle) {
      const float outside = std::max(0.0f, axis1.lower - angle) + std::max(0.0f, angle - axis1.upper);
      return std::make_pair(outside, std::fabs(angle));
    };
    const float first = std::remainder(phase + spread, 2.0f * glm::pi<float>());
    const float second = std::remainder(phase - spread, 2.0f * glm::pi<float>());
    b = cost(first) <= cost(second) ? first : second;
  }
  b = ClampToRange(b, axis1, clamp);
  // Then the turn about a0 that carries the result onto t.
  const glm::vec3 p = glm::angleAxis(b, a1) * v;
  const glm::vec3 pp = p - a0 * glm::dot(p, a0), tp = t - a0 * glm::dot(t, a0);
  float a = 0.0f;
  if (glm::length(pp) > 1e-6f && glm::length(tp) > 1e-6f) a = std::atan2(glm::dot(a0, glm::cross(pp, tp)), glm::dot(pp, tp));
  return {ClampToRange(a, axis0, clamp), b};
}

namespace {

// The chest joint (where the shoulders hang) of the goal's trunk, with the abdomen's rotation.
glm::vec3 ChestJoint(const Skeleton& skeleton, const BodyRig& rig, const PoseGoal& goal, const glm::quat& abdomen) {
  return goal.pelvisPosition + goal.pelvisRotation * skeleton.joints[rig.abdomen].restOffset +
         abdomen * skeleton.joints[rig.chest].restOffset;
}

// The shoulder or hip joint of `limb`, with the chest joint (unused for a leg).
glm::vec3 RootJoint(const Skeleton& skeleton, const BodyRig& rig, const PoseGoal& goal, Limb limb, const glm::vec3& chest) {
  const glm::vec3 offset = skeleton.joints[rig.upper[static_cast<int>(limb)]].restOffset;
  return IsArm(limb) ? chest + goal.chestRotation * offset : goal.pelvisPosition + goal.pelvisRotation * offset;
}

}  // namespace

glm::vec3 LimbRoot(const Skeleton& skeleton, const BodyRig& rig, const PoseGoal& goal, Limb limb) {
  return RootJoint(skeleton, rig, goal, limb, IsArm(limb) ? ChestJoint(skeleton, rig, goal, Abdomen(goal)) : glm::vec3(0.0f));
}

BodyPose SolveBodyPose(const Skeleton& skeleton, const BodyRig& rig, const PoseGoal& goal) {
  BodyPose pose;
  const glm::quat abdomen = Abdomen(goal);
  pose.worldRotations.assign(skeleton.joints.size(), goal.chestRotation);
  pose.worldRotations[rig.pelvis] = goal.pelvisRotation;
  pose.worldRotations[rig.abdomen] = abdomen;
  pose.worldRotations[rig.chest] = goal.chestRotation;
  pose.worldRotations[rig.head] = goal.headRotation;
  const glm::vec3 chest = ChestJoint(skeleton, rig, goal, abdomen);

  for (int i = 0; i < kLimbCount; ++i) {
    const Limb limb = static_cast<Limb>(i);
    const LimbGoal& limbGoal = goal.limbs[i];
    const glm::quat parent = IsArm(limb) ? goal.chestRotation : goal.pelvisRotation;
    const glm::vec3 upperBone = skeleton.joints[rig.lower[i]].restOffset;
    const glm::vec3 lowerBone = skeleton.joints[rig.end[i]].restOffset;
    const float l1 = glm::length(upperBone), l2 = glm::length(lowerBone);
    const glm::vec3 reach = glm::inverse(parent) * (limbGoal.target - RootJoint(skeleton, rig, goal, limb, chest));
    const float distance = glm::length(reach);

    // Hinge from the distance; both bones point along -Y at rest, so the
    // distance only depends on the hinge angle (law of cosines).
    const BodyRig::Axis& hinge = rig.hinge[i];
    const float cosHinge = (distance * distance - l1 * l1 - l2 * l2) / (2.0f * l1 * l2);
    const float bend = limbGoal.angles ? limbGoal.angles->z
                                       : std::clamp(std::acos(std::clamp(cosHinge, -1.0f, 1.0f)), hinge.lower, hinge.upper);
    const glm::quat hingeRotation = glm::angleAxis(bend, hinge.axis);
    const glm::vec3 limbVector = upperBone + hingeRotation * lowerBone;
    const glm::vec3 toward = distance > 1e-6f ? reach / distance : glm::normalize(limbVector);
    const glm::vec2 rootAngles = limbGoal.angles ? glm::vec2(limbGoal.angles->x, limbGoal.angles->y)
                                                 : SolveTwoAxes(rig.rootDofs[i][0], rig.rootDofs[i][1],
                                                                glm::normalize(limbVector), toward);
    // The arm turn leaves an arm out at 90 deg of abduction, where its flexion
    // only turns it about itself; the place's lifted swing from there had the
    // IK flip that flexion from -55 to 113 deg at its first step, and the hand
    // turning with it swept a corner 9.8 cm along the ground (samples/tall.json).
    const bool flipped = limbGoal.swingAngles && std::fabs(rootAngles.x - limbGoal.swingAngles->x) > kMaxSwingTwist;
    const glm::vec3 angles = flipped ? *limbGoal.swingAngles : glm::vec3(rootAngles, bend);
    const glm::quat hingeTurn = flipped ? glm::angleAxis(angles.z, hinge.axis) : hingeRotation;
    const glm::quat rootRotation =
        glm::angleAxis(angles.x, rig.rootDofs[i][0].axis) * glm::angleAxis(angles.y, rig.rootDofs[i][1].axis);
    pose.worldRotations[rig.upper[i]] = glm::normalize(parent * rootRotation);
    pose.worldRotations[rig.lower[i]] = glm::normalize(pose.worldRotations[rig.upper[i]] * hingeTurn);

    // The end: its key direction as the goal rotation has it, in the lower bone's frame.
    // A sole the ankle cannot turn flat is turned as near it as its range
    // allows. A far foot planted for the roll's push off, its shin led round by
    // the trunk's goal, is asked for a pitch that sweeps through the half turn
    // and on to 155 deg (range -50..30): clamped by sign, the commanded pitch
    // jumped from -50 to 30 deg as it crossed 180 and kicked the foot off the
    // ground; it came down 4-5 cm away and slid. Clamped to the nearer limit it
    // holds -50 until 170 deg, where both limits are as far: the jump still
    // comes, later (20 ms in bench/prone_variants supine k=0, whose foot then
    // slides 5.3 cm instead of 5.8). 48 supine starts: 33 -> 35 pass every bar;
    // stress seeds 5001-6000 and 9001-9500 stood 1042 -> 1055. A wrist clamped
    // that way keeps the palm toward the ground: turned the nearer way, the
    // place's hands pressed their fingers down and slid 15-17 cm in all 24
    // side_left starts.
    const glm::quat lowerWorld = pose.worldRotations[rig.lower[i]];
    const glm::vec3 wanted = glm::normalize(glm::inverse(lowerWorld) * (limbGoal.endRotation * rig.endKey[i]));
    const glm::vec2 end = SolveTwoAxes(rig.endDofs[i][0], rig.endDofs[i][1], rig.endKey[i], wanted,
                                       IsArm(limb) ? RangeClamp::kBySign : RangeClamp::kNearest);
    const glm::quat endFirst = glm::angleAxis(end.x, rig.endDofs[i][0].axis);
    const glm::quat endSecond = glm::angleAxis(end.y, rig.endDofs[i][1].axis);
    pose.worldRotations[rig.end[i]] = glm::normalize(lowerWorld * endFirst * endSecond);

    const glm::vec3 endKey = endFirst * endSecond * rig.endKey[i];
    pose.reached[i] = glm::length(rootRotation * (upperBone + hingeTurn * lowerBone) - reach) < 1e-3f;
    pose.endMatched[i] = glm::dot(endKey, wanted) > kEndKeyCos;
  }

  // End joints (no body of their own) follow their parent; then forward kinematics.
  pose.worldPositions.assign(skeleton.joints.size(), goal.pelvisPosition);
  for (int j = 0; j < skeleton.JointCount(); ++j) {
    const SkeletonJoint& joint = skeleton.joints[j];
    if (joint.parent < 0) continue;
    if (!joint.hasBox) pose.worldRotations[j] = pose.worldRotations[joint.parent];
    pose.worldPositions[j] = pose.worldPositions[joint.parent] + pose.worldRotations[joint.parent] * joint.restOffset;
  }
  return pose;
}

std::vector<glm::quat> LocalRotations(const Skeleton& skeleton, const std::vector<glm::quat>& world) {
  std::vector<glm::quat> local(world.size());
  for (int j = 0; j < skeleton.JointCount(); ++j) {
    const int parent = skeleton.joints[j].parent;
    local[j] = parent < 0 ? world[j] : glm::normalize(glm::inverse(world[parent]) * world[j]);
  }
  return local;
}

}  // namespace rise
