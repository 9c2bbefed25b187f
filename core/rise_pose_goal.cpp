// SPDX-License-Identifier: MIT
// From a planned move to the pose the servos track: the trunk pose that keeps
// every limb in reach with the CoM at its goal, each limb along its path, and
// the balance layers of the crawl and the rise.
#include "core/rise_controller_detail.h"

#include <array>

namespace rise {

using namespace rise_controller_detail;

namespace {

// A swinging hand or foot stays this many metres above its spot per metre it
// still has to go along the ground (see HoldAloftUntilOver).
constexpr float kLandSlope = 0.15f;

// ... and while it is more than kSkimReach from its spot, its lowest point is kept
// kSkimClearance above the ground: where it comes lower, its target is raised by
// kSkimRaise of the shortfall (see HoldAloftUntilOver).
constexpr float kSkimReach = 0.03f;      // m
constexpr float kSkimClearance = 0.02f;  // m
constexpr float kSkimRaise = 0.5f;

// Supporting arms are kept straight, so the weight goes down the bones and
// into the elbow's limit instead of through the weak elbow servo.
constexpr float kSupportArmReach = 1.0f;  // shoulder-to-wrist, of the arm's reach

// Phase 2's balance feedback: how far the pose's CoM goal moves against the
// capture point's offset from the feet centre. Rises that failed nearly all
// fell backward, the CoM drifting off the heels at 0.3-1.9 m/s; at 2 rather
// than 1 the pose leans against the drift sooner (its offset is bounded by
// the feet either way): stress seeds 5001-6000 and 9001-9500 stood 674 -> 690
// of 1500, the start matrix 25 -> 27 of 32; prone starts passing every bar
// unchanged (flat 117 of 120, tired style 121 of 144). 3 gave no more than 2.
constexpr float kCaptureGain = 2.0f;

// Phase 2's pelvis slide, nearly upright (pelvis above kSoftKneesFrom of its
// standing height), drops the pelvis by what the slide takes (d^2 / 2 L) and
// kSoftKnees: with the legs straight, a slide at the planned height puts the
// feet out of reach, so it was halved to 2-3 mm against a 10 cm CoM error and
// the CoM crept off staggered feet at 3-5 cm/s until the body fell (stress
// seed 21; 26 tries fell from the stand in seeds 1-600, now 5). Lower in the
// rise the drop deepened squats the ankles could not hold (7 tired prone
// starts fell).
constexpr float kSoftKnees = 0.02f;     // m, Scaled
constexpr float kSoftKneesFrom = 0.9f;  // of the standing pelvis height

// PlanTrunk's priorities, as weights of its least-squares residuals (per m, rad).
constexpr float kReachWeight = 30.0f;
constexpr float kStraightArmWeight = 3.0f;

// The CoM outweighs straight arms: at 1 the bear stance's shifts moved the
// planned CoM 3 mm of a 10 cm goal (the arms held the shoulders).
constexpr float kComWeight = 10.0f;
constexpr float kComHeightShare = 0.2f;  // of kComWeight, for the CoM's height
constexpr float kPitchWeight = 0.02f;
constexpr float kMaxHeelLift = 1.2f;  // rad a foot on its toes may lift its heel

// The spine curls forward (chest pitched down from the pelvis) so the pelvis can
// sit back over the feet while the hands stay on the ground; gently preferred straight.
constexpr float kMinCurl = -0.15f, kMaxCurl = 1.2f;  // rad
constexpr float kCurlWeight = 0.05f;
constexpr float kKneeClearance = 0.15f;  // m, Scaled: the knee joints keep this above the ground on hands and feet

// Solves a x = b (a symmetric positive definite) by Cholesky.
template <size_t N>
std::array<float, N> SolveSymmetric(std::array<std::array<float, N>, N> a, std::array<float, N> b) {
  const int n = static_cast<int>(N);
  for (int j = 0; j < n; ++j) {
    for (int k = 0; k < j; ++k) a[j][j] -= a[j][k] * a[j][k];
    a[j][j] = std::sqrt(std::max(a[j][j], 1e-12f));
    for (int i = j + 1; i < n; ++i) {
      for (int k = 0; k < j; ++k) a[i][j] -= a[i][k] * a[j][k];
      a[i][j] /= a[j][j];
    }
  }
  for (int i = 0; i < n; ++i) {
    for (int k = 0; k < i; ++k) b[i] -= a[i][k] * b[k];
    b[i] /= a[i][i];
  }
  for (int i = n - 1; i >= 0; --i) {
    for (int k = i + 1; k < n; ++k) b[i] -= a[k][i] * b[k];
    b[i] /= a[i][i];
  }
  return b;
}

float Blend(float s, float delay, float span) { return Ease((s - delay) / std::max(span, 1e-3f)); }

}  // namespace

void RiseController::PlanTrunk(Move& move, const glm::vec3& comGoal, const std::array<bool, 2>& bearingHands,
                               bool freeHeels) const {
  // The trunk (pelvis position and pitch, and with freeHeels the heel lift of
  // feet pivoting on their toes) found by damped Gauss-Newton on the paper's
  // priorities: first every hand and foot that holds a place reaches it (the
  // limbs' length limits), then the shoulders sit an arm's reach from bearing
  // hands (straight arms carry the weight in their bones), last the whole-body
  // CoM as close to the goal as that allows. Planning only reachable poses is
  // what keeps the servos from fighting the ground: an out-of-reach goal
  // turns into slipping feet and buckling arms.
  auto pitchOf = [&](const glm::quat& q) {
    const glm::vec3 up = q * kUp;
    return std::atan2(glm::dot(up, kUp), glm::dot(up, heading_));
  };
  const float startPitch = pitchOf(move.from.pelvisRotation);
  const float startCurl = std::clamp(startPitch - pitchOf(move.from.chestRotation), kMinCurl, kMaxCurl);
  // Residuals: CoM (3), each limb's reach (3 each), the planted feet's tilt (3 each),
  // the bearing arms' length (1 each), the knees' clearance (1 each), pitch, curl.
  constexpr int kFeetTilt = 3 + 3 * kLimbCount, kArmLength = kFeetTilt + 3 * 2, kKnees = kArmLength + 2;
  constexpr int kUnknowns = 6, kResiduals = kKnees + 2 + 2;
  using Unknowns = std::array<float, kUnknowns>;
  using Residuals = std::array<float, kResiduals>;
  std::vector<int> heels;
  for (int i = 2; i < 4; ++i) {
    if (freeHeels && move.limbs[i].mode == LimbMode::kToePivot) heels.push_back(i);
  }
  auto apply = [&](const Unknowns& x, Move& probe) {
    probe.to.pelvis = glm::vec3(x[0], x[1], x[2]);
    probe.to.pelvisRotation = TrunkRotation(heading_, x[3]);
    probe.to.chestRotation = TrunkRotation(heading_, x[3] - std::clamp(x[5], kMinCurl, kMaxCurl));
    for (int i : heels) probe.limbs[i].toRotation = FootRotation(heading_, std::clamp(x[4], 0.0f, kMaxHeelLift));
  };
  auto residuals = [&](const Unknowns& x) {
    Move probe = move;
    apply(x, probe);
    probe.from = probe.to;
    const PoseGoal goal = GoalAt(probe, 1.0f, BodyReading{});
    const BodyPose pose = SolveBodyPose(def_.skeleton, rig_, goal);
    Residuals r{};
    // The CoM's height matters less than where it is over the ground: a lower
    // or higher trunk is how far-placed hands and feet are reached. Height and
    // "over" are along gravity, never the ground's normal: on a 10 deg slope a
    // CoM 0.9 m up that is over the feet along the normal is 16 cm off them,
    // and the rise fell downhill (this and the CoM goals, which also stand on
    // kUp, stood 2 of 98 random starts on 5-10 deg slopes; now 21).
    const glm::vec3 com = PoseCom(pose) - comGoal;
    const float up = glm::dot(com, kUp);
    const glm::vec3 along = com - kUp * up;
    for (int k = 0; k < 3; ++k) r[k] = kComWeight * (along[k] + kComHeightShare * up * kUp[k]);
    for (int i = 0; i < kLimbCount; ++i) {
      if (probe.limbs[i].mode == LimbMode::kBody) continue;
      const glm::vec3 miss = pose.worldPositions[rig_.end[i]] - goal.limbs[i].target;
      for (int k = 0; k < 3; ++k) r[3 + 3 * i + k] = kReachWeight * miss[k];
    }
    // Sitting back, the planted feet also lie flat as planned: a squat deeper
    // than the ankles' dorsiflexion lifted the heels 20 deg, and a rise from
    // the toes with the CoM behind them fell back onto the ground. (Asked of
    // every move, it cost the crawl's steps: 74 -> 50 of 144 starts stood.)
    for (int i = 2; i < 4; ++i) {
      if (!probe.limbs[i].planted || move.name != "sit back") continue;
      const float halfLength = def_.skeleton.joints[rig_.end[i]].box.halfExtents.z;
      const glm::vec3 tilt = pose.worldRotations[rig_.end[i]] * kUp - goal.limbs[i].endRotation * kUp;
      for (int k = 0; k < 3; ++k) r[kFeetTilt + 3 * (i - 2) + k] = kReachWeight * halfLength * tilt[k];
    }
    for (int i = 0; i < 2; ++i) {
      if (!bearingHands[i]) continue;
      const float reach = glm::length(LimbRoot(def_.skeleton, rig_, goal, static_cast<Limb>(i)) - goal.limbs[i].target);
      r[kArmLength + i] = kStraightArmWeight * (reach - kSupportArmReach * armReach_);
    }
    // Knees stay off the ground: kneeling, the body would rest on joints the
    // plan does not count as supports.
    for (int leg = 2; leg < 4; ++leg) {
      const float height = Height(ground_, pose.worldPositions[rig_.lower[leg]]);
      r[kKnees + (leg - 2)] = kReachWeight * std::max(0.0f, Scaled(kKneeClearance) - height);
    }
    r[kResiduals - 2] = kPitchWeight * (x[3] - startPitch);
    r[kResiduals - 1] = kCurlWeight * x[5];
    return r;
  };
  auto cost = [](const Residuals& r) {
    float sum = 0.0f;
    for (float v : r) sum += v * v;
    return sum;
  };

  float heel = 0.0f;
  for (int i : heels) {
    const glm::vec3 footUp = move.limbs[i].toRotation * kUp;
    heel += std::acos(std::clamp(glm::dot(footUp, ground_.normal), -1.0f, 1.0f)) / static_cast<float>(heels.size());
  }
  auto descend = [&](Unknowns x) {
  Residuals r = residuals(x);
  float lambda = 1e-3f;
  for (int iteration = 0; iteration < 25; ++iteration) {
    std::array<Residuals, kUnknowns> jacobian{};
    for (int u = 0; u < kUnknowns; ++u) {
      Unknowns probe = x;
      constexpr float kStep = 1e-3f;
      probe[u] += kStep;
      const Residuals moved = residuals(probe);
      for (int k = 0; k < kResiduals; ++k) jacobian[u][k] = (moved[k] - r[k]) / kStep;
    }
    std::array<std::array<float, kUnknowns>, kUnknowns> normal{};
    std::array<float, kUnknowns> gradient{};
    for (int a = 0; a < kUnknowns; ++a) {
      for (int k = 0; k < kResiduals; ++k) gradient[a] += jacobian[a][k] * r[k];
      for (int b = 0; b < kUnknowns; ++b) {
        for (int k = 0; k < kResiduals; ++k) normal[a][b] += jacobian[a][k] * jacobian[b][k];
      }
    }
    bool improved = false;
    for (int attempt = 0; attempt < 6 && !improved; ++attempt) {
      std::array<std::array<float, kUnknowns>, kUnknowns> damped = normal;
      for (int a = 0; a < kUnknowns; ++a) damped[a][a] += lambda * (1.0f + normal[a][a]);
      const std::array<float, kUnknowns> delta = SolveSymmetric(damped, gradient);
      Unknowns next = x;
      for (int a = 0; a < kUnknowns; ++a) next[a] -= delta[a];
      const Residuals trial = residuals(next);
      if (cost(trial) < cost(r)) {
        x = next, r = trial, lambda = std::max(1e-5f, lambda * 0.3f), improved = true;
      } else {
        lambda *= 10.0f;
      }
    }
    if (!improved) break;
  }
  return std::make_pair(x, cost(r));
  };
  // Gauss-Newton only finds the pose nearest the start; the pike that brings
  // the feet in under a body on its hands lies over a ridge of the knee and
  // reach terms from a flat trunk, so a piked start is tried as well.
  auto best = descend({move.from.pelvis.x, move.from.pelvis.y, move.from.pelvis.z, startPitch, heel, startCurl});
  if (OnHandsAndFeet(move.phase)) {
    const glm::vec3 hips = Horizontal(comGoal) - heading_ * 0.2f + kUp * (0.85f * legReach_);
    const auto piked = descend({hips.x, hips.y, hips.z, -0.3f, heel, 0.6f});
    if (piked.second < best.second) best = piked;
  }
  apply(best.first, move);
}

// ---------------------------------------------------------------------------
// Evaluating a move

void RiseController::EvaluateLimb(const LimbMove& limb, Limb which, float s, const PoseGoal& trunkGoal,
                                  LimbGoal& out) const {
  const float u = Blend(s, limb.delay, limb.span);
  const float turn = Blend(s, limb.delay + limb.turnDelay * limb.span, (1.0f - limb.turnDelay) * limb.span);
  const glm::quat rotation = glm::slerp(limb.fromRotation, limb.toRotation, turn);
  out.angles.reset();
  out.swingAngles.reset();
  switch (limb.mode) {
    case LimbMode::kWorld:
      out.target = limb.lift > 0.0f ? SwingPath{limb.from, limb.to, ground_.normal, limb.lift}.At(u)
                                    : glm::mix(limb.from, limb.to, u);
      out.endRotation = rotation;
      break;
    case LimbMode::kToePivot:
      out.endRotation = rotation;
      out.target = AnkleForToe(glm::mix(limb.from, limb.to, u), rotation);
      break;
    case LimbMode::kBody: {
      const glm::quat frame = IsArm(which) ? trunkGoal.chestRotation : trunkGoal.pelvisRotation;
      out.target = LimbRoot(def_.skeleton, rig_, trunkGoal, which) + frame * glm::mix(limb.from, limb.to, u);
      out.endRotation = glm::normalize(frame * rotation);
      break;
    }
    case LimbMode::kJoint: {
      // Forward kinematics of the interpolated angles, which the IK turns back
      // into the same angles: a swing along the joints' arcs, never through the root.
      const int i = static_cast<int>(which);
      const glm::vec3 angles = glm::mix(limb.from, limb.to, u);
      const glm::quat frame = IsArm(which) ? trunkGoal.chestRotation : trunkGoal.pelvisRotation;
      const glm::quat upper = frame * glm::angleAxis(angles.x, rig_.rootDofs[i][0].axis) *
                              glm::angleAxis(angles.y, rig_.rootDofs[i][1].axis);
      const glm::quat lower = upper * glm::angleAxis(angles.z, rig_.hinge[i].axis);
      out.target = LimbRoot(def_.skeleton, rig_, trunkGoal, which) +
                   upper * def_.skeleton.joints[rig_.lower[i]].restOffset +
                   lower * def_.skeleton.joints[rig_.end[i]].restOffset;
      out.endRotation = glm::normalize(lower * rotation);
      // The lift rises early and holds, so a limb leaves the ground before the
      // swing has carried it far along it; the IK then finds the angles that
      // raise it, near the swing's own. Without one the angles are the goal as they are.
      out.target += ground_.normal * (limb.lift * std::min(1.0f, 8.0f * u * (1.0f - u)));
      if (limb.lift <= 0.0f) {
        out.angles = angles;
      } else {
        out.swingAngles = angles;
      }
      break;
    }
  }
}

void RiseController::ReleaseLiftedHands(const BodyReading& reading) {
  // Sitting back onto the feet takes the weight off the hands, which the
  // body then lifts. A planted hand's wrist target is where the wrist was at
  // the move's start, but the hand has rolled on its fingers since (the wrist
  // 5-10 cm from it): leaving the ground, the arm swung it back there and
  // dragged the palm 3-4 cm in its last centimetre above the ground, the
  // slide that failed 5 of 144 prone starts by 0.1-0.6 cm. Once no corner
  // presses into the ground, its target is held over where it is.
  // bench/prone_variants 144 prone, normal / tired: passed every bar 138 ->
  // 141 and 106 -> 106. (Also while holding still in the squat: tired 101.)
  for (int i = 0; i < 2; ++i) {
    LimbMove& m = move_.limbs[i];
    if (!m.planted || m.mode != LimbMode::kWorld || Clearance(reading, static_cast<Limb>(i)) < 0.0f) continue;
    glm::vec3 at = reading.jointPositions[rig_.end[i]];
    at += ground_.normal * glm::dot(m.to - at, ground_.normal);
    m.from = m.to = at;
  }
}

void RiseController::HoldAloftUntilOver(const Move& move, const BodyReading& reading, PoseGoal& goal) const {
  // A swing's path comes down on the clock, but the servos let a hand or foot
  // lag its target by 20-25 cm, so it came down while still catching up and
  // slid on landing (the place's hands touched down at 3 m/s and slid 8 cm).
  // The target therefore stays above the spot by kLandSlope times the measured
  // end's remaining distance along the ground, up to the swing's lift, and a
  // limb that is over its spot aims at it, not below it: it lands from above.
  // Measured without / with slope 0.25 / 0.15: bench/prone_variants prone 72
  // (20 s) stood 56 / 68 / 62, supine, side_left, side_right 36 each (30 s)
  // 87 / 88 / 89; prone starts of the notes harness (40, other bodies) stood
  // 31 / 40 / 36, passed every bar 21 / 19 / 22, on an 8 deg slope (30) passed
  // 6 / 8 / 11. Raising only the targets above the ground (landings still
  // aiming below it) passed 11 of the 40.
  // The wrist or ankle on that path can still leave the hand or foot skimming
  // the ground: a hand hanging fingers down from its wrist (a tall body's
  // place, as the arm swings in from behind) came within 1 cm of the ground
  // 5-10 cm short of its spot and brushed along it to the spot, 8 cm of slide
  // by the clip check's 1 cm contact height. So while still away from its spot
  // a hand or foot is also raised by part of how far its lowest point is under
  // kSkimClearance. (Raised by the whole shortfall, or 3 times it, the moves'
  // landings came late and slid: of the back and side starts of
  // bench/manifests, 95 / 79 and 132 / 120 passed every bar; by half of it 96
  // and 136, against 81 and 132 without; the library 40 of 40, against 39.
  // Its price: prone starts on 10 deg stood 29 of 48, against 34, and
  // samples/tall.json's place, which passed, skims 7.9 cm all the same. Raised
  // only in the place, the back starts kept none of their gain: 81.)
  for (int i = 0; i < kLimbCount; ++i) {
    const LimbMove& limb = move.limbs[i];
    if (limb.mode != LimbMode::kWorld || limb.lift <= 0.0f) continue;
    const float away = glm::length(AlongPlane(ground_, limb.to - reading.jointPositions[rig_.end[i]]));
    const float aloft = std::min(limb.lift, kLandSlope * away);
    const float height = glm::dot(goal.limbs[i].target - limb.to, ground_.normal);
    if (height < aloft) goal.limbs[i].target += ground_.normal * (aloft - height);
    const float shortfall = kSkimClearance - Clearance(reading, static_cast<Limb>(i));
    if (away > kSkimReach && shortfall > 0.0f) goal.limbs[i].target += ground_.normal * (kSkimRaise * shortfall);
  }
}

void RiseController::Lean(const Move& move, float s, float lean, PoseGoal& goal) const {
  const glm::quat tilt = glm::angleAxis(lean, glm::normalize(glm::cross(kUp, heading_)));
  goal.pelvisRotation = tilt * goal.pelvisRotation;
  goal.chestRotation = tilt * goal.chestRotation;
  goal.headRotation = tilt * goal.headRotation;
  for (int i = 0; i < kLimbCount; ++i) {
    if (move.limbs[i].mode == LimbMode::kBody) EvaluateLimb(move.limbs[i], static_cast<Limb>(i), s, goal, goal.limbs[i]);
  }
}

bool RiseController::FeetFlat(const PoseGoal& goal) const {
  const BodyPose pose = SolveBodyPose(def_.skeleton, rig_, goal);
  return pose.reached[2] && pose.reached[3] && pose.endMatched[2] && pose.endMatched[3];
}

float RiseController::BalanceLean(const Move& move, float s, const BodyReading& reading, float lo, float hi) const {
  // Hip strategy: how far the trunk leans forward of the plan (never back) for
  // the pose's CoM to reach the balance point along the heading. Leaning is
  // what keeps a rise out of a deep squat feasible, where the ankles cannot
  // bring the knees further forward. A lean the hips cannot make with the
  // feet flat counts as too far.
  const PoseGoal planned = GoalAt(move, s, reading, false);
  const glm::vec3 target = BalancePoint(reading);
  auto ahead = [&](float lean) {
    PoseGoal goal = planned;
    Lean(move, s, lean, goal);
    const BodyPose pose = SolveBodyPose(def_.skeleton, rig_, goal);
    if (!pose.reached[2] || !pose.reached[3] || !pose.endMatched[2] || !pose.endMatched[3]) return 1.0f;
    return glm::dot(PoseCom(pose) - target, heading_);
  };
  lo = std::max(lo, 0.0f), hi = std::min(hi, kMaxBalanceLean);
  if (ahead(hi) < 0.0f) return hi;
  if (ahead(lo) >= 0.0f) return lo;
  while (hi - lo > kLeanTolerance) {
    const float mid = 0.5f * (lo + hi);
    (ahead(mid) < 0.0f ? lo : hi) = mid;
  }
  return lo;
}

PoseGoal RiseController::GoalAt(const Move& move, float s, const BodyReading& reading, bool balance,
                                std::optional<BodyPose>* solved) const {
  if (solved) solved->reset();
  const float e = Ease(s);
  PoseGoal goal;
  goal.pelvisPosition = glm::mix(move.from.pelvis, move.to.pelvis, e);
  if (move.keepComOverFeet && !reading.jointPositions.empty()) goal.pelvisPosition = RisingPelvis(move, e, reading);
  goal.pelvisRotation = glm::slerp(move.from.pelvisRotation, move.to.pelvisRotation, e);
  goal.chestRotation = glm::slerp(move.from.chestRotation, move.to.chestRotation, Ease(std::min(1.0f, s * 1.25f)));

  // Secondary (priority) layer: style on the head and chest that the primary
  // targets below (CoM over the feet, contacts held) then absorb.
  const float t = static_cast<float>(reading.time);
  const float sway = static_cast<float>(spec_.style.sway);
  if (sway > 0.0f && move.keepComOverFeet) {
    goal.chestRotation = goal.chestRotation * glm::angleAxis(0.12f * sway * std::sin(1.7f * t), glm::vec3(0, 0, 1));
  }
  const float look = static_cast<float>(spec_.style.lookAround);
  // With the chest pitched forward the neck extends, so the face looks ahead
  // and the head stays clear of the ground.
  const float chestPitch = std::asin(std::clamp(glm::dot(goal.chestRotation * kUp, kUp), -1.0f, 1.0f));
  const float extension = std::clamp(0.6f * (0.5f * kPi - chestPitch), 0.0f, 0.8f);
  goal.headRotation = goal.chestRotation * glm::angleAxis(-extension, glm::vec3(1, 0, 0)) *
                      glm::angleAxis(0.6f * look * std::sin(0.9f * t), glm::vec3(0, 1, 0));

  for (int i = 0; i < kLimbCount; ++i) EvaluateLimb(move.limbs[i], static_cast<Limb>(i), s, goal, goal.limbs[i]);
  if (!reading.jointPositions.empty()) HoldAloftUntilOver(move, reading, goal);

  if (balance && OnHandsAndFeet(move.phase) && !reading.jointPositions.empty()) {
    // On hands and feet the plan is quasi-static, so where the CoM is matters
    // more than how the trunk is turned: the pelvis goal moves by the measured
    // CoM's horizontal error (and its integral, crawlOffset_), which the
    // planted limbs turn into a shift of the whole body.
    BodyPose plannedPose = SolveBodyPose(def_.skeleton, rig_, goal);
    glm::vec3 error = PoseCom(plannedPose) - reading.com;
    error.y = 0.0f;
    // Only as far as every hand and foot can still reach its place: past that
    // the servos would be asked for a pose whose feet are off their spots.
    const glm::vec3 planned = goal.pelvisPosition;
    glm::vec3 shift = kCrawlComGain * error + crawlOffset_;
    BodyPose shifted;
    bool reached = false;
    for (int halving = 0; halving < 6 && !reached; ++halving, shift *= 0.5f) {
      goal.pelvisPosition = planned + shift;
      reached = LimbsReach(move, goal, &shifted);
      if (!reached) goal.pelvisPosition = planned;
    }
    if (solved) *solved = std::move(reached ? shifted : plannedPose);
  }
  if (move.keepComOverFeet && balance && !reading.jointPositions.empty()) {
    if (solved) solved->reset();
    // Primary constraint of Phase 2: the whole-body CoM over the feet. The
    // trunk leans by balanceLean_ (the hip strategy, planned and smoothed in
    // Update); then the pelvis slides along the ground (the ankle strategy)
    // until the pose's CoM is over the balance point, moved to the far side of
    // it from the measured capture point (CoM + velocity / omega of the
    // inverted pendulum) so a body drifting forward is leaned back before its
    // CoM leaves the feet, plus the integral correction for the servos' sag.
    // The correction is bounded by what the feet can hold, the slide by what
    // the ankles allow with the feet flat where they are (upright, with the
    // knees bent as far as the slide needs: kSoftKnees). (Horizontal: balance
    // is along gravity, on a slope too; see PlanTrunk.)
    const glm::vec3 target = BalancePoint(reading);
    glm::vec3 capture = CapturePoint(reading) - target;
    capture.y = 0.0f;
    glm::vec3 correction = balanceOffset_ - kCaptureGain * capture;
    const float footLength = 2.0f * def_.skeleton.joints[rig_.end[2]].box.halfExtents.z;
    const float maxCorrection = 0.4f * footLength;
    if (glm::length(correction) > maxCorrection) correction *= maxCorrection / glm::length(correction);
    const glm::vec3 centre = target + correction;
    Lean(move, s, balanceLean_, goal);
    const glm::vec3 nominal = goal.pelvisPosition;
    const bool upright = Height(ground_, nominal) > kSoftKneesFrom * standPelvisHeight_;
    glm::vec3 slide(0.0f);
    for (int iteration = 0; iteration < 3; ++iteration) {
      glm::vec3 error = centre - PoseCom(goal);
      error.y = 0.0f;
      slide += error;
      if (glm::length(slide) > Scaled(kMaxBalanceSlide)) slide *= Scaled(kMaxBalanceSlide) / glm::length(slide);
      for (int halving = 0; halving < 5; ++halving, slide *= 0.5f) {
        goal.pelvisPosition = nominal + slide;
        if (FeetFlat(goal)) break;
        if (!upright) continue;
        goal.pelvisPosition -= kUp * (glm::dot(slide, slide) / (2.0f * legReach_) + Scaled(kSoftKnees));
        if (FeetFlat(goal)) break;
      }
      for (int i = 0; i < kLimbCount; ++i) {
        if (move.limbs[i].mode == LimbMode::kBody) EvaluateLimb(move.limbs[i], static_cast<Limb>(i), s, goal, goal.limbs[i]);
      }
    }
  }
  return goal;
}

bool RiseController::Reachable(const Move& move) const { return LimbsReach(move, GoalAt(move, 1.0f, BodyReading{})); }

bool RiseController::LimbsReach(const Move& move, const PoseGoal& goal, BodyPose* solved) const {
  BodyPose pose = SolveBodyPose(def_.skeleton, rig_, goal);
  for (int i = 0; i < kLimbCount; ++i) {
    if (move.limbs[i].mode != LimbMode::kBody &&
        glm::length(pose.worldPositions[rig_.end[i]] - goal.limbs[i].target) > kReachTolerance) {
      return false;
    }
  }
  if (solved) *solved = std::move(pose);
  return true;
}

}  // namespace rise
