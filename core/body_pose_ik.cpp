// SPDX-License-Identifier: MIT
#include "core/body_pose_ik.h"

#include "base/assert.h"

#include <glm/geometric.hpp>

namespace rise {
namespace {

bool IsArm(Limb limb) { return limb == Limb::kHandLeft || limb == Limb::kHandRight; }

int RequireJoint(const Skeleton& skeleton, const char* name) {
  const int index = skeleton.Find(name);
  RISE_ASSERT_MSG(index >= 0, name);
  return index;
}

// World rotation of the abdomen: halfway between pelvis and chest, so the
// spine bends evenly over its two joints.
glm::quat Abdomen(const PoseGoal& goal) { return glm::slerp(goal.pelvisRotation, goal.chestRotation, 0.5f); }

}  // namespace

const char* LimbName(Limb limb) {
  static const char* const kNames[kLimbCount] = {"hand_l", "hand_r", "foot_l", "foot_r"};
  return kNames[static_cast<int>(limb)];
}

BodyRig BodyRig::FromSkeleton(const Skeleton& skeleton, float maxElbowFlexion, float maxKneeFlexion) {
  BodyRig rig;
  rig.pelvis = RequireJoint(skeleton, "pelvis");
  rig.abdomen = RequireJoint(skeleton, "abdomen");
  rig.chest = RequireJoint(skeleton, "chest");
  rig.head = RequireJoint(skeleton, "head");
  static const char* const kUpper[kLimbCount] = {"upper_arm_l", "upper_arm_r", "thigh_l", "thigh_r"};
  static const char* const kLower[kLimbCount] = {"forearm_l", "forearm_r", "shin_l", "shin_r"};
  static const char* const kEnd[kLimbCount] = {"hand_l", "hand_r", "foot_l", "foot_r"};
  for (int i = 0; i < kLimbCount; ++i) {
    rig.upper[i] = RequireJoint(skeleton, kUpper[i]);
    rig.lower[i] = RequireJoint(skeleton, kLower[i]);
    rig.end[i] = RequireJoint(skeleton, kEnd[i]);
    rig.maxFlexion[i] = i < 2 ? maxElbowFlexion : maxKneeFlexion;
  }
  return rig;
}

glm::vec3 LimbRoot(const Skeleton& skeleton, const BodyRig& rig, const PoseGoal& goal, Limb limb) {
  const int i = static_cast<int>(limb);
  const glm::vec3 abdomen = goal.pelvisPosition + goal.pelvisRotation * skeleton.joints[rig.abdomen].restOffset;
  if (!IsArm(limb)) return goal.pelvisPosition + goal.pelvisRotation * skeleton.joints[rig.upper[i]].restOffset;
  const glm::vec3 chest = abdomen + Abdomen(goal) * skeleton.joints[rig.chest].restOffset;
  return chest + goal.chestRotation * skeleton.joints[rig.upper[i]].restOffset;
}

BodyPose SolveBodyPose(const Skeleton& skeleton, const BodyRig& rig, const PoseGoal& goal) {
  BodyPose pose;
  pose.worldRotations.assign(skeleton.joints.size(), goal.chestRotation);
  pose.worldRotations[rig.pelvis] = goal.pelvisRotation;
  pose.worldRotations[rig.abdomen] = Abdomen(goal);
  pose.worldRotations[rig.chest] = goal.chestRotation;
  pose.worldRotations[rig.head] = goal.headRotation;

  for (int i = 0; i < kLimbCount; ++i) {
    const Limb limb = static_cast<Limb>(i);
    const LimbGoal& limbGoal = goal.limbs[i];
    TwoBoneIk ik;
    ik.root = LimbRoot(skeleton, rig, goal, limb);
    ik.target = limbGoal.target;
    ik.pole = limbGoal.pole;
    ik.swivel = limbGoal.swivel;
    ik.upperLength = glm::length(skeleton.joints[rig.lower[i]].restOffset);
    ik.lowerLength = glm::length(skeleton.joints[rig.end[i]].restOffset);
    ik.maxFlexion = rig.maxFlexion[i];
    ik.restBoneDirection = glm::normalize(skeleton.joints[rig.lower[i]].restOffset);
    // Elbows bend backward, knees forward, in the standing rest pose.
    ik.restPole = IsArm(limb) ? glm::vec3(0, 0, -1) : glm::vec3(0, 0, 1);
    ik.Solve();
    pose.worldRotations[rig.upper[i]] = ik.upperRotation;
    pose.worldRotations[rig.lower[i]] = ik.lowerRotation;
    pose.worldRotations[rig.end[i]] = limbGoal.endRotation;
    pose.reached[i] = ik.reached;
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
