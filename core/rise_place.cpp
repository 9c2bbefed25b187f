// SPDX-License-Identifier: MIT
// Phase 0's end: hands and feet placed left and right of the prone body, put
// down, and the push up onto them.
#include "core/rise_controller_detail.h"

namespace rise {

using namespace rise_controller_detail;

namespace {

// The place swings the hands to kHandHover above their spots (0.04, 0.06 and
// 0.08 m measured: 12, 13 and 14 of 36 prone starts stood, 2, 10 and 8 of
// them with no contact sliding 5 cm); they then come down aiming kHandPress
// into the ground, so that they land bearing.
constexpr float kHandHover = 0.06f;  // m
constexpr float kHandPress = 0.005f;  // m

// A foot whose ankle is farther than this from its spot swings there in its joints.
constexpr float kJointSwingFoot = 0.8f;  // m

}  // namespace

RiseController::Move RiseController::PlanPlace(const BodyReading& r) {
  heading_ = HeadingForward(r);
  const glm::vec3 left = glm::normalize(glm::cross(kUp, heading_));
  Move move;
  move.name = "place";
  move.phase = RisePhase::kPlace;
  move.duration = 1.0;
  move.from = MeasuredTrunk(r);
  move.to = move.from;
  move.to.pelvisRotation = move.to.chestRotation = TrunkRotation(heading_, 0.0f);
  PoseGoal trunk;
  trunk.pelvisPosition = move.from.pelvis;
  trunk.pelvisRotation = trunk.chestRotation = move.to.chestRotation;
  std::array<float, 2> travel{};  // how far each hand goes, world
  for (int i = 0; i < 2; ++i) {
    const Limb hand = static_cast<Limb>(i);
    // The wrist beside the chest, under the shoulder and a little toward the
    // hips: where a push-up starts (the palm lies outward of it).
    const glm::vec3 shoulder = LimbRoot(def_.skeleton, rig_, trunk, hand);
    LimbMove& m = move.limbs[i];
    m = HoldLimb(r, hand, false);
    m.toRotation = PlantedHandRotation(hand);
    // Lying, the shoulder is only a few cm up: a wrist under it is out of
    // reach of the folded arm, which then put the fingertips down short of it
    // and dragged them 20-30 cm along the ground toward it. So the wrist goes
    // the least distance toward the hips that the arm reaches from this trunk.
    PoseGoal reach = trunk;
    reach.limbs[i].endRotation = m.toRotation;
    BodyPose pose;
    for (float back = 0.04f; back < 0.5f * armReach_; back += 0.02f) {
      const glm::vec3 spot = Project(ground_, shoulder - heading_ * back);
      m.to = reach.limbs[i].target = WristAbove(hand, spot, m.toRotation) + ground_.normal * kHandHover;
      pose = SolveBodyPose(def_.skeleton, rig_, reach);
      if (glm::length(pose.worldPositions[rig_.end[i]] - m.to) <= kReachTolerance) break;
    }
    travel[i] = glm::length(m.to - r.jointPositions[rig_.end[i]]);
    if ((move_.name == "arm out" || move_.name == "arm turn") && move_.limbs[i].mode == LimbMode::kJoint) {
      // An arm just brought out from overhead is bent elbow-up at the side,
      // where the solution for the wrist's path starts in another branch: the
      // servos snapped the arm across and whipped the hand at 10-12 m/s (33
      // of 63 runs over a bound in 1000 stress runs). It swings in its joints
      // to the pose that holds the hand over its spot instead.
      m = SwingInJoints(r, hand, pose);
    }
    m.lift = HandSwingLift(hand);
    m.span = 0.7f;
  }
  for (int i = 2; i < 4; ++i) {
    // Each foot steps to a wide crawl stance behind the hips and lands with its
    // toes tucked under, standing on its toe edge.
    const Limb foot = static_cast<Limb>(i);
    const float side = IsLeft(foot) ? 1.0f : -1.0f;
    const glm::vec3 hip = LimbRoot(def_.skeleton, rig_, trunk, foot);
    const float hipHalf = std::fabs(glm::dot(hip - move.from.pelvis, left));
    const glm::vec3 toe = Project(ground_, hip - heading_ * (0.9f * legReach_) + left * side * (Scaled(kCrawlHalfStance) - hipHalf));
    LimbMove& m = move.limbs[i];
    m = HoldLimb(r, foot, false);
    m.toRotation = FootRotation(heading_, glm::radians(80.0f));
    m.to = AnkleForToe(toe, m.toRotation);
    m.lift = static_cast<float>(spec_.style.stepHeightM);
    m.span = 0.7f;
    // Turned from lying on its instep to its toes while it rose, the foot
    // brought its toe edge back down to within 1 cm of the ground early in
    // the swing and scuffed it 5 cm (18 of 144 prone starts at the tired
    // style's pace 0.61). At full pace the servos' lag holds the turn back;
    // slower, they track it closely, so the turn waits up to a tenth of the
    // swing, the full tenth at pace 0.6 and below. bench/prone_variants 144
    // prone, tired (speed 0.8, tiredness 0.6): passed every bar 95 -> 106,
    // stood 128 -> 129; at speed 0.5 (72) 47 -> 48 passed, 68 -> 72 stood.
    // (A tenth at every pace cost 3 of the 144 at full pace.)
    m.turnDelay = static_cast<float>(0.1 * std::clamp((1.0 - StylePace(spec_.style)) / 0.4, 0.0, 1.0));
    // A foot with far to go swings in its joints to the pose that holds it
    // over its spot, as an arm brought out from overhead does: along its
    // ankle's path the hip's two angles passed into another branch and the
    // servos snapped the leg round, the foot at 10.7 m/s (stress seed 5132,
    // its ankle 1.27 m from its spot). Nine places in ten move a foot less
    // than 0.6 m (stress seeds 5001-5300), so only the long ones swing so.
    if (glm::length(m.to - m.from) > kJointSwingFoot) {
      PoseGoal reach = trunk;
      reach.limbs[i].target = m.to;
      reach.limbs[i].endRotation = m.toRotation;
      const float lift = m.lift, turnDelay = m.turnDelay;
      m = SwingInJoints(r, foot, SolveBodyPose(def_.skeleton, rig_, reach));
      m.lift = lift;
      m.span = 0.7f;
      m.turnDelay = turnDelay;
    }
  }
  // The hand with the shorter way goes first, with the foot on its side; the
  // other two 0.3 of the move later. Mirrored starts so place in mirrored
  // order: left always first stood 20 of 36 side_left starts against 30
  // side_right, this 31 and 30 (and the diagonal foot first, 30 and 27, cost
  // 8 prone starts).
  const bool leftFirst = travel[0] <= travel[1];
  for (int first : {0, 2}) {
    move.limbs[first].delay = leftFirst ? 0.0f : 0.3f;
    move.limbs[first + 1].delay = leftFirst ? 0.3f : 0.0f;
  }
  return move;
}

RiseController::Move RiseController::PlanHandsDown(const BodyReading& r) const {
  // The place leaves the hands hovering: its swing lags the wrist targets,
  // and a hand swung straight onto the ground touched down at up to 2 m/s with
  // its fingers hanging, then slid 10-30 cm. Here each comes straight down
  // where it is, turned flat, and lands at rest.
  Move move;
  move.name = "hands down";
  move.phase = RisePhase::kPlace;
  move.duration = 0.5;
  move.from = move.to = MeasuredTrunk(r);
  for (int i = 0; i < kLimbCount; ++i) move.limbs[i] = HoldLimb(r, static_cast<Limb>(i), false);
  for (int i = 0; i < 2; ++i) {
    const Limb hand = static_cast<Limb>(i);
    LimbMove& m = move.limbs[i];
    m.toRotation = PlantedHandRotation(hand);
    const glm::vec3 spot = Project(ground_, r.jointPositions[rig_.end[i]]);
    m.to = WristAbove(hand, spot, m.toRotation) - ground_.normal * kHandPress;
  }
  return move;
}

RiseController::Move RiseController::PlanCatch(const BodyReading& r) const {
  // A rise that tips forward off its toes is not yet down: a person puts the
  // hands to the ground and goes on from all fours. Counted as a fall, the
  // body was let settle, and as its feet were still under it a new rise began
  // at once, its CoM rocking back at 0.2-0.4 m/s from the hands' push, and fell
  // backward (stress seed 80). Stress seeds 1-1000: tries that ended in the
  // rise 239 -> 98 (43 catches missed, a fall from the place), stood 383 -> 392.
  Move move = PlanHandsDown(r);
  move.name = "catch";
  return move;
}

RiseController::Move RiseController::PlanPush(const BodyReading& r) {
  Move move;
  move.name = "push";
  move.phase = RisePhase::kPush;
  move.duration = 1.4;
  move.from = MeasuredTrunk(r);
  for (int i = 0; i < 2; ++i) move.limbs[i] = HoldLimb(r, static_cast<Limb>(i), true);
  glm::vec3 ankles(0.0f);
  for (int i = 2; i < 4; ++i) {
    LimbMove& m = move.limbs[i] = ToePivot(r, static_cast<Limb>(i), glm::radians(60.0f));
    ankles += AnkleForToe(m.to, m.toRotation);
  }
  ankles *= 0.5f;
  // Up onto hands and feet: the CoM rises to the crawl height a third of the
  // way from the hands to the feet, the trunk pitched so the arms stay nearly
  // straight (the "bear" stance the crawl starts from).
  const glm::vec3 wrists = 0.5f * (move.limbs[0].to + move.limbs[1].to);
  const glm::vec3 comGoal = Project(ground_, glm::mix(wrists, ankles, 0.35f)) + kUp * crawlComHeight_;
  PlanTrunk(move, comGoal, {true, true});
  placeTries_ = 0;
  crawlSteps_ = 0;
  shiftTries_ = 0;
  stepSpot_ = {};
  putDowns_ = 0;
  feetIn_ = false;
  crawlOffset_ = glm::vec3(0.0f);
  return move;
}

RiseController::Move RiseController::OnAllFours(const BodyReading& r, const char* name, double duration) const {
  Move move;
  move.phase = RisePhase::kCrawl;
  move.name = name;
  move.duration = duration;
  move.from = MeasuredTrunk(r);
  for (int i = 0; i < 2; ++i) move.limbs[i] = HoldLimb(r, static_cast<Limb>(i), true);
  for (int i = 2; i < 4; ++i) {
    move.limbs[i] = ToePivot(r, static_cast<Limb>(i), 0.0f);
    move.limbs[i].toRotation = move.limbs[i].fromRotation;
  }
  return move;
}

}  // namespace rise
