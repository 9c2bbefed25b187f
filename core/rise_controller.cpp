// SPDX-License-Identifier: MIT
// The rise controller's state machine: waiting for rest, planning the next move
// from the measured body, pacing it by the tracking error, falls and retries,
// and the control step that hands the servos their pose.
#include "core/rise_controller_detail.h"
#include "base/assert.h"

#include <utility>

namespace rise {

using namespace rise_controller_detail;

namespace {

// A fall is retried this many times; after the last the body is let come to rest.
constexpr int kMaxRetries = 4;

// Rest: the fallen body has stopped (the paper waits for this before rising).
constexpr float kRestSpeed = 0.08f;  // m/s
constexpr float kRestSpin = 0.4f;    // rad/s

// A clip that ends after the last fall ends on a body at rest by this speed: at
// kRestSpeed, one creeping down a 20 deg slope at 3 cm/s counted as at rest and
// the clip's last frames slid 1 mm each.
constexpr float kFinalRestSpeed = 0.02f;  // m/s

// Standing still long enough to end the clip (the checker looks at the last 0.5 s).
constexpr double kStandHold = 1.2;  // s

// A limb a put-down leaves in the air this many times in a row ends the try
// like a fall (stress seed 105: a foot hung 0.3 m up for 25 s, put down
// again and again where its hip could not take it).
constexpr int kMaxPutDowns = 4;

// A push or a crawl counts as fallen once it has borne on one hand or foot, or
// none, this long (Fallen). The push starts with the place's feet often still
// in the air, on the two hands alone, and a hand at rest on the ground drops
// out of contact for a step or two: 130 of the 287 push falls of 197 stress
// runs were called within 0.1 s of the push's start, the body lying still.
// Stress 3x500 (seeds 5001-6000, 9001-9500), the push: tries that ended in it
// 925 -> 529, stood 965 -> 974, stood at the first try 645 -> 673 (0.25 s:
// 965 stood, the falls it spared only came later); the crawl as well: tries
// that ended in the crawl 563 -> 478, stood 974 -> 987 (up to 10 deg 798 ->
// 813), at the first try 673 -> 682.
constexpr double kUnsupportedHold = 0.1;  // s

// How many hands and feet touch the ground.
int Bearing(const BodyReading& r) { return static_cast<int>(std::count(r.touching.begin(), r.touching.end(), true)); }

// Planted hands' wrists go soft so the palm lies flat and takes load at its heel.
constexpr float kPlantedWristGain = 0.15f;

// The fastest pace of the moves that balance the body on its hands and feet
// or its feet (push, crawl, rise, stand): the paper's quasi-static balance.
// Faster, the CoM overran the support: prone starts at speed 3 stood 29 of 72
// (2: 66), capped here 72 of 72 (69 pass every bar; uncapped 1.5: 72, 70).
// The roll and the placing of hands and feet keep the style's full pace.
constexpr double kMaxBalancedPace = 1.5;
// The crawl goes no slower than the pace its steps were tuned at, whatever
// the style: a slower crawl stays longer on three limbs and slid. Prone
// starts (bench/prone_variants) passing every bar: speed 0.5, 60 starts
// 35 -> 45; the tired style (0.8, 0.6), 144 starts 104 -> 121 (stood 138 ->
// 144); stress seeds 5001-5500 and 9001-9500 stood 399 -> 438 of 1000. At the
// default pace nothing changes. Speeding every crawl by 1.3 instead stood
// 428 of those 1000 but cost prone starts at the default pace: 117 -> 113 of
// 120 passed every bar.
constexpr double kMinCrawlPace = 1.0;
// The roll likewise: once past its side a body falls onto its front as fast as gravity takes it,
// whatever the style, while a slower roll swings the arms more slowly. At the tired style's pace
// (0.61) the far arm, swung down from overhead, was still out in front of the chest as it came
// down onto the front, and its hand was dragged 53-58 cm (the library's tired back clips).
// bench/prone_variants, tired (speed 0.8, tiredness 0.6), 48 each: supine 0 -> 34 pass every bar,
// side_left / side_right 46 / 44 -> 47 / 48; prone 144 stay 144. At pace 1 or more nothing changes.
constexpr double kMinRollPace = 1.0;
constexpr float kMaxLimbSpeed = 1.5f;  // m/s, average along a swing

// The walk-in's lengths marked "at kTunedHeight" were tuned on a body this
// tall; a body's own are these scaled by its height (WalkInLengths).
constexpr float kTunedHeight = 1.75f;  // m

// A roll takes 6 moves (tuck, push off, over, lie, arm out, arm turn) and a
// few more when one leaves the body short.
constexpr int kMaxRollMoves = 13;

// Places of the hands and feet before the push goes ahead with a hand still up
// or astray: farther than kPlaceAstray along the ground from its spot. (Stress,
// 1000 runs each, seeds 5001-6000 / 9001-10000: stood 377 / 364 without the
// astray test; with it at 0.18 m 392 / -, 0.12 m 406 / 395, 0.08 m 417 / 399,
// 0.05 m 417 / -; the tries that ended in the crawl fell most. Re-placed only
// face down: 419 / - as committed.)
constexpr int kMaxPlaceTries = 3;
constexpr float kPlaceAstray = 0.08f;  // m
// A place whose CoM moves faster than this, its pelvis this far from its
// goal, is tumbling: a fall (Fallen).
constexpr float kPlaceTumbleSpeed = 1.5f;  // m/s
constexpr float kPlaceTumbleLag = 0.25f;   // m

// A rising or standing body whose pelvis is lower than this, of its standing
// height, is down.
constexpr float kDownPelvis = 0.25f;

// A rising or standing body whose CoM is this far past the edge of its feet
// (along the ground) and moving faster than this is falling, even with the
// pelvis still up: no ankle or hip strategy brings it back from there.
constexpr float kOffFeet = 0.3f;        // m
constexpr float kOffFeetSpeed = 0.8f;   // m/s

// A rise that falls forward off its feet with the pelvis still up puts its
// hands down (PlanCatch) at most this many times a try before the tip counts
// as a fall.
constexpr int kMaxCatches = 2;

}  // namespace

const char* RisePhaseName(RisePhase phase) {
  switch (phase) {
    case RisePhase::kSettle: return "settle";
    case RisePhase::kRoll: return "roll";
    case RisePhase::kPlace: return "place";
    case RisePhase::kPush: return "push";
    case RisePhase::kCrawl: return "crawl";
    case RisePhase::kRise: return "rise";
    case RisePhase::kStand: return "stand";
  }
  return "?";
}

RiseController::RiseController(const BipedDef& def, const RiseSpec& spec, bool tracing)
    : def_(def), spec_(spec), ground_(GroundPlane(spec.terrain.slopeDeg)), rng_(static_cast<uint32_t>(spec.seed)),
      tracing_(tracing) {
  rig_ = BodyRig::FromDef(def);
  for (const BoneDef& bone : def.bones) totalMass_ += bone.massKg;
  const Skeleton& sk = def.skeleton;
  armReach_ = glm::length(sk.joints[rig_.lower[0]].restOffset) + glm::length(sk.joints[rig_.end[0]].restOffset);
  legReach_ = glm::length(sk.joints[rig_.lower[2]].restOffset) + glm::length(sk.joints[rig_.end[2]].restOffset);
  standPelvisHeight_ = sk.BindPositions()[rig_.pelvis].y;
  standComHeight_ = def.BindCenterOfMass().y;
  // How far the feet walk in, and in what steps, scales with the body's
  // height: unscaled, none of 9 prone starts of 1.40-1.50 m stood, scaled 6
  // did. Of 45 prone starts of 1.40-2.10 m 19 -> 26 stood and 13 -> 18 passed
  // every bar, of 30 supine starts 12 -> 20 stood; 40 prone starts of
  // 1.60-1.85 m: 36 -> 32 stood, 22 -> 23 passed. (Then also scaling, both
  // ways, the stance width, the lead between the feet, the shortest step and
  // the CoM's margin behind the hands: 27 / 16, 21 and 34 / 19.)
  const float scale = static_cast<float>(spec.character.heightM) / kTunedHeight;
  // The margins, reaches and stance lengths the phases plan with ("m, Scaled")
  // shrink with a shorter body, but do not grow with a taller one. Unscaled,
  // bodies under 1.45 m stood 24 of 43 times on slopes under 5 deg (the other
  // heights 94-100 %), most tries falling in the rise out of a squat set up
  // for longer feet; scaled, 40 of 43. Stress seeds 5001-6000 and 9001-9500:
  // 987 -> 1030 of 1500 stood, up to 10 deg 813 -> 850 of 973, at the first
  // try 682 -> 733. Grown with a taller body as well: 1012, up to 10 deg 852.
  lengthScale_ = std::min(scale, 1.0f);
  walkIn_ = {kFootWalkDistance * scale, kPikeStart * scale, kFootStep * scale, Scaled(kSitBackBehindSoles)};
  shoulderHalfWidth_ = std::fabs(sk.BindPositions()[rig_.upper[0]].x);
  // The crawl keeps the hips high (a pike), so knees stay off the ground.
  crawlComHeight_ = 0.5f * standComHeight_;
  const BoneBox& foot = sk.joints[rig_.end[2]].box;
  toeLocal_ = glm::vec3(0.0f, foot.center.y - foot.halfExtents.y, foot.center.z + foot.halfExtents.z);
  subtree_.assign(sk.joints.size(), {});
  for (int j = sk.JointCount() - 1; j >= 0; --j) {
    subtree_[j].push_back(j);
    if (sk.joints[j].parent >= 0) {
      std::vector<int>& parent = subtree_[sk.joints[j].parent];
      parent.insert(parent.end(), subtree_[j].begin(), subtree_[j].end());
    }
  }
  trace_.phase = phase_;
}

// ---------------------------------------------------------------------------
// Planning

void RiseController::StartMove(Move move) {
  double pace = StylePace(spec_.style);
  if (move.phase == RisePhase::kCrawl) pace = std::max(pace, kMinCrawlPace);
  if (move.phase == RisePhase::kRoll) pace = std::max(pace, kMinRollPace);
  if (OnHandsAndFeet(move.phase) || move.phase == RisePhase::kRise || move.phase == RisePhase::kStand) {
    pace = std::min(pace, kMaxBalancedPace);
  }
  move.duration /= pace;
  // However fast the style, a hand or foot crossing the world goes no faster
  // on average than kMaxLimbSpeed (the eased path peaks at about twice that):
  // a quick style on a long step otherwise whipped limbs past 10 m/s.
  for (int i = 0; i < kLimbCount; ++i) {
    const LimbMove& limb = move.limbs[i];
    if (limb.mode == LimbMode::kToePivot) continue;
    // (For a limb carried by the trunk, its path relative to the trunk; for one
    // turned in its joints, the arc its end sweeps at full reach.)
    const float path = limb.mode == LimbMode::kJoint
                           ? glm::length(limb.to - limb.from) * (IsArm(static_cast<Limb>(i)) ? armReach_ : legReach_)
                           : glm::length(limb.to - limb.from) + 2.0f * limb.lift;
    move.duration = std::max(move.duration, static_cast<double>(path / (kMaxLimbSpeed * std::max(limb.span, 0.1f))));
  }
  if (move.phase == RisePhase::kRoll) ++rollMoves_;
  move_ = std::move(move);
  phase_ = move_.phase;
  hasMove_ = true;
  progress_ = 0.0f;
  pelvisGoal_ = move_.from.pelvis;
  for (int i = 0; i < kLimbCount; ++i) planted_[i] = move_.limbs[i].planted;
  downAt_ = {};
}

bool RiseController::OnItsFeet(const BodyReading& r) {
  if (!r.touching[2] || !r.touching[3] || Height(ground_, r.jointPositions[rig_.pelvis]) < 0.3f * standPelvisHeight_) {
    return false;
  }
  heading_ = SafeNormalize(Horizontal(r.jointRotations[rig_.pelvis] * glm::vec3(0, 0, 1)), heading_);
  return FeetRegion(r).SignedDistance(Ground(r.com)) < -0.02f;
}

const TraceSample& RiseController::LastTrace() const {
  RISE_ASSERT(tracing_);
  return trace_;
}

bool RiseController::StandingFor(double time, double seconds) const {
  return phase_ == RisePhase::kStand && standTime_ >= 0.0 && time - standTime_ >= seconds;
}

bool RiseController::Fallen(const BodyReading& r) const {
  const float pelvisHeight = Height(ground_, r.jointPositions[rig_.pelvis]);
  // Built only when the cheap tests have not decided: this runs every step.
  auto comToFeet = [&] { return FeetRegion(r).SignedDistance(Ground(r.com)); };
  // A roll that has not got the body onto its front in this many moves is a
  // failed try like a fall (a slope can roll it back onto its back each time).
  if (phase_ == RisePhase::kRoll) return rollMoves_ > kMaxRollMoves;
  const int bearing = Bearing(r);
  // A push left on one hand or foot, or none, is not pushing up but sliding
  // or tumbling away, or resting on its knees: either way a failed try.
  // Pushed on, a body sliding down a 10 deg slope on one hand at 1.6-1.9 m/s
  // whipped that hand to 11.2 m/s (stress seed 5821). Counted as falls only
  // when the CoM moved faster than 0.5 m/s, pushes begun on the hands and
  // knees that lifted a hand went on from there: stress seeds 5001-5500 /
  // 5501-6000 / 9001-9500 stood 240 / 236 / 207, now 243 / 247 / 216.
  // (Update times how long it has been so: kUnsupportedHold.)
  const bool unsupported = unsupportedSince_ >= 0.0 && r.time - unsupportedSince_ >= kUnsupportedHold;
  if (phase_ == RisePhase::kPush) return unsupported;
  // Placing, the body lies on its front and keeps up with its goal. Fast
  // (its CoM over 1.5 m/s) and left behind by it, it is tumbling, and a
  // place driven on swings its limbs round with it: rolling down a 13.5 deg
  // slope at 2 m/s, its pelvis 0.4-1.5 m from its goal, a foot was whipped to
  // 10.2 m/s (stress seed 5789; 5910 likewise on 13.9 deg). (At 1 m/s, or by
  // speed alone, places on a slippery 11.9 deg slope counted as falls that
  // went on to stand: stress seed 5618.) A catch is a place too, but of a
  // body that is falling forward onto its hands.
  if (phase_ == RisePhase::kPlace) {
    return move_.name != "catch" && glm::length(r.comVelocity) > kPlaceTumbleSpeed &&
           glm::length(pelvisGoal_ - r.jointPositions[rig_.pelvis]) > kPlaceTumbleLag;
  }
  if (phase_ == RisePhase::kCrawl) {
    if (putDowns_ > kMaxPutDowns) return true;
    // On one hand or foot, or none, the body is not crawling but tipping over:
    // left to the crawl's servos, a body toppling over a hand down a 13.5 deg
    // slope swung a foot up to 1.4 m and, re-planned there, back down at
    // 12.7 m/s (stress seed 5189; 5.1 m/s now). Counted as a fall it goes limp as the
    // settle holds it. Stress, seeds 5001-5500 / 5501-6000 / 9001-9500: stood
    // 204 / 215 / 193 before, 206 / 217 / 193 after; runs over the 10 m/s
    // bound 4 / 3 / 0 before, 1 / 0 / 0 after (the one left a dropped ragdoll).
    // Like the push's, once it has lasted kUnsupportedHold.
    if (unsupported) return true;
    // Down on the ground again (sitting or lying) with the hands and feet no longer bearing.
    // (Squatting on both feet with the CoM over them is not down: it is where the crawl ends.)
    if (pelvisHeight >= 0.22f * standPelvisHeight_ || bearing >= 3) return false;
    return !(r.touching[2] && r.touching[3] && comToFeet() < 0.0f);
  }
  if (phase_ != RisePhase::kRise && phase_ != RisePhase::kStand) return false;
  if (pelvisHeight < kDownPelvis * standPelvisHeight_) return true;
  // Tipping off the feet: driven on toward the rise's goal, the servos swung
  // the arms round with the falling body until the pelvis came down (stress
  // seed 9370: a 2.04 m body toppled sideways out of its rise, the CoM 0.3 m
  // past its feet at 1 m/s, and a hand reached 12.65 m/s before the fall
  // counted). Stress seeds 5001-6000 and 9001-9500 stood 1030 times either way.
  if (glm::length(AlongPlane(ground_, r.comVelocity)) > kOffFeetSpeed && comToFeet() > kOffFeet) return true;
  // A chest folded over the knees is how a rise from a squat starts (and what
  // OnItsFeet accepts): down only with the CoM off the feet as well.
  const glm::vec3 up = r.jointRotations[rig_.chest] * kUp;
  return glm::dot(up, kUp) < std::cos(glm::radians(70.0f)) && comToFeet() > 0.05f;
}

void RiseController::StartOver() {
  // Down again: wait for rest and start over, kMaxRetries times.
  givingUp_ = retries_ == kMaxRetries;
  retries_ = std::min(retries_ + 1, kMaxRetries);
  hasMove_ = false;
  phase_ = RisePhase::kSettle;
  restSince_ = -1.0;
  standTime_ = -1.0;
  catches_ = 0;
}

void RiseController::PlanNext(const BodyReading& reading) {
  switch (phase_) {
    case RisePhase::kSettle:
    case RisePhase::kRoll: StartMove(PlanRoll(reading)); break;
    case RisePhase::kPlace: {
      // Caught on both hands: up onto hands and feet again, and the crawl
      // finishes from there; a catch that missed is a fall.
      if (move_.name == "catch") {
        if (reading.touching[0] && reading.touching[1]) StartMove(PlanPush(reading));
        else StartOver();
        break;
      }
      if (move_.name == "place" || move_.name == "place again") {
        // A place can end short of its spots: stalled on a trunk goal out of
        // reach, it ended with a hand out at the side of the shoulder, put
        // down there, and the push tipped the body over onto its seat (stress
        // seed 5084). Placed again from where the body now is, if it still
        // lies face down: a place from a body turned onto its side or back
        // swung a leg through the air at over 10 m/s (stress seed 90).
        bool astray = false;
        for (int i = 0; i < 2; ++i) {
          const LimbMove& hand = move_.limbs[i];
          astray = astray || (hand.mode == LimbMode::kWorld &&
                              glm::length(Horizontal(reading.jointPositions[rig_.end[i]] - hand.to)) > kPlaceAstray);
        }
        if (astray && FaceDown(reading) && ++placeTries_ < kMaxPlaceTries) {
          Move again = PlanPlace(reading);
          again.name = "place again";
          StartMove(again);
        } else {
          StartMove(PlanHandsDown(reading));
        }
        break;
      }
      // A hand the place left high (a swing that lagged, an arm held up by the
      // body) did not get down in "hands down": pushed up on one hand the body
      // tipped over sideways. It is placed again (stress seeds 1-300 and
      // 301-600 stood 116 and 100 without this, 118 and 101 with it), after
      // that arm has come out round the side as at a roll's end: placed again
      // from where it was, an arm folded in front of the face (elbow on the
      // ground, hand up) stayed folded through every place (stress seeds
      // 1-1000 stood 357 without the arm out, 383 with it).
      const bool handsDown = reading.touching[0] && reading.touching[1];
      if (!handsDown && ++placeTries_ < kMaxPlaceTries) {
        const std::optional<Move> armOut = PlanArmOut(reading, RollStage::kArmOut, true);
        if (armOut) rollStage_ = RollStage::kArmOut;
        StartMove(armOut ? *armOut : PlanPlace(reading));
      } else {
        StartMove(PlanPush(reading));
      }
      break;
    }
    case RisePhase::kPush:
    case RisePhase::kCrawl: StartMove(PlanCrawl(reading)); break;
    case RisePhase::kRise: StartMove(PlanStand(reading)); break;
    case RisePhase::kStand: StartMove(PlanStand(reading)); break;
  }
}

// ---------------------------------------------------------------------------
// The control step

bool RiseController::Still(const BodyReading& reading) {
  return reading.maxBodySpeed < kRestSpeed && reading.maxAngularSpeed < kRestSpin;
}

RiseController::WeightShare RiseController::HoldAsItLies(const BodyReading& reading, ServoTargets& out) const {
  out.local = LocalRotations(def_.skeleton, reading.jointRotations);
  out.gainScale.assign(def_.skeleton.joints.size(), 0.3f);
  return FeedForward(reading, reading.com, out.feedForward);
}

void RiseController::Update(const BodyReading& reading, ServoTargets& out) {
  RISE_ASSERT(static_cast<int>(reading.jointPositions.size()) == def_.skeleton.JointCount());
  const double dt = hasMove_ || phase_ != RisePhase::kSettle ? reading.time - lastTime_ : 0.0;
  lastTime_ = reading.time;
  if (OnHandsAndFeet(phase_) && Bearing(reading) <= 1) {
    if (unsupportedSince_ < 0.0) unsupportedSince_ = reading.time;
  } else {
    unsupportedSince_ = -1.0;
  }

  if (phase_ == RisePhase::kSettle && !hasMove_) {
    // Hold whatever pose the body fell into until it has come to rest.
    const bool still = Still(reading) && (!givingUp_ || reading.maxBodySpeed < kFinalRestSpeed);
    if (!still) restSince_ = -1.0;
    else if (restSince_ < 0.0) restSince_ = reading.time;
    // A body already balanced on its feet is not lying: it must not sag while it
    // waits for rest, so Phase 2 takes it at once.
    const bool rested = restSince_ >= 0.0 && reading.time - restSince_ >= kRestHold;
    if (givingUp_) {
      // Out of retries: the body is let come to rest, and the clip can end there.
      gaveUp_ = rested;
    } else if (rested || OnItsFeet(reading)) {
      PlanNext(reading);
    }
  } else if (Fallen(reading)) {
    // In the rise with the pelvis up, the fall is the folded body going off
    // its toes: while it still goes forward, the hands can catch it.
    const bool tipping = phase_ == RisePhase::kRise && catches_ < kMaxCatches &&
                         Height(ground_, reading.jointPositions[rig_.pelvis]) >= kDownPelvis * standPelvisHeight_ &&
                         glm::dot(reading.comVelocity, heading_) > 0.0f;
    if (tipping) {
      ++catches_;
      StartMove(PlanCatch(reading));
    } else {
      StartOver();
    }
  } else if (hasMove_) {
    // Quasi-static pace: progress slows while the pelvis lags its goal.
    // The lag behind the goal last handed to the servos, one step old: the
    // goal at this step's progress cost a second balance evaluation (its IK
    // solves) every step, 9.5 % of a prone clip's instructions, and the gate
    // works as well without it (prone 504 starts passed every bar 479 and 482
    // times, rolled 216 stood 170 and 165).
    const float lag = glm::length(pelvisGoal_ - reading.jointPositions[rig_.pelvis]);
    // A roll's trunk goal is only where the planted limbs push toward; how far
    // the body has come is its roll angle (Move::rolledTo), not this lag.
    const bool rolling = move_.phase == RisePhase::kRoll;
    const float gate = rolling ? 1.0f : std::clamp((kGateStop - lag) / (kGateStop - kGateError), 0.15f, 1.0f);
    progress_ = std::min(1.0f, progress_ + static_cast<float>(dt / move_.duration) * gate);
    trace_.trackingError = lag;
    if (lag < kGateStop) stalledSince_ = -1.0;
    else if (stalledSince_ < 0.0) stalledSince_ = reading.time;
    if (OnHandsAndFeet(move_.phase)) {
      glm::vec3 error = PoseCom(GoalAt(move_, progress_, reading, false)) - reading.com;
      error.y = 0.0f;
      crawlOffset_ += error * static_cast<float>(dt) * kCrawlComIntegral;
      if (glm::length(crawlOffset_) > Scaled(kMaxCrawlOffset)) crawlOffset_ *= Scaled(kMaxCrawlOffset) / glm::length(crawlOffset_);
    }
    if (move_.keepComOverFeet) {
      // The lean changes at most kLeanRate, so only that band is searched.
      const float step = kLeanRate * static_cast<float>(dt);
      balanceLean_ = BalanceLean(move_, progress_, reading, balanceLean_ - step, balanceLean_ + step);
      // Integral feedback on the measured CoM keeps the balance goal honest
      // when the model's masses or the servos' sag differ from the plan.
      glm::vec3 error = BalancePoint(reading) - reading.com;
      error.y = 0.0f;
      balanceOffset_ += error * static_cast<float>(dt) * 1.5f;
      const float limit = 0.05f;
      if (glm::length(balanceOffset_) > limit) balanceOffset_ *= limit / glm::length(balanceOffset_);
    }
    // Sitting back ends as soon as the CoM is over the feet: carried on, it
    // would keep going back past the heels.
    if (move_.name == "sit back" && FeetRegion(reading).SignedDistance(Ground(reading.com)) < -Scaled(kRiseMargin)) progress_ = 1.0f;
    // Heels down with a hand still on the ground ends once the soles are flat
    // with the CoM within kHeelsDownReach of them: the rise takes it the rest
    // of the way with the hands held. Carried on, the hands were unloaded
    // while still planted, rolled onto their fingers and dragged them 4-6 cm
    // (tired prone starts). (A body whose hands are already up finishes the
    // move: started early, drifting back at 0.2 m/s, stress seed 9188 sat down.)
    if (move_.name == "heels down" && progress_ > 0.5f && (reading.touching[0] || reading.touching[1]) &&
        SolesDown(reading) && FeetRegion(reading).SignedDistance(Ground(reading.com)) < Scaled(kHeelsDownReach)) {
      progress_ = 1.0f;
    }
    if (move_.landing >= 0 && reading.touching[move_.landing] &&
        Clearance(reading, static_cast<Limb>(move_.landing)) < kLandedClearance) {
      progress_ = 1.0f;
    }
    const bool stalled = stalledSince_ >= 0.0 && reading.time - stalledSince_ > kStallTime;
    // A move that turns the body over ends once it has, or once a foot
    // pushing it leaves the ground with the hip up: that push is spent, and
    // held on, the foot would be dragged.
    bool rolled = false;
    if (move_.rolledTo > 0.0f) {
      const float turned = RollAngle(reading.jointRotations[rig_.pelvis]);
      rolled = turned >= move_.rolledTo;
      for (int i = 2; i < 4; ++i) rolled = rolled || (planted_[i] && !reading.touching[i] && turned > kLiftOffRoll);
    }
    if (stalled || rolled) {
      // The body cannot follow this move: plan again from where it is.
      stalledSince_ = -1.0;
      // A rise that stalls in its squat is planned again from there: the
      // stand's goal is the full height, and from the squat its servos
      // launched the body off its feet (stress seed 5760: the CoM up at
      // 2.4 m/s, a hand whipped to 11.6 m/s).
      if (stalled && phase_ == RisePhase::kRise) {
        StartMove(PlanRise(reading));
      } else {
        PlanNext(reading);
      }
    } else if (progress_ >= 1.0f && (lag < kGateStop || rolling)) {
      if (phase_ == RisePhase::kStand) {
        finished_ = StandingFor(reading.time, kStandHold) && reading.maxBodySpeed < kRestSpeed;
        if (!finished_) PlanNext(reading);
      } else {
        PlanNext(reading);
      }
    }
  }

  if (hasMove_ && move_.name == "over") LetGoSkiddingFeet(reading);
  if (hasMove_ && (move_.name == "sit back" || move_.name == "heels down")) ReleaseLiftedHands(reading);
  if (hasMove_ && move_.phase == RisePhase::kRise) LetGoOverFeet(reading);
  // The pose to track.
  out.local.assign(def_.skeleton.joints.size(), glm::quat(1, 0, 0, 0));
  out.gainScale.assign(def_.skeleton.joints.size(), 1.0f);
  WeightShare shared;
  if (!hasMove_) {
    shared = HoldAsItLies(reading, out);
  } else {
    std::optional<BodyPose> solved;
    const PoseGoal goal = GoalAt(move_, progress_, reading, true, &solved);
    pelvisGoal_ = goal.pelvisPosition;
    const BodyPose pose = solved ? std::move(*solved) : SolveBodyPose(def_.skeleton, rig_, goal);
    out.local = LocalRotations(def_.skeleton, pose.worldRotations);
    // The plan's CoM is only needed for the virtual force on hands and feet.
    const glm::vec3 comGoal = OnHandsAndFeet(phase_) ? PoseCom(GoalAt(move_, progress_, reading, false)) : reading.com;
    shared = FeedForward(reading, comGoal, out.feedForward);
    for (int i = 0; i < 2; ++i) {
      if (planted_[i]) out.gainScale[rig_.end[i]] = kPlantedWristGain;
    }
    if (tracing_) {
      trace_.comGoal = PoseCom(pose);
      for (int i = 0; i < kLimbCount; ++i) trace_.limbTargets[i] = goal.limbs[i].target;
    }
  }

  if (!tracing_) return;
  trace_.time = reading.time;
  trace_.phase = phase_;
  trace_.move = hasMove_ ? move_.name : "settle";
  trace_.com = reading.com;
  trace_.comVelocity = reading.comVelocity;
  trace_.pressure = shared.pressure;
  trace_.load = shared.share;
  trace_.heading = heading_;
  // Zero while no side is chosen (after a fall, say), not the last roll's angles.
  trace_.rollSide = rollSign_;
  trace_.pelvisRoll = rollSign_ != 0.0f ? RollAngle(reading.jointRotations[rig_.pelvis]) : 0.0f;
  trace_.chestRoll = rollSign_ != 0.0f ? RollAngle(reading.jointRotations[rig_.chest]) : 0.0f;
  trace_.touching = reading.touching;
  trace_.planted = planted_;
  for (int i = 0; i < kLimbCount; ++i) {
    trace_.limbPositions[i] = reading.jointPositions[rig_.end[i]];
    trace_.clearance[i] = Clearance(reading, static_cast<Limb>(i));
  }
  trace_.support = SupportRegion(reading);
  trace_.feetDistance = FeetRegion(reading).SignedDistance(Ground(reading.com));
}

}  // namespace rise
