// SPDX-License-Identifier: MIT
// Phase 1, on hands and feet: the support triangle, the CoM shifted into it,
// the free limb stepped on a Bezier path, the feet walked in to the hands.
#include "core/rise_controller_detail.h"
#include "core/point_mass_plan.h"

namespace rise {

using namespace rise_controller_detail;

namespace {

// A foot farther than this across from its place in the crawl stance
// (kCrawlHalfStance) steps there first.
constexpr float kMaxStanceDrift = 0.15f;  // m, Scaled

// A hand that steps back toward the feet at the end of the crawl goes this far.
constexpr float kHandStepBack = 0.15f;  // m, Scaled
constexpr float kLandingReach = 0.1f;   // m below the ground a limb being put down aims

// However it goes, the crawl hands over to the rise after this many steps.
constexpr int kMaxCrawlSteps = 24;

// A limb lifts only with the CoM this far inside the other three's support;
// the shift before it aims kShiftMargin inside, and is tried this many times.
constexpr float kLiftMargin = 0.03f;  // m, Scaled
constexpr float kShiftMargin = 0.06f;  // m, Scaled
constexpr int kMaxShiftTries = 2;

// While a foot steps, the CoM stays this far behind the hands' line: over it
// the body pivots on its hands.
constexpr float kFootLiftHandLineMargin = 0.22f;  // m, Scaled

// ... and so far back that the shoulders, carried along with it, stay within
// kShoulderLead of that line (see FootLiftCom).
constexpr float kShoulderLead = 0.05f;  // m, Scaled

// CoM height in the squat the crawl ends in, of the standing CoM height. Measured with
// bench/prone_variants (prone 20 s, supine and sides 30 s): 0.45 stood 69 of 144 starts,
// 0.50 and 0.55 alike (151 and 149 of 288).
constexpr float kSquatComRatio = 0.55f;

// A squat hands over to the rise once the CoM is within this of the soles.
constexpr float kSitBackReach = 0.05f;  // m, Scaled
constexpr double kSteadyHold = 0.2;     // s a squat not yet steady holds still before it looks again (0.3: fewer pass every bar)
constexpr float kFlatSole = glm::radians(12.0f);  // a sole tilted less than this is flat

}  // namespace

float RiseController::HandsAhead(const BodyReading& r, Limb hand) const {
  // From the feet's toe edges (where feet on their toes press), along the heading.
  const glm::vec3 toes = 0.5f * (ContactPoint(r, Limb::kFootLeft) + ContactPoint(r, Limb::kFootRight));
  return glm::dot(ContactPoint(r, hand) - toes, heading_);
}

float RiseController::HandsAhead(const BodyReading& r) const {
  return 0.5f * (HandsAhead(r, Limb::kHandLeft) + HandsAhead(r, Limb::kHandRight));
}

float RiseController::StanceAcross(const BodyReading& r, Limb foot, const glm::vec3& point) const {
  const glm::vec3 left = glm::normalize(glm::cross(kUp, heading_));
  const glm::vec3 hands = 0.5f * (ContactPoint(r, Limb::kHandLeft) + ContactPoint(r, Limb::kHandRight));
  const float side = IsLeft(foot) ? 1.0f : -1.0f;
  return side * Scaled(kCrawlHalfStance) - glm::dot(point - hands, left);
}

std::vector<Limb> RiseController::StepCandidates(const BodyReading& r) const {
  // Phase 1 brings the feet in to the hands until the CoM can sit back over
  // them with the hands still down (bench/reach_probe: the hands within about
  // 0.4-0.5 m of the toes): the rear foot steps, then the other, and once in,
  // the rear one comes up beside the other. The hands stay where the push put
  // them: walking them back as well, as the paper's Phase 1 does, stood 3 of
  // 36 prone starts (bench/prone_variants) against 14 with the feet alone.
  // A step that ended short leaves its limb in the air: it goes down first.
  for (int i = 0; i < kLimbCount; ++i) {
    if (Clearance(r, static_cast<Limb>(i)) > kLandedClearance) return {static_cast<Limb>(i)};
  }
  // A heels-down that could not bring the CoM over the soles, the arms at full
  // reach to hands far ahead: the hand farther ahead steps back toward the
  // feet, as the paper's Phase 1 moves the free hand. (With the CoM held back
  // by the shoulders' lead, rolled starts, whose stance is longer, ended the
  // crawl with the hands ~0.7 m ahead of the ankles and repeated the heels-down
  // until the time ran out: 108 rolled starts stood 85 -> 54; with this 84.)
  if (move_.name == "heels down" && FeetRegion(r).SignedDistance(Ground(r.com)) >= Scaled(kSitBackReach)) {
    return {HandsAhead(r, Limb::kHandLeft) >= HandsAhead(r, Limb::kHandRight) ? Limb::kHandLeft : Limb::kHandRight};
  }
  // A foot far to the side of its place steps back across first: every step
  // corrects its own foot's width, but the walk-in steps only the rear foot,
  // and a body bent sideways as it came up, both feet off to one side of the
  // hands, walked its rear foot in and out until the time ran out while the
  // other stayed 0.7 m wide (stress seed 33).
  const float driftLeft = std::fabs(StanceAcross(r, Limb::kFootLeft, ContactPoint(r, Limb::kFootLeft)));
  const float driftRight = std::fabs(StanceAcross(r, Limb::kFootRight, ContactPoint(r, Limb::kFootRight)));
  if (std::max(driftLeft, driftRight) > Scaled(kMaxStanceDrift)) return {driftLeft >= driftRight ? Limb::kFootLeft : Limb::kFootRight};
  // By the ankles, as the step length measures them (toe edges can sit askew).
  const float stagger = glm::dot(r.jointPositions[rig_.end[2]] - r.jointPositions[rig_.end[3]], heading_);
  const Limb rear = stagger < 0.0f ? Limb::kFootLeft : Limb::kFootRight;
  const float handsAhead = HandsAhead(r);
  if (handsAhead <= walkIn_.handsAhead + Scaled(kMinFootStep) || feetIn_) {
    if (std::fabs(stagger) > Scaled(kMinFootStep)) return {rear};
    return {};
  }
  return {rear};
}

SupportPolygon RiseController::StanceWithout(const BodyReading& r, Limb lifted) const {
  std::vector<glm::vec2> points;
  for (int i = 0; i < kLimbCount; ++i) {
    if (i != static_cast<int>(lifted)) points.push_back(Ground(ContactPoint(r, static_cast<Limb>(i))));
  }
  return SupportPolygon::FromPoints(points);
}

float RiseController::CrawlComHeight(const BodyReading& r) const {
  // The hips rise from the bear stance's height into a pike as the feet walk in
  // under them.
  const float handsAhead = HandsAhead(r);
  const float in = std::clamp((walkIn_.pikeStart - handsAhead) / (walkIn_.pikeStart - walkIn_.handsAhead), 0.0f, 1.0f);
  return glm::mix(crawlComHeight_, kPikeComRatio * standComHeight_, in);
}

glm::vec3 RiseController::FootLiftCom(const BodyReading& r, Limb foot) const {
  // Where the CoM is inside both feet's lift triangles at once (hands and one
  // foot each): the triangle of the hands and the crossing of the diagonals
  // from each hand to the opposite foot. Held at its incentre, deepest inside,
  // either foot can lift in turn without the CoM crossing the body between
  // steps; and the spot comes from contacts that stay put, not from where the
  // measured CoM has crept to.
  const glm::vec2 hl = Ground(ContactPoint(r, Limb::kHandLeft)), hr = Ground(ContactPoint(r, Limb::kHandRight));
  const glm::vec2 fl = Ground(ContactPoint(r, Limb::kFootLeft)), fr = Ground(ContactPoint(r, Limb::kFootRight));
  const glm::vec2 d1 = fr - hl, d2 = fl - hr;
  const float cross = d1.x * d2.y - d1.y * d2.x;
  glm::vec2 deep = StanceWithout(r, foot).Centroid();
  if (std::fabs(cross) > 1e-4f) {
    const glm::vec2 w = hr - hl;
    const float t = (w.x * d2.y - w.y * d2.x) / cross;
    if (t > 0.0f && t < 1.0f) {
      const glm::vec2 x = hl + t * d1;
      const float a = glm::length(hr - x), b = glm::length(x - hl), c = glm::length(hl - hr);
      deep = (a * hl + b * hr + c * x) / (a + b + c);
    }
  }
  // Never near the hands' line: over it the body pivots on its hands. Nor so
  // far forward that the shoulders pass well over the hands: the arms then
  // lean forward, bent, and hold most of the weight; a 1.95 m body (its
  // shoulders ~0.45 m ahead of its CoM, not ~0.33) buckled at the elbows and
  // fell on its face in every prone start. kShoulderLead 0.12 / 0.08 / 0.05 /
  // 0.04 / 0.02 / 0: 40 prone starts of 1.60-1.85 m passed every bar 25 / 30 /
  // 40 / 40 / 30 / 23 (without: 23); 45 of 1.40-2.10 m stood 31 / 31 / 41 / 42
  // / 24 / 24 (26) and passed 22 / 25 / 33 / 34 / 21 / 19 (18). (Measured
  // before the hand's step back of StepCandidates; with it, 0.05: 40, 42, 33.)
  const glm::vec2 forward = glm::normalize(Ground(heading_));
  const float handLine = std::min(glm::dot(hl, forward), glm::dot(hr, forward));
  const glm::vec3 shoulders = 0.5f * (r.jointPositions[rig_.upper[0]] + r.jointPositions[rig_.upper[1]]);
  const float shouldersAhead = glm::dot(Ground(shoulders - r.com), forward);
  const float margin = std::max(Scaled(kFootLiftHandLineMargin), shouldersAhead - Scaled(kShoulderLead));
  deep -= forward * std::max(0.0f, glm::dot(deep, forward) - (handLine - margin));
  return Project(ground_, glm::vec3(deep.x, 0.0f, deep.y)) + kUp * CrawlComHeight(r);
}

std::optional<RiseController::Move> RiseController::PlanShift(const BodyReading& r, Limb lifted) const {
  const SupportPolygon stance = StanceWithout(r, lifted);
  const glm::vec2 forward = glm::normalize(Ground(heading_));
  // For a hand: the nearest point kShiftMargin inside the support of the limbs
  // that stay, from a point a little behind the CoM (toward the feet, the
  // paper's secondary goal).
  auto inside = [&](glm::vec2 from) {
    glm::vec2 goal = stance.Closest(from);
    const glm::vec2 centre = stance.Centroid();
    for (int k = 0; k < 30 && stance.SignedDistance(goal) > -Scaled(kShiftMargin); ++k) goal += 0.1f * (centre - goal);
    return Project(ground_, glm::vec3(goal.x, 0.0f, goal.y)) + kUp * CrawlComHeight(r);
  };
  std::vector<glm::vec3> goals;
  if (IsArm(lifted)) {
    // The paper's low-dimensional model: both feet and the support hand
    // fixed, the CoM within every limb's length range, inside their triangle,
    // as close to the feet as that allows; then, if no reachable pose gets
    // there, the nearest balanced point.
    PointMassPlan plan;
    plan.com = r.com;
    plan.footLeft = r.jointPositions[rig_.end[2]];
    plan.footRight = r.jointPositions[rig_.end[3]];
    plan.feetRegion = FeetRegion(r);
    plan.supportHand = ContactPoint(r, OtherHand(lifted));
    plan.leg = {0.6f * legReach_, legReach_ + 0.1f};
    plan.arm = {0.6f * armReach_, armReach_ + 0.35f};
    plan.minHeight = 0.35f * standComHeight_;
    plan.preferredHeight = CrawlComHeight(r);
    plan.maxStep = 0.18f;
    plan.balanceMargin = Scaled(kShiftMargin);
    plan.Solve();
    goals.push_back(plan.target);
    goals.push_back(inside(Ground(r.com) - forward * 0.05f));
  } else {
    goals.push_back(FootLiftCom(r, lifted));
  }
  for (const glm::vec3& comGoal : goals) {
    Move move = OnAllFours(r, "shift", 0.8);
    const float toFeet = glm::length(Ground(comGoal) - FeetRegion(r).Centroid());
    const float heelLift = std::clamp(glm::radians(60.0f) * (toFeet - 0.15f) / 0.6f, 0.0f, glm::radians(60.0f));
    for (int i = 2; i < 4; ++i) move.limbs[i].toRotation = FootRotation(heading_, heelLift);
    PlanTrunk(move, comGoal, {true, true}, true);
    const glm::vec3 planned = PoseCom(GoalAt(move, 1.0f, BodyReading{}));
    if (stance.SignedDistance(Ground(planned)) < -Scaled(kLiftMargin)) return move;
  }
  return std::nullopt;
}

bool RiseController::SolesDown(const BodyReading& r) const {
  for (int i = 2; i < 4; ++i) {
    if (glm::dot(r.jointRotations[rig_.end[i]] * kUp, ground_.normal) <= std::cos(kFlatSole)) return false;
  }
  return true;
}

RiseController::Move RiseController::FinishCrawl(const BodyReading& r) {
  const glm::vec3 toes = 0.5f * (ContactPoint(r, Limb::kFootLeft) + ContactPoint(r, Limb::kFootRight));
  // Hands and feet are together (or no step works). On the toes, the heels
  // come down first, the CoM held over the toe edges with the hands still
  // bearing: on its toes a body whose CoM goes back past the toe edges can
  // only fall back (nothing behind them can push it forward again), while a
  // flat sole reaches back to the heel. Then the CoM goes back over the flat
  // soles, hips low, the hands still touching; the rise lets go of them once
  // it is there.
  const bool heelsUp = !SolesDown(r);
  Move move = OnAllFours(r, heelsUp ? "heels down" : "sit back", 1.2);
  for (int i = 2; i < 4; ++i) move.limbs[i] = ToePivot(r, static_cast<Limb>(i), 0.0f);
  const glm::vec3 back = heelsUp ? glm::vec3(0.0f) : heading_ * walkIn_.sitBack;
  PlanTrunk(move, Project(ground_, toes - back) + kUp * (kSquatComRatio * standComHeight_), {true, true});
  ++crawlSteps_;
  return move;
}

RiseController::Move RiseController::PlanCrawl(const BodyReading& r) {
  const SupportPolygon feet = FeetRegion(r);
  const float comToFeet = feet.SignedDistance(Ground(r.com));
  // The hands let go only with the CoM not on its way off the feet (its
  // capture point on them too): the heels coming down can lift the hands and
  // leave the body rocking forward, and rises begun so at 0.2-0.5 m/s carried
  // the CoM past the toes before the legs were straight.
  const bool steady = feet.SignedDistance(Ground(CapturePoint(r))) < 0.0f;
  // From a squat (sitting back, the heels just down, or holding still) the
  // rise starts a little short of the soles: its own balance takes the CoM
  // the rest of the way.
  const bool squatting = move_.name == "sit back" || move_.name == "heels down" || move_.name == "steady";
  if ((steady && (comToFeet < -Scaled(kRiseMargin) || (squatting && comToFeet < Scaled(kSitBackReach)))) ||
      crawlSteps_ >= kMaxCrawlSteps) {
    return PlanRise(r);
  }
  // Near the soles but not steady (rocking, often with the hands lifted by the
  // heels coming down), the body holds still on all fours a moment and looks
  // again. Hand steps from there fell back in 10 of 19 failed prone starts;
  // holding, bench/prone_variants 72 (prone 20 s, rolled 30 s) stood 162 -> 210
  // of 288, and prone clips passing every bar went 15 -> 21 of 40.
  if (squatting && !steady && comToFeet < Scaled(kSitBackReach)) {
    Move move = OnAllFours(r, "steady", kSteadyHold);
    move.to = move.from;
    ++crawlSteps_;
    return move;
  }
  const std::vector<Limb> candidates = StepCandidates(r);
  if (candidates.empty()) return FinishCrawl(r);
  // The first candidate the CoM is balanced for steps; else the CoM shifts for
  // the current one, and after kMaxShiftTries the next candidate is tried.
  std::optional<Limb> step;
  for (const Limb limb : candidates) {
    if (StanceWithout(r, limb).SignedDistance(Ground(r.com)) < -Scaled(kLiftMargin)) {
      step = limb;
      break;
    }
  }
  if (!step) {
    // Iteration of Phase 1: the CoM moves into the support of the three limbs
    // that stay, for the first candidate whose planned pose (PlanTrunk keeps
    // every limb in reach) puts it there; a goal no reachable pose meets is
    // not tried. When none does, or shifts keep failing to get the body
    // there, the CoM goes back to the middle of all four supports first.
    if (shiftTries_ < kMaxShiftTries * static_cast<int>(candidates.size())) {
      for (size_t k = 0; k < candidates.size(); ++k) {
        const Limb limb = candidates[(static_cast<size_t>(shiftTries_) / kMaxShiftTries + k) % candidates.size()];
        if (std::optional<Move> shift = PlanShift(r, limb)) {
          ++shiftTries_;
          return *shift;
        }
      }
    }
    shiftTries_ = 0;
    // A centre after which no step and no shift works either was followed by
    // the same centre until the time ran out (12 of 25 stress runs that ended
    // in the crawl); from there the crawl ends as it does with hands and feet
    // together.
    if (move_.name == "centre") return FinishCrawl(r);
    Move move = OnAllFours(r, "centre", 0.8);
    std::vector<glm::vec2> points;
    for (int i = 0; i < kLimbCount; ++i) points.push_back(Ground(ContactPoint(r, static_cast<Limb>(i))));
    const glm::vec2 centre = SupportPolygon::FromPoints(points).Centroid();
    PlanTrunk(move, Project(ground_, glm::vec3(centre.x, 0.0f, centre.y)) + kUp * CrawlComHeight(r), {true, true}, true);
    return move;
  }
  // The step: the limb lifts and swings to its new place on a Bezier path
  // while the other three hold the body, its CoM kept where it is. The place
  // is the farthest toward the goal (up to a full step) that the body can
  // reach with every limb from one trunk pose.
  shiftTries_ = 0;
  const Limb limb = *step;
  const int i = static_cast<int>(limb);
  const glm::vec3 left = glm::normalize(glm::cross(kUp, heading_));
  Move best;
  // A limb left in the air by a short step only goes down where it is. That
  // finishes the step, so it is not counted as one of the crawl's steps (its
  // own limit is kMaxPutDowns): counted, a high-stepping body whose every foot
  // step ended in the air got half as far as kMaxCrawlSteps meant and rose
  // with its CoM 0.3 m short of its feet (stress seed 2).
  const bool putDown = Clearance(r, limb) > kLandedClearance;
  putDowns_ = putDown ? putDowns_ + 1 : 0;
  if (!putDown) ++crawlSteps_;
  static constexpr std::array<float, 5> kFractions{1.0f, 0.75f, 0.5f, 0.3f, 0.15f};
  float nominalFootStep = 0.0f;
  // A foot steps with the CoM held at FootLiftCom; if no step length is
  // reachable so, each is tried again with the CoM held where it is (safe: a
  // foot only lifts with the CoM already inside the other three's support).
  // After a roll the bear stance is about 10 cm longer than after a prone start,
  // and with the CoM at FootLiftCom the held foot's leg fell ~2 cm short of it
  // at every step length: the feet shuffled in place for the rest of the crawl.
  const bool comMayStay = !IsArm(limb) && !putDown;
  for (size_t k = 0; k < (comMayStay ? 2 : 1) * kFractions.size(); ++k) {
    const bool comStays = k >= kFractions.size();
    const float fraction = putDown ? 0.0f : kFractions[k % kFractions.size()];
    Move move = OnAllFours(r, IsArm(limb) ? "hand step" : "foot step", 0.7);
    LimbMove& m = move.limbs[i] = HoldLimb(r, limb, false);
    if (IsArm(limb)) {
      // (Hands step only to come down, or back at the crawl's end:
      // StepCandidates.) Where it is along the heading, less the step back,
      // and beside the shoulder's line across it.
      const float side = IsLeft(limb) ? 1.0f : -1.0f;
      const float back = putDown ? 0.0f : Scaled(kHandStepBack);
      const glm::vec3 spot = Project(ground_, FeetCentre(r) + heading_ * (HandsAhead(r, limb) - back) + left * side * shoulderHalfWidth_ * 0.75f);
      m.toRotation = PlantedHandRotation(limb);
      m.to = WristAbove(limb, spot, m.toRotation);
      m.lift = HandSwingLift(limb);
    } else if (putDown) {
      // Straight down, turned as it is, aiming below the ground: the ground
      // stops it, and the move ends once it touches.
      m.toRotation = m.fromRotation;
      // Toward the step's own spot the first time; once that has failed,
      // straight down from where the limb hangs, the CoM held where it is.
      glm::vec3 across = stepSpot_[i] && putDowns_ == 1 ? *stepSpot_[i] - m.from : glm::vec3(0.0f);
      across = AlongPlane(ground_, across);
      m.to = m.from + across - ground_.normal * (Clearance(r, limb) + kLandingReach);
      m.lift = 0.0f;
      move.landing = i;
    } else {
      const float handsAhead = HandsAhead(r);
      // Feet come in side by side: a step ends at most kFootLead ahead of the other foot.
      const Limb other = limb == Limb::kFootLeft ? Limb::kFootRight : Limb::kFootLeft;
      const float behindOther = glm::dot(r.jointPositions[rig_.end[static_cast<int>(other)]] - r.jointPositions[rig_.end[i]], heading_);
      nominalFootStep = std::clamp(std::min(handsAhead - walkIn_.handsAhead, behindOther + Scaled(kFootLead)), 0.05f, walkIn_.footStep);
      // In: the rear foot only comes up beside the other.
      if (handsAhead <= walkIn_.handsAhead + Scaled(kMinFootStep)) nominalFootStep = std::clamp(behindOther, 0.0f, walkIn_.footStep);
      const float length = fraction * nominalFootStep;
      // From the ankle, not the toe: with no hip twist the foot's yaw follows the
      // leg, so its toe can sit to one side, and stepping from there walked
      // the feet apart.
      m.toRotation = FootRotation(heading_, glm::radians(60.0f));
      const glm::vec3 toe = Project(ground_, r.jointPositions[rig_.end[i]] + m.toRotation * toeLocal_);
      // Back to the stance width either side of the hands' midline: feet that
      // keep their own line splay apart step by step.
      const glm::vec3 across = left * StanceAcross(r, limb, toe);
      m.to = AnkleForToe(toe + heading_ * length + across, m.toRotation);
      m.lift = static_cast<float>(spec_.style.stepHeightM);
    }
    // A limb being put down aims below the ground, but the trunk is planned
    // for it touching down there: reaching for the aim pulled the body over.
    const float aimBelow = putDown ? kLandingReach : 0.0f;
    m.to += ground_.normal * aimBelow;
    const bool holdCom = IsArm(limb) || comStays || putDowns_ > 1;
    PlanTrunk(move, holdCom ? r.com : FootLiftCom(r, limb), {limb != Limb::kHandLeft, limb != Limb::kHandRight});
    move.limbs[i].to -= ground_.normal * aimBelow;
    const bool reachable = putDown || Reachable(move);
    // None reachable: the shortest step with the CoM at FootLiftCom, as before.
    if (!comStays || reachable) best = move;
    if (reachable) break;
  }
  if (!putDown) stepSpot_[i] = best.limbs[i].to;
  // The feet are as far in as this body bent at the hips lets them come: the
  // hands walk from here.
  if (!IsArm(limb) && !putDown) {
    feetIn_ = nominalFootStep >= 2.0f * Scaled(kMinFootStep) && glm::dot(best.limbs[i].to - best.limbs[i].from, heading_) < Scaled(kMinFootStep);
  }
  return best;
}

}  // namespace rise
