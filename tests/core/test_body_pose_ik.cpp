// SPDX-License-Identifier: MIT
#include "core/biped_def.h"
#include "core/body_pose_ik.h"
#include "test_support.h"

#include <glm/geometric.hpp>

namespace {

// The standing bind pose as a goal: trunk upright, limbs at their bind positions.
rise::PoseGoal StandingGoal(const rise::BipedDef& def, const rise::BodyRig& rig) {
  const std::vector<glm::vec3> bind = def.skeleton.BindPositions();
  rise::PoseGoal goal;
  goal.pelvisPosition = bind[rig.pelvis];
  for (int i = 0; i < rise::kLimbCount; ++i) {
    goal.limbs[i].target = bind[rig.end[i]];
    goal.limbs[i].pole = i < 2 ? glm::vec3(0, 0, -1) : glm::vec3(0, 0, 1);
  }
  return goal;
}

}  // namespace

TEST_SUITE("body_pose_ik") {
TEST_CASE("the standing goal reproduces the bind pose") {
  const rise::BipedDef def = rise::MakeBipedDef(1.75f, 70.0f);
  const rise::BodyRig rig = rise::BodyRig::FromSkeleton(def.skeleton, glm::radians(150.0f), glm::radians(150.0f));
  const rise::BodyPose pose = rise::SolveBodyPose(def.skeleton, rig, StandingGoal(def, rig));
  const std::vector<glm::vec3> bind = def.skeleton.BindPositions();
  for (int j = 0; j < def.skeleton.JointCount(); ++j) {
    INFO(def.skeleton.joints[j].name);
    CHECK_VEC3_NEAR(pose.worldPositions[j], bind[j], 1e-4f);
  }
}

TEST_CASE("a crouch keeps the feet on their targets and bends the knees forward") {
  const rise::BipedDef def = rise::MakeBipedDef(1.75f, 70.0f);
  const rise::BodyRig rig = rise::BodyRig::FromSkeleton(def.skeleton, glm::radians(150.0f), glm::radians(150.0f));
  rise::PoseGoal goal = StandingGoal(def, rig);
  goal.pelvisPosition.y -= 0.35f;
  const rise::BodyPose pose = rise::SolveBodyPose(def.skeleton, rig, goal);
  for (int i = 2; i < 4; ++i) {
    CHECK(pose.reached[i]);
    CHECK_VEC3_NEAR(pose.worldPositions[rig.end[i]], goal.limbs[i].target, 1e-4f);
    CHECK(pose.worldPositions[rig.lower[i]].z > goal.pelvisPosition.z + 0.1f);  // knee ahead of the hip
  }
  // The shin's local rotation relative to the thigh is a pure knee flexion (about X).
  const auto local = rise::LocalRotations(def.skeleton, pose.worldRotations);
  const glm::quat knee = local[rig.lower[2]];
  CHECK(std::fabs(knee.y) < 1e-4f);
  CHECK(std::fabs(knee.z) < 1e-4f);
  CHECK(glm::angle(knee) > glm::radians(60.0f));
}
}
