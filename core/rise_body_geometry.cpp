// SPDX-License-Identifier: MIT
// Geometry of the measured body for the planner: trunk, contacts, support
// regions, balance and capture points, and where hands and feet go to lie flat.
#include "core/rise_controller_detail.h"

namespace rise {

using namespace rise_controller_detail;

namespace {

// Rotation about +Y that turns +Z onto the horizontal direction `forward`.
glm::quat HeadingRotation(const glm::vec3& forward) {
  return glm::angleAxis(std::atan2(forward.x, forward.z), kUp);
}

// Rotation with the given images of +X and +Y (both unit, orthogonal).
glm::quat FromAxes(const glm::vec3& x, const glm::vec3& y) {
  return glm::normalize(glm::quat_cast(glm::mat3(x, y, glm::cross(x, y))));
}

// A limb's root angles and hinge angle (degrees) in the given local rotations.
glm::vec3 LimbAnglesDeg(const BipedDef& def, const BodyRig& rig, const std::vector<glm::quat>& local, int limb) {
  float root[3] = {}, hinge[3] = {};
  def.JointAngles(rig.upper[limb], local[rig.upper[limb]], root);
  def.JointAngles(rig.lower[limb], local[rig.lower[limb]], hinge);
  return glm::vec3(root[0], root[1], hinge[0]);
}

}  // namespace

RiseController::TrunkPose RiseController::MeasuredTrunk(const BodyReading& r) const {
  return TrunkPose{r.jointPositions[rig_.pelvis], r.jointRotations[rig_.pelvis], r.jointRotations[rig_.chest]};
}

RiseController::LimbMove RiseController::HoldLimb(const BodyReading& r, Limb limb, bool planted) const {
  const int end = rig_.end[static_cast<int>(limb)];
  LimbMove hold;
  hold.mode = LimbMode::kWorld;
  hold.from = hold.to = r.jointPositions[end];
  hold.fromRotation = hold.toRotation = r.jointRotations[end];
  hold.planted = planted;
  return hold;
}

RiseController::LimbMove RiseController::SwingToAngles(const BodyReading& r, Limb limb,
                                                       const std::array<float, 5>& anglesDeg) const {
  const int i = static_cast<int>(limb);
  const std::vector<glm::quat> local = LocalRotations(def_.skeleton, r.jointRotations);
  LimbMove m;
  m.mode = LimbMode::kJoint;
  m.from = glm::radians(LimbAnglesDeg(def_, rig_, local, i));
  m.to = glm::radians(glm::vec3(anglesDeg[0], anglesDeg[1], anglesDeg[2]));
  m.fromRotation = local[rig_.end[i]];
  m.toRotation = def_.JointRotation(rig_.end[i], &anglesDeg[3]);
  return m;
}

RiseController::LimbMove RiseController::SwingInJoints(const BodyReading& r, Limb limb, const BodyPose& pose) const {
  const int i = static_cast<int>(limb);
  const std::vector<glm::quat> local = LocalRotations(def_.skeleton, pose.worldRotations);
  const glm::vec3 angles = LimbAnglesDeg(def_, rig_, local, i);
  LimbMove m = SwingToAngles(r, limb, {angles.x, angles.y, angles.z, 0, 0});
  m.toRotation = local[rig_.end[i]];
  return m;
}

RiseController::LimbMove RiseController::ToePivot(const BodyReading& r, Limb foot, float heelLift) const {
  const int end = rig_.end[static_cast<int>(foot)];
  LimbMove pivot;
  pivot.mode = LimbMode::kToePivot;
  pivot.from = pivot.to = Project(ground_, r.jointPositions[end] + r.jointRotations[end] * toeLocal_);
  pivot.fromRotation = r.jointRotations[end];
  pivot.toRotation = FootRotation(heading_, heelLift);
  pivot.planted = true;
  return pivot;
}

glm::vec3 RiseController::FeetCentre(const BodyReading& r) const {
  glm::vec3 sum(0.0f);
  for (int i = 2; i < 4; ++i) {
    const int foot = rig_.end[i];
    const BoneBox& box = def_.skeleton.joints[foot].box;
    sum += r.jointPositions[foot] + r.jointRotations[foot] * box.center;
  }
  return Project(ground_, sum * 0.5f);
}

glm::vec3 RiseController::BalancePoint(const BodyReading& r) const {
  // Between the ankles and the soles' centres: where a person standing at ease
  // keeps the CoM, so the ankles work little and the toes and heels keep a margin.
  glm::vec3 ankles(0.0f);
  for (int i = 2; i < 4; ++i) ankles += 0.5f * r.jointPositions[rig_.end[i]];
  return 0.5f * (FeetCentre(r) + Project(ground_, ankles));
}

SupportPolygon RiseController::FeetRegion(const BodyReading& r) const {
  // The soles as they lie once flat: from each toe edge back along the heading
  // by the foot's length. While the heels are still up the body rests on its
  // toes, but the rise flattens the feet, so this is the region the CoM must
  // reach before the hands let go.
  const BoneBox& box = def_.skeleton.joints[rig_.end[2]].box;
  const float footLength = 2.0f * box.halfExtents.z;
  const glm::vec3 left = glm::normalize(glm::cross(kUp, heading_));
  std::vector<glm::vec2> points;
  for (int i = 2; i < 4; ++i) {
    const int foot = rig_.end[i];
    const glm::vec3 toe = Project(ground_, r.jointPositions[foot] + r.jointRotations[foot] * toeLocal_);
    for (float side : {-1.0f, 1.0f}) {
      const glm::vec3 edge = toe + left * side * box.halfExtents.x;
      points.push_back(Ground(edge));
      points.push_back(Ground(edge - heading_ * footLength));
    }
  }
  return SupportPolygon::FromPoints(points);
}

SupportPolygon RiseController::SupportRegion(const BodyReading& r) const {
  std::vector<glm::vec2> points = FeetRegion(r).hull;
  for (int i = 0; i < 2; ++i) {
    if (planted_[i]) points.push_back(Ground(r.jointPositions[rig_.end[i]]));
  }
  return SupportPolygon::FromPoints(points);
}

glm::vec3 RiseController::CapturePoint(const BodyReading& r) const {
  const float omega = std::sqrt(9.81f / std::max(0.3f, Height(ground_, r.com)));
  return r.com + r.comVelocity / omega;
}

glm::vec3 RiseController::HeadingForward(const BodyReading& r) const {
  // The direction from the pelvis toward the head, along the ground: the way
  // the body will face once it stands after rising over its feet.
  const glm::vec3 along = r.jointPositions[rig_.head] - r.jointPositions[rig_.pelvis];
  return SafeNormalize(Horizontal(along), glm::vec3(0.0f, 0.0f, 1.0f));
}

bool RiseController::FaceDown(const BodyReading& r) const {
  const glm::vec3 face = r.jointRotations[rig_.chest] * glm::vec3(0, 0, 1);
  return glm::dot(face, ground_.normal) < -0.7f;
}

// ---------------------------------------------------------------------------
// Placement helpers

glm::quat RiseController::TrunkRotation(const glm::vec3& forward, float pitch) const {
  // pitch 0: lying face down with the head toward `forward`; pi/2: upright
  // facing `forward`; negative: head down (the pike of the crawl).
  return glm::normalize(HeadingRotation(forward) * glm::angleAxis(0.5f * kPi - pitch, glm::vec3(1, 0, 0)));
}

glm::quat RiseController::FootRotation(const glm::vec3& forward, float heelLift) const {
  // Flat on the ground plane, toes along `forward`, heel raised about the toe edge.
  const glm::vec3 n = ground_.normal;
  const glm::vec3 toes = SafeNormalize(forward - n * glm::dot(forward, n), glm::vec3(0, 0, 1));
  const glm::quat flat = FromAxes(glm::cross(n, toes), n);
  return glm::normalize(flat * glm::angleAxis(heelLift, glm::vec3(1, 0, 0)));
}

glm::quat RiseController::HandRotation(Limb hand, const glm::vec3& fingers) const {
  // The bone's -Y points along the fingers; the palm (-X of the left hand,
  // +X of the right, facing the thigh in the bind pose) faces the ground.
  const glm::vec3 n = ground_.normal;
  const glm::vec3 along = SafeNormalize(fingers - n * glm::dot(fingers, n), glm::vec3(0, 0, 1));
  const glm::vec3 x = hand == Limb::kHandLeft ? n : -n;
  return FromAxes(x, -along);
}

float RiseController::HandSwingLift(Limb hand) const {
  // The swing path is the wrist's; the hand hangs up to its own length below
  // it in mid-swing, so the fingertips clear the ground only if the wrist
  // rises that much more than the style's step height.
  const BoneBox& box = def_.skeleton.joints[rig_.end[static_cast<int>(hand)]].box;
  return static_cast<float>(spec_.style.stepHeightM) + 2.0f * box.halfExtents.y;
}

glm::quat RiseController::PlantedHandRotation(Limb hand) const {
  // The arm has no pronation (shoulder and wrist are 2-DOF, the elbow a hinge),
  // so a palm laid flat in front of the shoulder can only point its fingers
  // outward, turned a little forward: wrist extension does the rest.
  const glm::vec3 left = glm::normalize(glm::cross(kUp, heading_));
  return HandRotation(hand, left * (IsLeft(hand) ? 1.0f : -1.0f) + heading_ * 0.35f);
}

glm::vec3 RiseController::WristAbove(Limb hand, const glm::vec3& groundPoint, const glm::quat& rotation) const {
  const BoneBox& box = def_.skeleton.joints[rig_.end[static_cast<int>(hand)]].box;
  glm::vec3 palmOffset = rotation * box.center;
  palmOffset = AlongPlane(ground_, palmOffset);
  return WristForPalm(hand, groundPoint + palmOffset, rotation);
}

glm::vec3 RiseController::WristForPalm(Limb hand, const glm::vec3& palmPoint, const glm::quat& rotation) const {
  const BoneBox& box = def_.skeleton.joints[rig_.end[static_cast<int>(hand)]].box;
  const glm::vec3 boxCentre = palmPoint + ground_.normal * (box.halfExtents.x + 0.002f);
  return boxCentre - rotation * box.center;
}

glm::vec3 RiseController::AnkleForToe(const glm::vec3& toePoint, const glm::quat& rotation) const {
  return toePoint + ground_.normal * 0.002f - rotation * toeLocal_;
}

glm::vec3 RiseController::PoseCom(const PoseGoal& goal) const {
  return PoseCom(SolveBodyPose(def_.skeleton, rig_, goal));
}

glm::vec3 RiseController::PoseCom(const BodyPose& pose) const {
  glm::vec3 sum(0.0f);
  for (int j = 0; j < def_.skeleton.JointCount(); ++j) {
    const SkeletonJoint& joint = def_.skeleton.joints[j];
    if (!joint.hasBox) continue;
    sum += def_.bones[j].massKg * (pose.worldPositions[j] + pose.worldRotations[j] * joint.box.center);
  }
  return sum / totalMass_;
}

float RiseController::Clearance(const BodyReading& r, Limb limb) const {
  const int end = rig_.end[static_cast<int>(limb)];
  const BoneBox& box = def_.skeleton.joints[end].box;
  float lowest = 1e9f;
  for (int corner = 0; corner < 8; ++corner) {
    lowest = std::min(lowest, Height(ground_, r.jointPositions[end] + r.jointRotations[end] * box.Corner(corner)));
  }
  return lowest;
}

glm::vec3 RiseController::ContactPoint(const BodyReading& r, Limb limb) const {
  const int end = rig_.end[static_cast<int>(limb)];
  const BoneBox& box = def_.skeleton.joints[end].box;
  const glm::quat rotation = r.jointRotations[end];
  // A soft wrist loads the heel of the hand.
  if (IsArm(limb)) return Project(ground_, r.jointPositions[end] + rotation * (0.3f * box.center));
  // A foot up on its toes presses at the toe edge.
  if (glm::dot(rotation * kUp, ground_.normal) < std::cos(glm::radians(10.0f))) {
    return Project(ground_, r.jointPositions[end] + rotation * toeLocal_);
  }
  return Project(ground_, r.jointPositions[end] + rotation * box.center);
}

glm::vec3 RiseController::SupportPoint(const BodyReading& r, Limb limb, const glm::vec3& pressure) const {
  const int end = rig_.end[static_cast<int>(limb)];
  const glm::quat rotation = r.jointRotations[end];
  if (IsArm(limb) || glm::dot(rotation * kUp, ground_.normal) < std::cos(glm::radians(10.0f))) return ContactPoint(r, limb);
  // A flat foot is to press along its length at the wanted pressure point:
  // where the force must act for the body to balance. (Where it presses now would be
  // wrong: tipping back, the pressure moves to the heel, and feeding that
  // forward would take away the ankle torque that stops the tipping.)
  const BoneBox& box = def_.skeleton.joints[end].box;
  const glm::vec3 centre = r.jointPositions[end] + rotation * box.center;
  const glm::vec3 along = rotation * glm::vec3(0.0f, 0.0f, 1.0f);
  const float offset = std::clamp(glm::dot(pressure - centre, along), -box.halfExtents.z, box.halfExtents.z);
  return Project(ground_, centre + along * offset);
}

}  // namespace rise
