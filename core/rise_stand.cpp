// SPDX-License-Identifier: MIT
// Phase 2: the rise from the squat with the CoM kept over the feet, and the
// still stand it ends in.
#include "core/rise_controller_detail.h"
#include "base/assert.h"

namespace rise {

using namespace rise_controller_detail;

namespace {

// A hand let go in the rise (or a foot the roll's over lets go) first goes this
// far straight up. A hand sent straight to
// the side along the chest's frame, it was swept along the ground as it left:
// the hands of prone starts slid 3-5 cm in their last moment on the ground
// (bench/prone_variants, 3 of 144 prone starts and 23 of 144 tired ones missed
// the slip bar so).
constexpr float kLiftOff = 0.05f;  // m

// How high a hand swung to the side (ArmToSide) rises early in the swing and
// holds, above its arc: along the joints' arcs from the ground the hand's first
// stretch runs along the ground (without a lift, 48 of bench/prone_variants'
// 144 prone starts slid a hand 16-22 cm; with 0.05 / 0.08 m 8 / 9, with 0.12,
// 0.15 and 0.2 m none).
constexpr float kArmToSideLift = 0.15f;  // m

}  // namespace

std::array<float, 2> RiseController::LegPitches(const BodyReading& r, int leg) const {
  // Pitch from the vertical toward the heading, of the shin (ankle to knee) and
  // of the thigh (knee to hip).
  const glm::vec3 ankle = r.jointPositions[rig_.end[leg]], knee = r.jointPositions[rig_.lower[leg]];
  const glm::vec3 hip = r.jointPositions[rig_.upper[leg]];
  auto pitch = [&](const glm::vec3& v) { return std::atan2(glm::dot(v, heading_), glm::dot(v, kUp)); };
  return {pitch(knee - ankle), pitch(hip - knee)};
}

glm::vec3 RiseController::RisingPelvis(const Move& move, float e, const BodyReading& r) const {
  // The legs straighten in their own angles, shin and thigh pitch going to zero
  // together, standing on the feet where they are. A straight line for the
  // pelvis instead would carry the knees forward of what the ankles allow on
  // the way up out of a deep squat.
  glm::vec3 pelvis(0.0f), ankles(0.0f);
  for (int leg = 2; leg < 4; ++leg) {
    const float shinLength = glm::length(def_.skeleton.joints[rig_.end[leg]].restOffset);
    const float thighLength = glm::length(def_.skeleton.joints[rig_.lower[leg]].restOffset);
    auto along = [&](float pitch) { return kUp * std::cos(pitch) + heading_ * std::sin(pitch); };
    const std::array<float, 2>& from = move.legPitches[leg - 2];
    const glm::vec3 ankle = r.jointPositions[rig_.end[leg]];
    ankles += 0.5f * ankle;
    pelvis += 0.5f * (ankle + shinLength * along(from[0] * (1.0f - e)) + thighLength * along(from[1] * (1.0f - e)));
  }
  // Standing at ease the legs lean forward at the ankles, the pelvis over the
  // balance point: the upright body's CoM is there with the trunk upright.
  // Straight up over the ankles it stayed behind, and the hip strategy held the
  // trunk leaning forward through the stand (pelvis to head 9.4-9.6 deg from
  // vertical at the end of 143 of bench/prone_variants' 144 prone starts, 16.7
  // deg in one, over the clip's 15 deg bar; now at most 0.2 deg in all 144). The
  // rise brings the pelvis there as the legs straighten; the stand keeps it
  // there (starting each stand move from over the ankles, the body bowed 8 deg
  // and back once a second).
  const float forward = move.phase == RisePhase::kStand ? 1.0f : e;
  return pelvis + forward * Horizontal(BalancePoint(r) - ankles);
}

RiseController::Move RiseController::RiseMove(const BodyReading& r) const {
  Move move;
  move.name = "rise";
  move.phase = RisePhase::kRise;
  move.duration = 2.6;
  move.keepComOverFeet = true;
  for (int leg = 2; leg < 4; ++leg) move.legPitches[leg - 2] = LegPitches(r, leg);
  move.from = MeasuredTrunk(r);
  move.to.pelvisRotation = move.to.chestRotation = TrunkRotation(heading_, 0.5f * kPi);
  move.to.pelvis = FeetCentre(r) + kUp * standPelvisHeight_ * 0.985f;
  for (int i = 0; i < 2; ++i) move.limbs[i] = ArmToSide(r, static_cast<Limb>(i), 0.0f);
  for (int i = 2; i < 4; ++i) {
    move.limbs[i] = ToePivot(r, static_cast<Limb>(i), 0.0f);
    move.limbs[i].span = 0.5f;
  }
  return move;
}

RiseController::LimbMove RiseController::ArmToSide(const BodyReading& r, Limb limb, float delay) const {
  // Swung down in the joints' own angles to hang at the side (the bind pose).
  // Taken along a straight line in the chest's frame, an arm that started
  // overhead of a chest folded down over the knees passed through the
  // shoulder: half way the IK's arm flipped from in front to behind, and the
  // servos swung it the other way round, up over the head at 9 m/s (the prone
  // sample's rise).
  LimbMove m = SwingToAngles(r, limb, {0, 0, 0, 0, 0});
  m.lift = kArmToSideLift;
  m.delay = delay;
  m.span = std::min(0.6f, 1.0f - delay);
  return m;
}

RiseController::LimbMove RiseController::LiftOff(const BodyReading& r, Limb limb) const {
  LimbMove m = HoldLimb(r, limb, false);
  m.from = m.to = m.from + ground_.normal * kLiftOff;
  return m;
}

void RiseController::LetGoOverFeet(const BodyReading& r) {
  // In the rise a hand's world-space goal is either held (planted) or lifting off.
  auto world = [&](int i) { return move_.limbs[i].mode == LimbMode::kWorld; };
  // This runs every step of the rise: the feet's polygon only while a hand is on the ground.
  if (!world(0) && !world(1)) return;
  const bool overSoles = FeetRegion(r).SignedDistance(Ground(r.com)) < 0.0f;
  for (int i = 0; i < 2; ++i) {
    if (!world(i)) continue;
    const Limb hand = static_cast<Limb>(i);
    const bool lifting = !move_.limbs[i].planted;
    if (lifting ? Clearance(r, hand) > kLandedClearance : (overSoles || !r.touching[i])) {
      move_.limbs[i] = lifting ? ArmToSide(r, hand, std::min(progress_, 0.9f)) : LiftOff(r, hand);
    }
  }
}

RiseController::Move RiseController::PlanRise(const BodyReading& r) {
  Move move = RiseMove(r);
  // A squat that starts its rise with the CoM short of the soles keeps its
  // hands down until the rise's balance has brought it over them
  // (LetGoOverFeet). Let go at once, such squats on a 10 deg slope tipped
  // forward onto their faces (prone_variants 48 on 10 deg: 21 -> 25 stand;
  // tired prone 144: 129 -> 137; stress 600: 198 -> 205).
  const bool overSoles = FeetRegion(r).SignedDistance(Ground(r.com)) <= 0.0f;
  for (int i = 0; i < 2; ++i) {
    if (r.touching[i]) move.limbs[i] = overSoles ? LiftOff(r, static_cast<Limb>(i)) : HoldLimb(r, static_cast<Limb>(i), true);
  }
  balanceOffset_ = glm::vec3(0.0f);
  balanceLean_ = BalanceLean(move, 0.0f, r, 0.0f, kMaxBalanceLean);
  return move;
}

RiseController::Move RiseController::PlanStand(const BodyReading& r) {
  // Standing holds the pose the rise ended in, and its balance feedback
  // carries on: re-planned from the measured trunk and legs every second, the
  // goal went back to where the servos sagged to and the integral to zero, and
  // on a 10 deg cross-slope that jolted the CoM 2 cm sideways and back each
  // time: the body never came to rest.
  RISE_ASSERT(hasMove_ && (move_.phase == RisePhase::kRise || move_.phase == RisePhase::kStand));
  Move move = RiseMove(r);
  move.from = move_.to;
  move.legPitches = {};
  move.name = "stand";
  move.phase = RisePhase::kStand;
  move.duration = 1.0;
  // The arms hang where the rise swung them, held there (no swing, so no lift).
  for (int i = 0; i < 2; ++i) {
    LimbMove& arm = move.limbs[i];
    arm.from = arm.to;
    arm.fromRotation = arm.toRotation;
    arm.lift = 0.0f;
  }
  if (standTime_ < 0.0) standTime_ = r.time;
  return move;
}

}  // namespace rise
