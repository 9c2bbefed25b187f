// SPDX-License-Identifier: MIT
#include "core/biped_def.h"
#include "core/body_pose_ik.h"
#include "test_support.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <random>

namespace {

// The standing bind pose as a goal: trunk upright, limbs at their bind positions.
rise::PoseGoal StandingGoal(const rise::BipedDef& def, const rise::BodyRig& rig) {
  const std::vector<glm::vec3> bind = def.skeleton.BindPositions();
  rise::PoseGoal goal;
  goal.pelvisPosition = bind[rig.pelvis];
  for (int i = 0; i < rise::kLimbCount; ++i) {
    goal.limbs[i].target = bind[rig.end[i]];
  }
  return goal;
}

// An ankle's two axes (pitch -50..30 deg, roll -20..35 deg) and its sole's key direction.
const rise::BodyRig::Axis kPitch{{1, 0, 0}, glm::radians(-50.0f), glm::radians(30.0f)};
const rise::BodyRig::Axis kRoll{{0, 0, 1}, glm::radians(-20.0f), glm::radians(35.0f)};
const glm::vec3 kUp(0, 1, 0);

// The sole's key turned by (pitch, roll).
glm::vec3 TurnedSole(const glm::vec2& angles) {
  return glm::angleAxis(angles.x, kPitch.axis) * glm::angleAxis(angles.y, kRoll.axis) * kUp;
}

}  // namespace

