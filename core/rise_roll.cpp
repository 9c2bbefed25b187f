// SPDX-License-Identifier: MIT
// Phase 0, the roll: from the back or a side onto the front, the far leg pushing,
// the chest leading over, the arm left overhead brought out round the side.
#include "core/clip_quality.h"
#include "core/rise_controller_detail.h"

namespace rise {

using namespace rise_controller_detail;

namespace {

// A far leg whose ankle is this far from its hip, of the leg's reach, is set to push.
constexpr float kTuckedLeg = 0.8f;

// ... and its foot no higher than this over the ground: the push off presses it down.
constexpr float kTuckedClearance = 0.2f;  // m
constexpr float kChestOverRoll = glm::radians(120.0f);
// How far past kChestOverRoll the chest of a roll's "over" move aims.
constexpr float kOverLead = glm::radians(5.0f);
constexpr float kProneRoll = glm::radians(135.0f);
// The push off turns the trunk's goal on to kPushOffRoll, but by less than a
// half turn in one move: the goal is reached by slerp, which takes the shorter
// way round. A pelvis turned well onto the other side (past -40 deg, as a
// twisted body lies when the chest picked the roll side) had a goal past
// 180 deg, and the trunk swung back the other way, whipping the arm overhead
// to 10-10.7 m/s (stress seeds 382, 470, 502, 510, 584).
constexpr float kPushOffRoll = glm::radians(135.0f);
constexpr float kMaxPushOffTurn = glm::radians(150.0f);

// A slope from which a body flat on its back rolls downhill (PlanRoll). Below it
// the seed picks a side, as on level ground: taken from any slope, two stress
// starts on 0.8 and 2 deg (seeds 102, 173) rolled the other way and got over
// later or not at all, while the 1000 runs' failed rolls were the same.
constexpr float kDownhillRollSlope = glm::radians(3.0f);
// ... and only when it lies across the slope: its left-right axis within 60 deg
// of the fall line (this is the cosine). Lying along the fall line neither side
// is downhill; picked by the sign of a near-zero product, three of the four
// supine starts on 10 deg of bench/start_matrix rolled the other way and did
// not stand (25 -> 22 of 32).
constexpr float kAcrossSlope = 0.5f;

// Shoulder flexion past which an arm lies overhead.
constexpr float kOverheadArm = glm::radians(60.0f);

// Shoulder abduction past which an arm is out to the side (turned there by the arm out).
constexpr float kArmOutAbduction = glm::radians(70.0f);

// The arm on the roll side overhead (shoulder flexion and abduction, elbow, wrist; deg). Drawn in
// toward the head and bent at the elbow, its hand stays off the ground as the chest turns onto that
// shoulder. (Straight and out at 15 deg it hovered 19 cm up, landed mid push off, and its goal then
// pointed into the ground and dragged it up to 18 cm: all 24 supine starts of bench/prone_variants.)
constexpr std::array<float, 5> kNearArmOverhead{165, -10, 50, 0, 0};

// The near leg in the "over" of a roll from the back. The push off has lifted it; held straight
// in line with the pelvis it came down under the turning hips and was dragged 10-20 cm along the
// ground (23 of 24 supine starts). Drawn back and a little across, the knee bent, it stays in the
// air above the hips until the lie lays the thigh down with the shin up. (Drawn across by 20 deg,
// the foot of a body of 1.9 m or more stayed down and was pushed 6-7 cm along the ground as the
// leg swung there; 10 deg, with kFarArmBehind and kSkidLimit, takes the 144 back starts of
// 1.50-2.05 m that pass every bar from 53 to 81, and across by 0 / 5 / 10 / 20 deg: 71 / 74 / 81
// / 69, drawn back 10 / 20 / 30 deg: 48 / 81 / 61.)
constexpr std::array<float, 5> kNearLegAloft{-20, -10, 30, -20, 0};

// The far arm in the "over" and the lie after a push off, swung down from overhead: a little
// behind the trunk, so its hand comes down onto the buttock's side of the body last. Alongside
// (flexion 0) the hand landed beside the hip while the trunk was still turning onto the front
// and slid 5-8 cm: with the skid let-go alone (at 3.5 cm), 74 of the 144 back starts above
// failed by a hand slid so, with the arm behind 5. From a side, with no push off, it stays
// alongside: behind, 84 of 144 side starts passed every bar, against 132.
constexpr std::array<float, 5> kFarArmBehind{-30, 10, 10, 0, 0};
constexpr std::array<float, 5> kFarArmAlongside{0, 10, 10, 0, 0};

// How far a foot held planted in the "over" may skid along the ground before it lets go
// (lifted straight up, LiftOff). The push off ends with the pelvis turned to kPushedRoll; the over
// holds the far foot there while the chest leads, but the pelvis turns on a few degrees and back,
// lifting the foot and setting it down again while the trunk still moved: dragged 5-6 cm, the
// slide that failed the bundled library's average back starts. A foot that skids no longer holds
// anything, and a person lifts it. Let go after 2.5 / 3.5 / 4.5 cm: 81 / 74 / 70 of the 144
// back starts pass every bar (69 never let go). Letting go in the push off too, once the pelvis
// is past 30 / 45 deg, took the push from the roll: 0 / 33.
constexpr float kSkidLimit = 0.025f;  // m

// The near leg otherwise: straight along the pelvis, the foot relaxed.
constexpr std::array<float, 5> kNearLegAlong{5, 0, 4, -20, 0};

// The near leg in the "over" from a side, where it lies under the body: straight along the pelvis
// as kNearLegAlong, the foot square to the shin. Relaxed (pointed 20 deg), the foot lying on its
// outer edge turned in place as the leg rolled with the pelvis and slid 5-11 cm (bench/prone_variants
// 48 side_left / side_right: pass every bar 28 / 25 that way, 41 / 38 square, 36-40 / 37-38 with
// the foot anywhere from 10 deg pointed to 15 deg raised, 0 / 0 pointed 40 deg; at the tired
// style's pace 5 / 3 against 25 / 29).
constexpr std::array<float, 5> kNearLegUnder{5, 0, 4, 0, 0};

// The near leg's swing to kNearLegAlong, as the arc its ankle sweeps at full reach, past which the
// leg starts bent (a custom pose, say) and its foot is lifted kBentLegLift on the way. Straightened
// along the ground, samples/custom.json's near leg (hip 45, knee 80 deg) slid its foot 17 cm in the
// tuck. A leg lying straight swings a few centimetres and is not lifted.
constexpr float kBentLegSwing = 0.25f;  // m
constexpr float kBentLegLift = 0.08f;   // m

// Both legs in the lie: hips straight, knees bent 90 deg with the feet up (see the lie).
constexpr std::array<float, 5> kLieLeg{0, 0, 90, -50, 0};

// How high the top leg's foot is lifted in the "over" when it is not pushing (from a side, say),
// as a fraction of the leg's reach. Lying on its side, the leg's weight pulls straight against the
// hip's abduction, and no feed-forward holds a limb up while the body lies, so the servo lifts the
// foot only once its target is well above it. Lifted a step's height (8 cm), the foot stayed down
// 0.25-0.3 s while the turning pelvis dragged it 5-7 cm: 72 of 144 side starts of 1.5-2.05 m slid
// it past the bar, the library's tall side clips 6.4-6.6 cm. 0.2 / 0.25 / 0.3 / 0.35 / 0.4 of the
// reach: 100 / 116 / 127 / 122 / 109 of those 144 pass every bar (55 before). bench/prone_variants
// 48 side_left / side_right: 41 / 38 -> 48 / 48, tired style 25 / 29 -> 46 / 44.
constexpr float kTopLegLift = 0.3f;

}  // namespace

float RiseController::RollAngle(const glm::quat& segment) const {
  const glm::vec3 front = segment * glm::vec3(0, 0, 1);
  const glm::vec3 side = rollSign_ * (segment * glm::vec3(1, 0, 0));
  const float angle = std::atan2(-glm::dot(side, ground_.normal), glm::dot(front, ground_.normal));
  // Face down a little past flat reads as turned on past pi, not as -pi (on
  // the back the other way round): an arm lifted out to the side tipped a
  // prone chest a few degrees on, and the roll flipped to the other side and
  // began again from "over".
  return angle < -0.5f * kPi ? angle + 2.0f * kPi : angle;
}

RiseController::TrunkPose RiseController::RolledTrunk(const BodyReading& r, float angle, float twist) const {
  const TrunkPose measured = MeasuredTrunk(r);
  const glm::quat pelvis = measured.pelvisRotation;
  const BoneBox& box = def_.skeleton.joints[rig_.pelvis].box;
  // On the back the trunk turns over the back edge of the roll side, past the
  // side over its front edge.
  const float frontOrBack = RollAngle(pelvis) < 0.5f * kPi ? -1.0f : 1.0f;
  const glm::vec3 pivot = measured.pelvis + pelvis * (box.center + glm::vec3(rollSign_ * box.halfExtents.x, 0.0f,
                                                                             frontOrBack * box.halfExtents.z));
  const glm::quat turn = glm::angleAxis(rollSign_ * angle, pelvis * kUp);
  TrunkPose rolled;
  rolled.pelvis = pivot + turn * (measured.pelvis - pivot);
  rolled.pelvisRotation = glm::normalize(turn * pelvis);
  rolled.chestRotation = glm::normalize(rolled.pelvisRotation * glm::angleAxis(rollSign_ * twist, kUp));
  return rolled;
}

RiseController::Move RiseController::PlanRoll(const BodyReading& r) {
  const glm::quat chest = r.jointRotations[rig_.chest];
  const glm::quat pelvis = r.jointRotations[rig_.pelvis];
  // Crouched on both feet with the CoM over them: Phase 2 directly.
  if (OnItsFeet(r)) return PlanRise(r);
  // From rest (the start, or after a fall) a roll starts afresh.
  if (phase_ == RisePhase::kSettle) rollSign_ = 0.0f, rollStage_ = RollStage::kNone, rollMoves_ = 0, placeTries_ = 0, hadPushOff_ = false;
  // Face down already: Phase 0 goes straight to placing hands and feet, but
  // an arm lying overhead first comes out round the side as at a roll's end.
  // Swung from overhead to its spot under the shoulder it pressed its bent
  // elbow into the ground, the hand stayed 20 cm up, and the push on the
  // other hand tipped the body over. In the 51 failed stress runs of seeds
  // 1-150, 27 of 81 pushes started with a hand up, now 12; seeds 1-300 and
  // 301-600 stood 108 and 96, now 116 and 100.
  if (rollSign_ == 0.0f && FaceDown(r)) {
    if (rollStage_ == RollStage::kNone || rollStage_ == RollStage::kArmOut) {
      rollStage_ = rollStage_ == RollStage::kNone ? RollStage::kArmOut : RollStage::kArmTurn;
      if (std::optional<Move> armOut = PlanArmOut(r, rollStage_)) return *armOut;
    }
    return PlanPlace(r);
  }
  if (rollSign_ == 0.0f) {
    // Roll over the side that is already down. Flat on the back and across a
    // slope of kDownhillRollSlope or more it rolls downhill; otherwise the
    // seed picks. (Picked by the seed on a slope, half the rolls went uphill:
    // over 1000 stress runs, 147 tries ended in a roll that could not get
    // over, now 95.)
    const glm::vec3 left = chest * glm::vec3(1, 0, 0);
    const float leftDown = -glm::dot(left, ground_.normal);
    // The ground normal's horizontal part points downhill; its length is the slope's sine.
    const glm::vec3 downhill = Horizontal(ground_.normal);
    const bool sloped = glm::length(downhill) >= std::sin(kDownhillRollSlope);
    const float across = sloped ? glm::dot(left, glm::normalize(downhill)) : 0.0f;
    if (std::fabs(leftDown) > 0.3f) {
      rollSign_ = leftDown > 0.0f ? 1.0f : -1.0f;
    } else if (std::fabs(across) > kAcrossSlope) {
      rollSign_ = across > 0.0f ? 1.0f : -1.0f;
    } else {
      rollSign_ = (rng_() & 1u) ? 1.0f : -1.0f;
    }
  }
  // A body that has turned well past its back the other way (a slope or its
  // own limbs rolled it there) rolls on over that side. Measured the planned
  // way it looked as if it had not pushed off yet, and the push went on
  // against it until the roll's moves ran out. (In 126 failed stress runs
  // push offs were 94 of the falls; this, 78; with the re-tuck below, 6.)
  if (std::max(RollAngle(pelvis), RollAngle(chest)) < -kPushedRoll) rollSign_ = -rollSign_;
  const float pelvisRoll = RollAngle(pelvis), chestRoll = RollAngle(chest);
  const bool prone = std::min(pelvisRoll, chestRoll) > kProneRoll;
  // Lying on the front with the legs straightened: an arm left overhead comes
  // out to the side, then the prone path takes over.
  for (const RollStage from : {RollStage::kLie, RollStage::kArmOut}) {
    if (rollStage_ != from || !prone) continue;
    rollStage_ = from == RollStage::kLie ? RollStage::kArmOut : RollStage::kArmTurn;
    if (std::optional<Move> armOut = PlanArmOut(r, rollStage_)) return *armOut;
  }
  if (rollStage_ == RollStage::kArmTurn && prone) return PlanPlace(r);

  const Limb nearArm = rollSign_ > 0.0f ? Limb::kHandLeft : Limb::kHandRight;
  const Limb farArm = OtherHand(nearArm);
  const Limb nearLeg = rollSign_ > 0.0f ? Limb::kFootLeft : Limb::kFootRight;
  const Limb farLeg = rollSign_ > 0.0f ? Limb::kFootRight : Limb::kFootLeft;

  // Each move is chosen by how far the trunk has turned, so one that does not
  // get the body as far as planned is followed by the one that fits where it is.
  RollStage stage = RollStage::kOver;
  if (prone || chestRoll > kChestOverRoll) stage = RollStage::kLie;
  // The push needs the far foot down near the buttock, the knee up: a leg
  // left straight (a roll that fell back, or a custom start) only slid its
  // foot, and the push went on until the roll's moves ran out.
  const int far = static_cast<int>(farLeg);
  const bool farFootSet = Clearance(r, farLeg) < kTuckedClearance &&
                          glm::length(r.jointPositions[rig_.end[far]] - r.jointPositions[rig_.upper[far]]) < kTuckedLeg * legReach_;
  const bool firstMove = rollStage_ == RollStage::kNone;
  // The push off swings the near arm overhead while the trunk turns: an arm
  // left at the side by the moves before (an arm turn after a fall, say) swung
  // 220 deg in its joints with the trunk and whipped the hand to 12.3 m/s
  // (stress seed 5600). The tuck brings it up first, with the trunk at rest
  // (after a tuck or a push off it is up or on its way).
  const bool armUp = rollStage_ == RollStage::kTuck || rollStage_ == RollStage::kPush ||
                     SwingToAngles(r, nearArm, kNearArmOverhead).from.x > kOverheadArm;
  if (pelvisRoll < kPushedRoll) stage = firstMove || !farFootSet || !armUp ? RollStage::kTuck : RollStage::kPush;
  const bool pushedOff = pelvisRoll > kLiftOffRoll && !r.touching[far];
  if (stage == RollStage::kPush && pushedOff) stage = RollStage::kOver;
  const RollStage previous = rollStage_;
  rollStage_ = stage;

  heading_ = HeadingForward(r);
  Move move;
  move.phase = RisePhase::kRoll;
  move.from = MeasuredTrunk(r);
  auto set = [&](Limb limb, const LimbMove& m) { move.limbs[static_cast<int>(limb)] = m; };
  auto swing = [&](Limb limb, const std::array<float, 5>& anglesDeg) {
    LimbMove m = SwingToAngles(r, limb, anglesDeg);
    m.lift = static_cast<float>(spec_.style.stepHeightM);
    return m;
  };
  // The arm on the roll side goes overhead so the body rolls over the
  // shoulder instead of onto the arm. (From the back it was kept along the
  // side, a log roll, while the arm-out move dragged an overhead hand 50-75 cm;
  // since that move ends with the arm straight, alongside stood fewer:
  // bench/prone_variants-style harness, 48 supine at 30 s, 36 against 45.)
  set(nearArm, SwingToAngles(r, nearArm, kNearArmOverhead));
  // Where the far arm comes down in the over and the lie.
  const std::array<float, 5>& farArmDown = hadPushOff_ ? kFarArmBehind : kFarArmAlongside;
  LimbMove nearAlong = SwingToAngles(r, nearLeg, kNearLegAlong);
  if (glm::length(nearAlong.to - nearAlong.from) * legReach_ > kBentLegSwing) nearAlong.lift = kBentLegLift;
  set(nearLeg, nearAlong);
  // The far arm's angles in each move, the chest's lead, the turn at which the
  // lie follows and the over's pace were set by a sweep over bench/prone_variants'
  // 24 supine and 24 side_left starts, scored by how far hands and feet slid
  // past the clip's 5 cm bar (with kNearArmOverhead and kNearLegAloft): none of
  // the 48 passed every bar before, 17 supine and 9 side_left (side_right 9) after.
  switch (stage) {
    case RollStage::kTuck: {
      // The far knee comes up and its foot is set flat beside the buttock and
      // out to the side, where pushing on it lifts that hip up and over; the
      // near arm goes overhead now, before the body turns onto it. (Sent only
      // to point at the sky here and overhead in the push off, 12 supine
      // starts slid the near foot 25-27 cm as the pelvis turned over it, the
      // near hand 19-22 cm as it landed overhead; now 18-19 and 17.)
      move.name = "tuck";
      move.duration = 0.6;
      move.to = move.from;
      const glm::vec3 hip = r.jointPositions[rig_.upper[static_cast<int>(farLeg)]];
      const glm::vec3 farSide = SafeNormalize(Horizontal(pelvis * glm::vec3(-rollSign_, 0.0f, 0.0f)), glm::vec3(0));
      const glm::vec3 toe = Project(ground_, hip - heading_ * (0.5f * legReach_) + farSide * (0.3f * legReach_));
      LimbMove foot = HoldLimb(r, farLeg, false);
      foot.toRotation = FootRotation(-heading_, 0.0f);
      foot.to = AnkleForToe(toe, foot.toRotation);
      // Drawn up from lying on its heel, the foot turns its sole down on the
      // way, so the heel sweeps well below the ankle: twice a step's lift.
      foot.lift = 2.0f * static_cast<float>(spec_.style.stepHeightM);
      set(farLeg, foot);
      set(farArm, SwingToAngles(r, farArm, {35, 8, 10, 0, 0}));
      break;
    }
    case RollStage::kPush:
      // The planted far foot holds its place while the trunk's goal turns on
      // over the near edge of the back: the leg's servos push the hip over.
      move.name = "push off";
      move.duration = 0.8;
      move.to = RolledTrunk(r, std::min(kPushOffRoll - pelvisRoll, kMaxPushOffTurn), 0.0f);
      move.rolledTo = kPushedRoll;
      {
        // Held where it is, a tucked foot left hovering (the pelvis half
        // turned, say) stayed up and the push went into the air.
        LimbMove foot = HoldLimb(r, farLeg, true);
        foot.to -= ground_.normal * Clearance(r, farLeg);
        set(farLeg, foot);
      }
      // The far arm, part way up since the tuck, swings on over the head and out.
      set(farArm, SwingToAngles(r, farArm, {150, 50, 10, 0, 0}));
      hadPushOff_ = true;
      break;
    case RollStage::kOver: {
      // Past the side: the chest leads over onto the front, the top arm comes
      // down alongside (brought down beside the head, flexion 45, abduction
      // 45, elbow 90 deg, its hand slid 14-16 cm as the chest came down onto
      // the front: 12 of 12 side_left starts; alongside, 4 slid 5-6 cm). A foot
      // still planted from the push holds the pelvis from falling back, so the
      // chest can lead by the spine's full twist. Without it the chest leads at
      // least 30 deg and at least as far as takes it kOverLead past
      // kChestOverRoll, where the lie follows: led by 30 deg alone from a pelvis
      // on its side (90 deg), its goal fell short of the lie's, and
      // side starts repeated "over" 7 times (5 s) while it crept there; in
      // stress 300 (seeds 1-300) some rolls stalled so until their moves ran
      // out. With the lead, stress 300 stood 81 -> 102, side_left 48 stood 0.3 s
      // sooner (their slides, already over the bar, 6.4 -> 7.6 cm on average).
      move.name = "over";
      move.duration = 1.26;
      const bool pushing = planted_[static_cast<int>(farLeg)];
      const float lead = std::clamp(kChestOverRoll + kOverLead - pelvisRoll, glm::radians(30.0f), glm::radians(65.0f));
      move.to = RolledTrunk(r, 0.0f, pushing ? glm::radians(35.0f) : lead);
      set(farArm, swing(farArm, farArmDown));
      if (pushing) {
        set(farLeg, HoldLimb(r, farLeg, true));
      } else {
        LimbMove topLeg = SwingToAngles(r, farLeg, {40, -2, 60, -20, 0});
        topLeg.lift = kTopLegLift * legReach_;
        set(farLeg, topLeg);
      }
      // From a side the near leg lies under the body from the start: it
      // straightens under the turning pelvis with a lift (held to its angles
      // alone its ankle's goal went 5-8 cm into the ground, and the foot was
      // pushed along it), the foot square to the shin (kNearLegUnder). After a
      // push off it is in the air and stays there.
      // An over again after a lie (the pelvis did not follow the chest onto the
      // front) leaves the near leg as the lie laid it, thigh down and shin up:
      // swung back to kNearLegAloft under a body already on its front, its foot
      // came down and the turning pelvis dragged it 26 cm (samples/custom.json).
      set(nearLeg, previous == RollStage::kLie ? SwingToAngles(r, nearLeg, kLieLeg)
                                               : swing(nearLeg, hadPushOff_ ? kNearLegAloft : kNearLegUnder));
      break;
    }
    case RollStage::kLie:
    case RollStage::kArmOut:
    case RollStage::kArmTurn:
    case RollStage::kNone:
      // The hips straighten and the spine untwists: straightening the top leg
      // turns the pelvis after the chest onto the front, as a body lying prone.
      // The knees bend, feet up: straightened along the ground, the legs
      // dragged their toes 10-12 cm (27 feet in 36 supine starts; the place swings
      // the feet down to their spots next). The arm overhead swings out along
      // the ground, nearer to where the hands are placed next. The far arm
      // lies alongside: bent under the chest (flexion 20, abduction 20,
      // elbow 60 deg) its hand propped that side 28 deg up, so the near arm
      // out at the side pointed into the ground; 12 supine / 12 side_left
      // starts stood 0 / 0 of 12 that way, 12 / 12 alongside.
      move.name = "lie";
      move.duration = 0.6;
      move.to = RolledTrunk(r, 0.0f, 0.0f);
      set(farArm, swing(farArm, farArmDown));
      set(nearArm, swing(nearArm, {170, 35, 10, 0, 0}));
      set(nearLeg, SwingToAngles(r, nearLeg, kLieLeg));
      set(farLeg, SwingToAngles(r, farLeg, kLieLeg));
      break;
  }
  return move;
}

void RiseController::LetGoSkiddingFeet(const BodyReading& r) {
  for (int i = 2; i < 4; ++i) {
    const Limb foot = static_cast<Limb>(i);
    // Down on the ground as the clip check counts a contact.
    if (!planted_[i] || Clearance(r, foot) > static_cast<float>(QualityOptions{}.contactHeight)) {
      downAt_[i].reset();
      continue;
    }
    const glm::vec3 at = Project(ground_, r.jointPositions[rig_.end[i]]);
    if (!downAt_[i]) downAt_[i] = at;
    if (glm::length(at - *downAt_[i]) <= kSkidLimit) continue;
    move_.limbs[i] = LiftOff(r, foot);
    planted_[i] = false;
    downAt_[i].reset();
  }
}

std::optional<RiseController::Move> RiseController::PlanArmOut(const BodyReading& r, RollStage stage, bool raisedOnly) const {
  // The arm the body rolled over lies overhead. Swung from there straight to
  // beside the chest it sweeps through the ground, and ended folded under the
  // shoulder with the elbow down and the hand up: the shoulder rested on it,
  // the trunk stayed tilted 30 deg, and that hand never reached the ground.
  // Swung in the shoulder's two angles from overhead to out at the side and
  // angled toward the hips (flexion -55, abduction 80), it passed through
  // the directions in front of the chest, into the ground, and dragged the
  // hand 41-47 cm (12 supine starts). Lying face down, the arm's way out that
  // stays above the shoulder's height is round the side: first abducted to
  // 90 deg (out to the side, the hand rising to the shoulder's height as it
  // goes), where flexion only turns the arm about itself, then turned there
  // to the flexion of an arm out to the side and raised behind (the
  // directions the place then swings down from).
  const bool turn = stage == RollStage::kArmTurn;
  Move move;
  move.name = turn ? "arm turn" : "arm out";
  move.phase = RisePhase::kRoll;
  move.duration = 0.8;
  move.from = move.to = MeasuredTrunk(r);
  bool any = false;
  for (int i = 0; i < kLimbCount; ++i) {
    const Limb limb = static_cast<Limb>(i);
    move.limbs[i] = HoldLimb(r, limb, false);
    if (!IsArm(limb)) continue;
    const std::array<float, 5> outToSide{170, 90, 0, 0, 0}, turnedThere{-55, 90, 0, 0, 0};
    const LimbMove out = SwingToAngles(r, limb, turn ? turnedThere : outToSide);
    const bool needed = raisedOnly ? !r.touching[i]
                        : turn     ? out.from.y > kArmOutAbduction && out.from.x > 0.0f
                                   : out.from.x > kOverheadArm;
    if (needed) move.limbs[i] = out, any = true;
  }
  if (!any) return std::nullopt;
  return move;
}

}  // namespace rise
