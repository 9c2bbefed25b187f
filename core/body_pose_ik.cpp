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

bool InRange(float angle, const BodyRig::Axis& axis) { return angle >= axis.lower && angle <= axis.upper; }

// The turn about the unit axis u that carries w's part across u onto s's (0 when either lies along u).
float TurnAbout(const glm::vec3& u, const glm::vec3& w, const glm::vec3& s) {
  const glm::vec3 wp = w - u * glm::dot(w, u), sp = s - u * glm::dot(s, u);
  if (glm::length(wp) <= 1e-6f || glm::length(sp) <= 1e-6f) return 0.0f;
  return std::atan2(glm::dot(u, glm::cross(wp, sp)), glm::dot(wp, sp));
}

// The in-range turn nearest `angle` round the circle. How close a turn about one axis brings a
// direction to another falls off as the cosine of its distance from the best turn, so out of
// range the closer of the two limits is the one nearer round the circle.
float NearestInRange(float angle, const BodyRig::Axis& axis) {
  if (InRange(angle, axis)) return angle;
  const float turn = 2.0f * glm::pi<float>();
  const float toLower = std::fabs(std::remainder(angle - axis.lower, turn));
  const float toUpper = std::fabs(std::remainder(angle - axis.upper, turn));
  return toLower <= toUpper ? axis.lower : axis.upper;
}

// The plan turns an ankle's dorsiflexion only this far short of the joint's
// limit (40 deg, what a loaded ankle gives in a squat): the servos then never
// drive it into its stop, and the body's weight can still bend it the rest of
// the way. Over 1500 stress starts (seeds 5001-6000, 9001-9500), planned to
// the full 40 deg / 5 short / 10 short: stood 1119 / 1124 / 1058, up to 10 deg
// of slope 892 / 900 / 870 of 973; bench/prone_variants 48 supine passed
// every bar 39 / 43 / 48, 48 prone on 10 deg stood 30 / 34 / 30.
constexpr float kAnklePlanMargin = glm::radians(5.0f);

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
    if (!IsArm(static_cast<Limb>(i))) rig.endDofs[i][0].upper -= kAnklePlanMargin;
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
  // Of the two solutions for b (each already in [-pi, pi]), the one nearer the
  // joint's range (then the smaller turn) first.
  std::array<float, 2> roots{0.0f, 0.0f};
  if (radius > 1e-6f) {
    const float phase = std::atan2(B, A);
    const float spread = std::acos(std::clamp(C / radius, -1.0f, 1.0f));
    const auto cost = [&](float angle) {
      const float outside = std::max(0.0f, axis1.lower - angle) + std::max(0.0f, angle - axis1.upper);
      return std::make_pair(outside, std::fabs(angle));
    };
    roots = {std::remainder(phase + spread, 2.0f * glm::pi<float>()), std::remainder(phase - spread, 2.0f * glm::pi<float>())};
    if (cost(roots[1]) < cost(roots[0])) std::swap(roots[0], roots[1]);
  }
  // Then the turn about a0 that carries the result onto t.
  if (clamp == RangeClamp::kBySign) {
    const float b = std::clamp(roots[0], axis1.lower, axis1.upper);
    return {std::clamp(TurnAbout(a0, glm::angleAxis(b, a1) * v, t), axis0.lower, axis0.upper), b};
  }
  for (const float b : roots) {
    const float a = TurnAbout(a0, glm::angleAxis(b, a1) * v, t);
    if (InRange(a, axis0) && InRange(b, axis1)) return {a, b};
  }
  // Out of reach, the closest direction the ranges allow lies on their edge: one angle at a limit,
  // the other the best turn given it. Clamping each angle on its own instead left the second one
  // where the unreachable turn had put it.
  glm::vec2 best(0.0f);
  float bestDot = -2.0f;
  const auto consider = [&](float a, float b) {
    const float closeness = glm::dot(glm::angleAxis(a, a0) * (glm::angleAxis(b, a1) * v), t);
    if (closeness > bestDot) bestDot = closeness, best = {a, b};
  };
  for (const float a : {axis0.lower, axis0.upper}) {
    consider(a, NearestInRange(TurnAbout(a1, v, glm::angleAxis(-a, a0) * t), axis1));
  }
  for (const float b : {axis1.lower, axis1.upper}) {
    consider(NearestInRange(TurnAbout(a0, glm::angleAxis(b, a1) * v, t), axis0), b);
  }
  return best;
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
    // allows, both angles together (RangeClamp::kClosest). A far foot planted
    // for the roll's push off, its shin led round by the trunk's goal, is asked
    // for a pitch beyond its range; clamped each on its own, the pitch sat at
    // its limit while the roll stayed where the unreachable turn put it, and
    // the foot, pressed on its edge, slid 5-7 cm as the hips went over (15 of
    // bench/prone_variants' 48 supine starts; clamped by sign it also jumped
    // from one pitch limit to the other across the half turn, as it still does
    // once the sole is closer to the other limit). With the roll turned as far
    // toward flat as it goes at that pitch, 47 of the 48 passed (the ankle's
    // range then -50..30 deg; 43 with today's range and plan margin). Not for
    // every body: the 8 back starts of samples/library.json (1.75 and 1.95 m)
    // slid 4.1-4.9 cm before and 5.5-6.1 cm after, and over 144 back starts of
    // 1.50-2.05 m 72 -> 68 passed (74 with today's range). A wrist keeps the
    // by-sign clamp: turned the nearer way round, the place's hands pressed
    // their fingers down and slid 15-17 cm in all 24 side_left starts.
    const glm::quat lowerWorld = pose.worldRotations[rig.lower[i]];
    const glm::vec3 wanted = glm::normalize(glm::inverse(lowerWorld) * (limbGoal.endRotation * rig.endKey[i]));
    const glm::vec2 end = SolveTwoAxes(rig.endDofs[i][0], rig.endDofs[i][1], rig.endKey[i], wanted,
                                       IsArm(limb) ? RangeClamp::kBySign : RangeClamp::kClosest);
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