TEST_SUITE("body_pose_ik") {
TEST_CASE("the standing goal reproduces the bind pose") {
  const rise::BipedDef def = rise::MakeBipedDef(1.75f, 70.0f);
  const rise::BodyRig rig = rise::BodyRig::FromDef(def);
  const rise::BodyPose pose = rise::SolveBodyPose(def.skeleton, rig, StandingGoal(def, rig));
  const std::vector<glm::vec3> bind = def.skeleton.BindPositions();
  for (int j = 0; j < def.skeleton.JointCount(); ++j) {
    INFO(def.skeleton.joints[j].name);
    // acos near a straight limb loses a little float precision.
    CHECK_VEC3_NEAR(pose.worldPositions[j], bind[j], 5e-4f);
  }
}

TEST_CASE("a crouch keeps the feet on their targets and bends the knees forward") {
  const rise::BipedDef def = rise::MakeBipedDef(1.75f, 70.0f);
  const rise::BodyRig rig = rise::BodyRig::FromDef(def);
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

TEST_SUITE("body_pose_ik") {
TEST_CASE("two-axis turns reach any direction their ranges allow") {
  const rise::BodyRig::Axis flexion{{-1, 0, 0}, glm::radians(-60.0f), glm::radians(170.0f)};
  const rise::BodyRig::Axis abduction{{0, 0, 1}, glm::radians(-30.0f), glm::radians(80.0f)};
  const glm::vec3 down(0, -1, 0);
  for (const glm::vec3 t : {glm::vec3(0, 0, 1), glm::normalize(glm::vec3(0.5f, -0.5f, 0.7f)), glm::normalize(glm::vec3(0, 0.94f, 0.34f)),
                            glm::normalize(glm::vec3(0.3f, -1.0f, -0.2f))}) {
    const glm::vec2 angles = rise::SolveTwoAxes(flexion, abduction, down, t);
    const glm::vec3 got = glm::angleAxis(angles.x, flexion.axis) * glm::angleAxis(angles.y, abduction.axis) * down;
    CHECK_VEC3_NEAR(got, glm::normalize(t), 1e-4f);
  }
  // Out of range (abducting the left arm across the body) the closest reachable direction is kept.
  const glm::vec2 clamped = rise::SolveTwoAxes(flexion, abduction, down, glm::vec3(-1, 0, 0));
  CHECK(clamped.y == doctest::Approx(glm::radians(-30.0f)));
}

TEST_CASE("two-axis turns out of range: by sign each angle to the limit on its side, closest the best pair in range") {
  // An ankle asked to turn its sole 175 deg about the pitch axis.
  const rise::BodyRig::Axis& pitch = kPitch;
  const rise::BodyRig::Axis& roll = kRoll;
  const glm::vec3& up = kUp;
  // Across the half turn (175 to -175 deg) by sign jumps from one limit to the other; closest stays.
  for (const float wantedDeg : {175.0f, -175.0f}) {
    INFO(wantedDeg);
    const glm::vec3 t = glm::angleAxis(glm::radians(wantedDeg), pitch.axis) * up;
    const glm::vec2 bySign = rise::SolveTwoAxes(pitch, roll, up, t, rise::RangeClamp::kBySign);
    const glm::vec2 closest = rise::SolveTwoAxes(pitch, roll, up, t, rise::RangeClamp::kClosest);
    CHECK(bySign.x == doctest::Approx(wantedDeg > 0.0f ? pitch.upper : pitch.lower));
    // 175 deg is 135 deg round from -50 and 145 from 30; -175 is 125 from -50 and 155 from 30.
    // Nearly opposite its target, the sole also rolls to its wider limit: turned out of the plane
    // of the two, it points less away from the target.
    CHECK(closest.x == doctest::Approx(pitch.lower));
    CHECK(closest.y == doctest::Approx(roll.upper));
    CHECK(glm::dot(TurnedSole(closest), t) >= glm::dot(TurnedSole(bySign), t) - 1e-5f);
  }
  // Pitched beyond its limit and rolled within range, the sole keeps its roll: by sign the roll
  // stays where the unreachable turn put it, which is no longer the best at the limit's pitch.
  const glm::vec3 pitchedAndRolled =
      glm::angleAxis(glm::radians(-80.0f), pitch.axis) * glm::angleAxis(glm::radians(30.0f), roll.axis) * up;
  const glm::vec2 bySign = rise::SolveTwoAxes(pitch, roll, up, pitchedAndRolled, rise::RangeClamp::kBySign);
  const glm::vec2 closest = rise::SolveTwoAxes(pitch, roll, up, pitchedAndRolled, rise::RangeClamp::kClosest);
  CHECK(closest.x == doctest::Approx(pitch.lower));
  CHECK(glm::dot(TurnedSole(closest), pitchedAndRolled) > glm::dot(TurnedSole(bySign), pitchedAndRolled) + 1e-3f);
  // Within range both give the exact turn.
  const glm::vec3 inside = glm::angleAxis(glm::radians(-20.0f), pitch.axis) * up;
  CHECK(rise::SolveTwoAxes(pitch, roll, up, inside, rise::RangeClamp::kClosest).x == doctest::Approx(glm::radians(-20.0f)));
  CHECK(rise::SolveTwoAxes(pitch, roll, up, inside, rise::RangeClamp::kBySign).x == doctest::Approx(glm::radians(-20.0f)));
}

TEST_CASE("two-axis turns, closest: no pair in the ranges turns the key nearer the target") {
  // Against a search over the ranges at 0.5 deg, for directions all round the sphere.
  const rise::BodyRig::Axis& pitch = kPitch;
  const rise::BodyRig::Axis& roll = kRoll;
  auto closeness = [](float a, float b, const glm::vec3& t) { return glm::dot(TurnedSole({a, b}), t); };
  std::mt19937& random = rise::test::Rng();
  std::normal_distribution<float> normal;
  for (int k = 0; k < 60; ++k) {
    const glm::vec3 t = glm::normalize(glm::vec3(normal(random), normal(random), normal(random)));
    const glm::vec2 closest = rise::SolveTwoAxes(pitch, roll, kUp, t, rise::RangeClamp::kClosest);
    CHECK(closest.x >= pitch.lower);
    CHECK(closest.x <= pitch.upper);
    CHECK(closest.y >= roll.lower);
    CHECK(closest.y <= roll.upper);
    float searched = -2.0f;
    for (float a = pitch.lower; a <= pitch.upper; a += glm::radians(0.5f)) {
      for (float b = roll.lower; b <= roll.upper; b += glm::radians(0.5f)) searched = std::max(searched, closeness(a, b, t));
    }
    INFO("t " << t.x << " " << t.y << " " << t.z);
    CHECK(closeness(closest.x, closest.y, t) >= searched - 1e-5f);
  }
}

TEST_CASE("a planted hand's palm turns as close to the ground as the wrist's two DOF allow") {
  const rise::BipedDef def = rise::MakeBipedDef(1.75f, 70.0f);
  const rise::BodyRig rig = rise::BodyRig::FromDef(def);
  rise::PoseGoal goal = StandingGoal(def, rig);
  // Prone push-up: trunk face down, wrists under the shoulders on the ground.
  goal.pelvisRotation = goal.chestRotation = goal.headRotation = glm::angleAxis(glm::radians(80.0f), glm::vec3(1, 0, 0));
  goal.pelvisPosition = {0.0f, 0.35f, 0.0f};
  for (int i = 0; i < 2; ++i) {
    const glm::vec3 shoulder = rise::LimbRoot(def.skeleton, rig, goal, static_cast<rise::Limb>(i));
    goal.limbs[i].target = {shoulder.x, 0.05f, shoulder.z};
    goal.limbs[i].endRotation = glm::angleAxis(glm::radians(i == 0 ? 90.0f : -90.0f), glm::vec3(0, 0, 1));
  }
  const rise::BodyPose pose = rise::SolveBodyPose(def.skeleton, rig, goal);
  for (int i = 0; i < 2; ++i) {
    INFO(i);
    CHECK(pose.reached[i]);
    CHECK_VEC3_NEAR(pose.worldPositions[rig.end[i]], goal.limbs[i].target, 1e-3f);
    // Brute force over the wrist's range: nothing turns the palm normal lower.
    const glm::quat forearm = pose.worldRotations[rig.lower[i]];
    float lowest = 1.0f;
    for (float a = rig.endDofs[i][0].lower; a <= rig.endDofs[i][0].upper; a += 0.01f) {
      for (float b = rig.endDofs[i][1].lower; b <= rig.endDofs[i][1].upper; b += 0.01f) {
        const glm::quat q = forearm * glm::angleAxis(a, rig.endDofs[i][0].axis) * glm::angleAxis(b, rig.endDofs[i][1].axis);
        lowest = std::min(lowest, (q * rig.endKey[i]).y);
      }
    }
    CHECK((pose.worldRotations[rig.end[i]] * rig.endKey[i]).y <= lowest + 0.01f);
  }
}
}

TEST_SUITE("body_pose_ik") {
TEST_CASE("a lifted swing at 90 deg of shoulder abduction keeps its own turn of the arm about itself") {
  // The arm turn leaves an arm out to the side with the shoulder at 90 deg of
  // abduction, where flexion only turns the arm about itself. Lifted a few cm,
  // the wrist target there leaves that turn to the IK, which picks its own.
  const rise::BipedDef def = rise::MakeBipedDef(1.75f, 70.0f);
  const rise::BodyRig rig = rise::BodyRig::FromDef(def);
  rise::PoseGoal goal = StandingGoal(def, rig);
  const int arm = 0;
  const glm::vec3 swing(glm::radians(-55.0f), glm::radians(91.0f), 0.0f);
  const glm::quat upper = glm::angleAxis(swing.x, rig.rootDofs[arm][0].axis) * glm::angleAxis(swing.y, rig.rootDofs[arm][1].axis);
  const glm::vec3 wrist = rise::LimbRoot(def.skeleton, rig, goal, rise::Limb::kHandLeft) +
                          upper * (def.skeleton.joints[rig.lower[arm]].restOffset + def.skeleton.joints[rig.end[arm]].restOffset);
  goal.limbs[arm].target = wrist + glm::vec3(0.0f, 0.03f, 0.0f);
  goal.limbs[arm].endRotation = upper;
  auto flexion = [&](const rise::BodyPose& pose) {
    float angles[3] = {};
    def.JointAngles(rig.upper[arm], rise::LocalRotations(def.skeleton, pose.worldRotations)[rig.upper[arm]], angles);
    return angles[0];
  };
  const float free = flexion(rise::SolveBodyPose(def.skeleton, rig, goal));
  goal.limbs[arm].swingAngles = swing;
  const float kept = flexion(rise::SolveBodyPose(def.skeleton, rig, goal));
  INFO("flexion: the IK's own " << free << " deg, with the swing's angles " << kept << " deg");
  CHECK(std::fabs(free - glm::degrees(swing.x)) > glm::degrees(rise::kMaxSwingTwist));  // the flip this guards against
  CHECK(kept == doctest::Approx(glm::degrees(swing.x)).epsilon(1e-3));
}
}
