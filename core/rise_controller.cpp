// SPDX-License-Identifier: MIT
#include "core/rise_controller.h"

#include "base/assert.h"
#include "core/bezier.h"
#include "core/biped.h"
#include "core/point_mass_plan.h"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/gtx/matrix_operation.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <utility>

namespace rise {
namespace {

constexpr float kPi = glm::pi<float>();
const glm::vec3 kUp(0.0f, 1.0f, 0.0f);

// Rest: the fallen body has stopped (the paper waits for this before rising).
constexpr float kRestSpeed = 0.08f;         // m/s
constexpr float kRestSpin = 0.4f;           // rad/s
constexpr double kRestHold = 0.25;          // s the body must stay below both
// A clip that ends after the last fall ends on a body at rest by this speed: at
// kRestSpeed, one creeping down a 20 deg slope at 3 cm/s counted as at rest and
// the clip's last frames slid 1 mm each.
constexpr float kFinalRestSpeed = 0.02f;    // m/s
// Standing still long enough to end the clip (the checker looks at the last 0.5 s).
constexpr double kStandHold = 1.2;          // s
// Tracking-error gate: moves slow down when the pelvis lags its goal.
constexpr float kGateError = 0.06f;         // m: full speed below this
constexpr float kGateStop = 0.20f;          // m: slowest pace at and above this
constexpr double kStallTime = 1.5;        // s a move may lag beyond kGateStop before it is re-planned
constexpr int kMaxCrawlSteps = 24;
// A limb lifts only with the CoM this far inside the other three's support;
// the shift before it aims kShiftMargin inside, and is tried this many times.
constexpr float kLiftMargin = 0.03f;  // m
constexpr float kShiftMargin = 0.06f;  // m
constexpr int kMaxShiftTries = 2;
// A limb a put-down leaves in the air this many times in a row ends the try
// like a fall (stress seed 105: a foot hung 0.3 m up for 25 s, put down
// again and again where its hip could not take it).
constexpr int kMaxPutDowns = 4;
// While a foot steps, the CoM stays this far behind the hands' line: over it
// the body pivots on its hands.
constexpr float kFootLiftHandLineMargin = 0.22f;  // m
// ... and so far back that the shoulders, carried along with it, stay within
// kShoulderLead of that line (see FootLiftCom).
constexpr float kShoulderLead = 0.05f;  // m
// A hand that steps back toward the feet at the end of the crawl goes this far.
constexpr float kHandStepBack = 0.15f;  // m
constexpr float kReachTolerance = 0.01f;  // m a planned limb may miss its place by
constexpr float kLandedClearance = 0.02f;  // m above the ground a placed hand or foot counts as down
constexpr float kLandingReach = 0.1f;      // m below the ground a limb being put down aims
// The place swings the hands to kHandHover above their spots (0.04, 0.06 and
// 0.08 m measured: 12, 13 and 14 of 36 prone starts stood, 2, 10 and 8 of
// them with no contact sliding 5 cm); they then come down aiming kHandPress
// into the ground, so that they land bearing.
constexpr float kHandHover = 0.06f;  // m
constexpr float kHandPress = 0.005f;  // m
// A swinging hand or foot stays this many metres above its spot per metre it
// still has to go along the ground (see HoldAloftUntilOver).
constexpr float kLandSlope = 0.15f;
// Phase 2 starts once the CoM's ground projection is this far inside the feet.
constexpr float kRiseMargin = 0.02f;  // m
// The sit back puts the CoM this far behind the middle of the flat soles:
// far enough in that the rise starts with room to brake a drift either way.
constexpr float kSitBackBehindSoles = 0.1f;  // m
// CoM height in the squat the crawl ends in, of the standing CoM height. Measured with
// bench/prone_variants (prone 20 s, supine and sides 30 s): 0.45 stood 69 of 144 starts,
// 0.50 and 0.55 alike (151 and 149 of 288).
constexpr float kSquatComRatio = 0.55f;
// A squat hands over to the rise once the CoM is within this of the soles.
constexpr float kSitBackReach = 0.05f;  // m
constexpr double kSteadyHold = 0.2;     // s a squat not yet steady holds still before it looks again (0.3: fewer pass every bar)
constexpr float kFlatSole = glm::radians(12.0f);  // a sole tilted less than this is flat
// Supporting arms are kept straight, so the weight goes down the bones and
// into the elbow's limit instead of through the weak elbow servo.
constexpr float kSupportArmReach = 1.0f;  // shoulder-to-wrist, of the arm's reach
// Planted hands' wrists go soft so the palm lies flat and takes load at its heel.
constexpr float kPlantedWristGain = 0.15f;
// Feet this far either side of the hands' midline in the crawl: narrow, so
// the knees come in between the arms as the feet walk up to the hands and the
// squat the rise starts from is balanced side to side (0.10-0.15 m measured:
// 11, 14 and 5 of 36 prone starts stood).
constexpr float kCrawlHalfStance = 0.12f;  // m
// A foot farther than this across from its place in that stance steps there first.
constexpr float kMaxStanceDrift = 0.15f;  // m
constexpr int kMaxRetries = 4;
// The fastest pace of the moves that balance the body on its hands and feet
// or its feet (push, crawl, rise, stand): the paper's quasi-static balance.
// Faster, the CoM overran the support: prone starts at speed 3 stood 29 of 72
// (2: 66), capped here 72 of 72 (69 pass every bar; uncapped 1.5: 72, 70).
// The roll and the placing of hands and feet keep the style's full pace.
constexpr double kMaxBalancedPace = 1.5;
constexpr float kMaxLimbSpeed = 1.5f;  // m/s, average along a swing
// Phase 2's balance feedback: how far the pose's CoM goal moves against the
// capture point's offset from the feet centre.
constexpr float kCaptureGain = 1.0f;
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
constexpr float kKneeClearance = 0.15f;  // m the knee joints keep above the ground on hands and feet
// CoM feedback on hands and feet: proportional gain, integral gain (1/s), integral bound.
constexpr float kCrawlComGain = 0.5f;
constexpr float kCrawlComIntegral = 1.0f;
constexpr float kMaxCrawlOffset = 0.06f;  // m
// The virtual CoM force on hands and feet: stiffness and damping per kg of body
// (omega ~3.5 rad/s, critically damped), bounded as a fraction of the weight.
constexpr float kVirtualStiffness = 12.0f;  // 1/s^2
constexpr float kVirtualDamping = 7.0f;     // 1/s
constexpr float kMaxVirtualForce = 0.25f;
// Phase 2's ankle strategy: the CoM's wanted acceleration toward the balance
// point, per m of offset and per m/s (omega 3 rad/s, critically damped).
constexpr float kBalanceStiffness = 9.0f;  // 1/s^2
constexpr float kBalanceDamping = 6.0f;    // 1/s
constexpr float kMaxBalanceSlide = 0.1f;  // m the pelvis may slide from its planned place
constexpr float kMaxBalanceLean = 1.2f;   // rad the trunk may lean forward of its plan
constexpr float kLeanRate = 0.8f;         // rad/s the balance lean may change
constexpr float kLeanTolerance = 0.002f;  // rad: the balance lean's search stops this close
// The feet walk in while the hands are farther than this ahead of them (from
// nearer, a foot can hardly come further under a body bent at the hips); a
// foot step is at most kFootStep long. The hips rise from the bear stance into
// a pike as the hands come from kPikeStart to kFootWalkDistance ahead.
constexpr float kFootWalkDistance = 0.5f;  // m at kTunedHeight
constexpr float kPikeStart = 1.1f;         // m at kTunedHeight
constexpr float kPikeComRatio = 0.62f;     // CoM height of the pike as the feet come in, of standing
constexpr float kFootStep = 0.3f;          // m at kTunedHeight
constexpr float kFootLead = 0.1f;          // m
constexpr float kMinFootStep = 0.06f;      // m: a reachable step shorter than this ends the walk-in
// The walk-in's lengths marked "at kTunedHeight" were tuned on a body this
// tall; a body's own are these scaled by its height (WalkInLengths).
constexpr float kTunedHeight = 1.75f;  // m
// The roll (RiseController::RollAngle: 0 on the back, pi on the front): the far
// foot pushes until the pelvis has turned this far, or has pushed off once
// the pelvis is past kLiftOffRoll; the chest past kChestOverRoll has led over
// and the legs straighten; both past kProneRoll lie prone.
constexpr float kLiftOffRoll = glm::radians(30.0f);
constexpr float kPushedRoll = glm::radians(60.0f);
// A far leg whose ankle is this far from its hip, of the leg's reach, is set to push.
constexpr float kTuckedLeg = 0.8f;
// ... and its foot no higher than this over the ground: the push off presses it down.
constexpr float kTuckedClearance = 0.2f;  // m
constexpr float kChestOverRoll = glm::radians(125.0f);
constexpr float kProneRoll = glm::radians(135.0f);
// Shoulder flexion past which an arm lies overhead.
constexpr float kOverheadArm = glm::radians(60.0f);
// Shoulder abduction past which an arm is out to the side (turned there by the arm out).
constexpr float kArmOutAbduction = glm::radians(70.0f);
// A roll takes 6 moves (tuck, push off, over, lie, arm out, arm turn) and a
// few more when one leaves the body short.
constexpr int kMaxRollMoves = 13;

// On hands and feet: where the plan is quasi-static and the CoM is held by feedback.
bool OnHandsAndFeet(RisePhase phase) { return phase == RisePhase::kPush || phase == RisePhase::kCrawl; }

bool IsArm(Limb limb) { return limb == Limb::kHandLeft || limb == Limb::kHandRight; }
bool IsLeft(Limb limb) { return limb == Limb::kHandLeft || limb == Limb::kFootLeft; }
Limb OtherHand(Limb hand) { return hand == Limb::kHandLeft ? Limb::kHandRight : Limb::kHandLeft; }

glm::vec3 Horizontal(const glm::vec3& v) { return {v.x, 0.0f, v.z}; }

glm::vec3 SafeNormalize(const glm::vec3& v, const glm::vec3& fallback) {
  const float length = glm::length(v);
  return length > 1e-5f ? v / length : fallback;
}

// Rotation about +Y that turns +Z onto the horizontal direction `forward`.
glm::quat HeadingRotation(const glm::vec3& forward) {
  return glm::angleAxis(std::atan2(forward.x, forward.z), kUp);
}

// Rotation with the given images of +X and +Y (both unit, orthogonal).
glm::quat FromAxes(const glm::vec3& x, const glm::vec3& y) {
  return glm::normalize(glm::quat_cast(glm::mat3(x, y, glm::cross(x, y))));
}

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

float Height(const physics::PlaneShape& plane, const glm::vec3& p) { return glm::dot(plane.normal, p) - plane.offset; }
glm::vec3 Project(const physics::PlaneShape& plane, const glm::vec3& p) { return p - plane.normal * Height(plane, p); }

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
  // 1.60-1.85 m: 36 -> 32 stood, 22 -> 23 passed. Also scaling the stance
  // width, the lead between the feet, the shortest step and the CoM's margin
  // behind the hands: 27 / 16, 21 and 34 / 19.
  const float scale = static_cast<float>(spec.character.heightM) / kTunedHeight;
  walkIn_ = {kFootWalkDistance * scale, kPikeStart * scale, kFootStep * scale};
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
// Geometry of the measured body

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
  palmOffset -= ground_.normal * glm::dot(palmOffset, ground_.normal);
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
      r[kKnees + (leg - 2)] = kReachWeight * std::max(0.0f, kKneeClearance - height);
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
      // raise it. Without one the angles are the goal as they are.
      out.target += ground_.normal * (limb.lift * std::min(1.0f, 8.0f * u * (1.0f - u)));
      if (limb.lift <= 0.0f) out.angles = angles;
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
  for (int i = 0; i < kLimbCount; ++i) {
    const LimbMove& limb = move.limbs[i];
    if (limb.mode != LimbMode::kWorld || limb.lift <= 0.0f) continue;
    glm::vec3 away = limb.to - reading.jointPositions[rig_.end[i]];
    away -= ground_.normal * glm::dot(away, ground_.normal);
    const float aloft = std::min(limb.lift, kLandSlope * glm::length(away));
    const float height = glm::dot(goal.limbs[i].target - limb.to, ground_.normal);
    if (height < aloft) goal.limbs[i].target += ground_.normal * (aloft - height);
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
    // the ankles allow with the feet flat where they are. (Horizontal: balance
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
    glm::vec3 slide(0.0f);
    for (int iteration = 0; iteration < 3; ++iteration) {
      glm::vec3 error = centre - PoseCom(goal);
      error.y = 0.0f;
      slide += error;
      if (glm::length(slide) > kMaxBalanceSlide) slide *= kMaxBalanceSlide / glm::length(slide);
      for (int halving = 0; halving < 5; ++halving, slide *= 0.5f) {
        goal.pelvisPosition = nominal + slide;
        if (FeetFlat(goal)) break;
      }
      for (int i = 0; i < kLimbCount; ++i) {
        if (move.limbs[i].mode == LimbMode::kBody) EvaluateLimb(move.limbs[i], static_cast<Limb>(i), s, goal, goal.limbs[i]);
      }
    }
  }
  return goal;
}

// ---------------------------------------------------------------------------
// Planning

void RiseController::StartMove(Move move) {
  double pace = StylePace(spec_.style);
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

bool RiseController::Standing(double time) const {
  return phase_ == RisePhase::kStand && standTime_ >= 0.0 && time - standTime_ >= kStandHold;
}

bool RiseController::Fallen(const BodyReading& r) const {
  const float pelvisHeight = Height(ground_, r.jointPositions[rig_.pelvis]);
  // Built only when the cheap tests have not decided: this runs every step.
  auto comToFeet = [&] { return FeetRegion(r).SignedDistance(Ground(r.com)); };
  // A roll that has not got the body onto its front in this many moves is a
  // failed try like a fall (a slope can roll it back onto its back each time).
  if (phase_ == RisePhase::kRoll) return rollMoves_ > kMaxRollMoves;
  if (phase_ == RisePhase::kCrawl) {
    if (putDowns_ > kMaxPutDowns) return true;
    // Down on the ground again (sitting or lying) with the hands and feet no longer bearing.
    // (Squatting on both feet with the CoM over them is not down: it is where the crawl ends.)
    const int bearing = static_cast<int>(std::count(r.touching.begin(), r.touching.end(), true));
    if (pelvisHeight >= 0.22f * standPelvisHeight_ || bearing >= 3) return false;
    return !(r.touching[2] && r.touching[3] && comToFeet() < 0.0f);
  }
  if (phase_ != RisePhase::kRise && phase_ != RisePhase::kStand) return false;
  if (pelvisHeight < 0.25f * standPelvisHeight_) return true;
  // A chest folded over the knees is how a rise from a squat starts (and what
  // OnItsFeet accepts): down only with the CoM off the feet as well.
  const glm::vec3 up = r.jointRotations[rig_.chest] * kUp;
  return glm::dot(up, kUp) < std::cos(glm::radians(70.0f)) && comToFeet() > 0.05f;
}

void RiseController::PlanNext(const BodyReading& reading) {
  switch (phase_) {
    case RisePhase::kSettle:
    case RisePhase::kRoll: StartMove(PlanRoll(reading)); break;
    case RisePhase::kPlace: StartMove(move_.name == "place" ? PlanHandsDown(reading) : PlanPush(reading)); break;
    case RisePhase::kPush:
    case RisePhase::kCrawl: StartMove(PlanCrawl(reading)); break;
    case RisePhase::kRise: StartMove(PlanStand(reading)); break;
    case RisePhase::kStand: StartMove(PlanStand(reading)); break;
  }
}

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

RiseController::LimbMove RiseController::RollLimb(const BodyReading& r, Limb limb,
                                                  const std::array<float, 5>& anglesDeg) const {
  const int i = static_cast<int>(limb);
  const std::vector<glm::quat> local = LocalRotations(def_.skeleton, r.jointRotations);
  float root[3] = {}, hinge[3] = {};
  def_.JointAngles(rig_.upper[i], local[rig_.upper[i]], root);
  def_.JointAngles(rig_.lower[i], local[rig_.lower[i]], hinge);
  LimbMove m;
  m.mode = LimbMode::kJoint;
  m.from = glm::radians(glm::vec3(root[0], root[1], hinge[0]));
  m.to = glm::radians(glm::vec3(anglesDeg[0], anglesDeg[1], anglesDeg[2]));
  m.fromRotation = local[rig_.end[i]];
  m.toRotation = def_.JointRotation(rig_.end[i], &anglesDeg[3]);
  return m;
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
  if (phase_ == RisePhase::kSettle) rollSign_ = 0.0f, rollStage_ = RollStage::kNone, rollMoves_ = 0;
  const glm::vec3 face = chest * glm::vec3(0, 0, 1);
  // Face down already: Phase 0 goes straight to placing hands and feet.
  if (rollSign_ == 0.0f && glm::dot(face, ground_.normal) < -0.7f) return PlanPlace(r);
  if (rollSign_ == 0.0f) {
    // Roll over the side that is already down; flat on the back, the seed picks.
    const float leftDown = -glm::dot(chest * glm::vec3(1, 0, 0), ground_.normal);
    rollSign_ = std::fabs(leftDown) > 0.3f ? (leftDown > 0.0f ? 1.0f : -1.0f) : ((rng_() & 1u) ? 1.0f : -1.0f);
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
  if (pelvisRoll < kPushedRoll) stage = firstMove || !farFootSet ? RollStage::kTuck : RollStage::kPush;
  const bool pushedOff = pelvisRoll > kLiftOffRoll && !r.touching[far];
  if (stage == RollStage::kPush && pushedOff) stage = RollStage::kOver;
  rollStage_ = stage;

  heading_ = HeadingForward(r);
  Move move;
  move.phase = RisePhase::kRoll;
  move.from = MeasuredTrunk(r);
  auto set = [&](Limb limb, const LimbMove& m) { move.limbs[static_cast<int>(limb)] = m; };
  auto swing = [&](Limb limb, const std::array<float, 5>& anglesDeg) {
    LimbMove m = RollLimb(r, limb, anglesDeg);
    m.lift = static_cast<float>(spec_.style.stepHeightM);
    return m;
  };
  // The arm on the roll side goes overhead so the body rolls over the
  // shoulder instead of onto the arm. (From the back it was kept along the
  // side, a log roll, while the arm-out move dragged an overhead hand 50-75 cm;
  // since that move ends with the arm straight, alongside stood fewer:
  // bench/prone_variants-style harness, 48 supine at 30 s, 36 against 45.)
  set(nearArm, RollLimb(r, nearArm, {165, 15, 10, 0, 0}));
  set(nearLeg, RollLimb(r, nearLeg, {5, 0, 5, -20, 0}));
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
      const glm::vec3 toe = Project(ground_, hip - heading_ * (0.5f * legReach_) + farSide * (0.25f * legReach_));
      LimbMove foot = HoldLimb(r, farLeg, false);
      foot.toRotation = FootRotation(-heading_, 0.0f);
      foot.to = AnkleForToe(toe, foot.toRotation);
      // Drawn up from lying on its heel, the foot turns its sole down on the
      // way, so the heel sweeps well below the ankle: twice a step's lift.
      foot.lift = 2.0f * static_cast<float>(spec_.style.stepHeightM);
      set(farLeg, foot);
      set(nearArm, RollLimb(r, nearArm, {165, 15, 10, 0, 0}));
      set(farArm, RollLimb(r, farArm, {90, 0, 10, 0, 0}));
      break;
    }
    case RollStage::kPush:
      // The planted far foot holds its place while the trunk's goal turns on
      // over the near edge of the back: the leg's servos push the hip over.
      // (Less than half a turn per move: the goal is reached by slerp, which
      // would take the other way round.)
      move.name = "push off";
      move.duration = 0.8;
      move.to = RolledTrunk(r, glm::radians(140.0f) - pelvisRoll, 0.0f);
      move.rolledTo = kPushedRoll;
      {
        // Held where it is, a tucked foot left hovering (the pelvis half
        // turned, say) stayed up and the push went into the air.
        LimbMove foot = HoldLimb(r, farLeg, true);
        foot.to -= ground_.normal * Clearance(r, farLeg);
        set(farLeg, foot);
      }
      set(farArm, RollLimb(r, farArm, {90, 0, 10, 0, 0}));
      break;
    case RollStage::kOver: {
      // Past the side: the chest leads over onto the front, the top arm comes
      // down alongside (brought down beside the head, flexion 45, abduction
      // 45, elbow 90 deg, its hand slid 14-16 cm as the chest came down onto
      // the front: 12 of 12 side_left starts; alongside, 4 slid 5-6 cm). A foot
      // still planted from the push holds the pelvis from falling back, so the
      // chest can lead by the spine's full twist.
      move.name = "over";
      move.duration = 0.9;
      const bool pushing = planted_[static_cast<int>(farLeg)];
      move.to = RolledTrunk(r, 0.0f, glm::radians(pushing ? 65.0f : 30.0f));
      set(farArm, swing(farArm, {0, 10, 10, 0, 0}));
      set(farLeg, pushing ? HoldLimb(r, farLeg, true) : swing(farLeg, {40, -10, 60, -20, 0}));
      // The near leg straightens under the turning pelvis with a lift: held to
      // its angles alone its ankle's goal went 5-8 cm into the ground, and the
      // foot was pushed along it (side starts: feet 8.2 -> 6.9 cm median).
      set(nearLeg, swing(nearLeg, {5, 0, 5, -20, 0}));
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
      set(farArm, swing(farArm, {0, 10, 10, 0, 0}));
      set(nearArm, swing(nearArm, {165, 60, 10, 0, 0}));
      set(nearLeg, RollLimb(r, nearLeg, {0, 0, 90, -50, 0}));
      set(farLeg, RollLimb(r, farLeg, {0, 0, 90, -50, 0}));
      break;
  }
  return move;
}

std::optional<RiseController::Move> RiseController::PlanArmOut(const BodyReading& r, RollStage stage) const {
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
    const LimbMove out = RollLimb(r, limb, turn ? turnedThere : outToSide);
    const bool needed = turn ? out.from.y > kArmOutAbduction && out.from.x > 0.0f : out.from.x > kOverheadArm;
    if (needed) move.limbs[i] = out, any = true;
  }
  if (!any) return std::nullopt;
  return move;
}

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
      const std::vector<glm::quat> local = LocalRotations(def_.skeleton, pose.worldRotations);
      float root[3] = {}, hinge[3] = {};
      def_.JointAngles(rig_.upper[i], local[rig_.upper[i]], root);
      def_.JointAngles(rig_.lower[i], local[rig_.lower[i]], hinge);
      m = RollLimb(r, hand, {root[0], root[1], hinge[0], 0, 0});
      m.toRotation = local[rig_.end[i]];
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
    const glm::vec3 toe = Project(ground_, hip - heading_ * (0.9f * legReach_) + left * side * (kCrawlHalfStance - hipHalf));
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

float RiseController::HandsAhead(const BodyReading& r, Limb hand) const {
  // From the feet's toe edges (where feet on their toes press), along the heading.
  const glm::vec3 toes = 0.5f * (ContactPoint(r, Limb::kFootLeft) + ContactPoint(r, Limb::kFootRight));
  return glm::dot(ContactPoint(r, hand) - toes, heading_);
}

float RiseController::HandsAhead(const BodyReading& r) const {
  return 0.5f * (HandsAhead(r, Limb::kHandLeft) + HandsAhead(r, Limb::kHandRight));
}

float RiseController::StanceDrift(const BodyReading& r, Limb foot) const {
  const glm::vec3 left = glm::normalize(glm::cross(kUp, heading_));
  const glm::vec3 hands = 0.5f * (ContactPoint(r, Limb::kHandLeft) + ContactPoint(r, Limb::kHandRight));
  const float side = IsLeft(foot) ? 1.0f : -1.0f;
  return std::fabs(glm::dot(ContactPoint(r, foot) - hands, left) - side * kCrawlHalfStance);
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
  if (move_.name == "heels down" && FeetRegion(r).SignedDistance(Ground(r.com)) >= kSitBackReach) {
    return {HandsAhead(r, Limb::kHandLeft) >= HandsAhead(r, Limb::kHandRight) ? Limb::kHandLeft : Limb::kHandRight};
  }
  // A foot far to the side of its place steps back across first: every step
  // corrects its own foot's width, but the walk-in steps only the rear foot,
  // and a body bent sideways as it came up, both feet off to one side of the
  // hands, walked its rear foot in and out until the time ran out while the
  // other stayed 0.7 m wide (stress seed 33).
  const float driftLeft = StanceDrift(r, Limb::kFootLeft), driftRight = StanceDrift(r, Limb::kFootRight);
  if (std::max(driftLeft, driftRight) > kMaxStanceDrift) return {driftLeft >= driftRight ? Limb::kFootLeft : Limb::kFootRight};
  // By the ankles, as the step length measures them (toe edges can sit askew).
  const float stagger = glm::dot(r.jointPositions[rig_.end[2]] - r.jointPositions[rig_.end[3]], heading_);
  const Limb rear = stagger < 0.0f ? Limb::kFootLeft : Limb::kFootRight;
  const float handsAhead = HandsAhead(r);
  if (handsAhead <= walkIn_.handsAhead + kMinFootStep || feetIn_) {
    if (std::fabs(stagger) > kMinFootStep) return {rear};
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
  const float margin = std::max(kFootLiftHandLineMargin, shouldersAhead - kShoulderLead);
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
    for (int k = 0; k < 30 && stance.SignedDistance(goal) > -kShiftMargin; ++k) goal += 0.1f * (centre - goal);
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
    plan.balanceMargin = kShiftMargin;
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
    if (stance.SignedDistance(Ground(planned)) < -kLiftMargin) return move;
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
  const glm::vec3 back = heelsUp ? glm::vec3(0.0f) : heading_ * kSitBackBehindSoles;
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
  if ((steady && (comToFeet < -kRiseMargin || (squatting && comToFeet < kSitBackReach))) ||
      crawlSteps_ >= kMaxCrawlSteps) {
    return PlanRise(r);
  }
  // Near the soles but not steady (rocking, often with the hands lifted by the
  // heels coming down), the body holds still on all fours a moment and looks
  // again. Hand steps from there fell back in 10 of 19 failed prone starts;
  // holding, bench/prone_variants 72 (prone 20 s, rolled 30 s) stood 162 -> 210
  // of 288, and prone clips passing every bar went 15 -> 21 of 40.
  if (squatting && !steady && comToFeet < kSitBackReach) {
    // Still not steady after holding: the CoM rests just off the soles (a
    // heels-down on a slope left it 3 cm ahead of the toe edges), and holding
    // again only ran out the crawl's steps into a rise that fell on its face.
    // Sitting back takes it over them.
    if (move_.name == "steady") return FinishCrawl(r);
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
    if (StanceWithout(r, limb).SignedDistance(Ground(r.com)) < -kLiftMargin) {
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
  ++crawlSteps_;
  const Limb limb = *step;
  const int i = static_cast<int>(limb);
  const glm::vec3 left = glm::normalize(glm::cross(kUp, heading_));
  Move best;
  // A limb left in the air by a short step only goes down where it is.
  const bool putDown = Clearance(r, limb) > kLandedClearance;
  putDowns_ = putDown ? putDowns_ + 1 : 0;
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
      const float back = putDown ? 0.0f : kHandStepBack;
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
      across -= ground_.normal * glm::dot(across, ground_.normal);
      m.to = m.from + across - ground_.normal * (Clearance(r, limb) + kLandingReach);
      m.lift = 0.0f;
      move.landing = i;
    } else {
      const float handsAhead = HandsAhead(r);
      // Feet come in side by side: a step ends at most kFootLead ahead of the other foot.
      const Limb other = limb == Limb::kFootLeft ? Limb::kFootRight : Limb::kFootLeft;
      const float behindOther = glm::dot(r.jointPositions[rig_.end[static_cast<int>(other)]] - r.jointPositions[rig_.end[i]], heading_);
      nominalFootStep = std::clamp(std::min(handsAhead - walkIn_.handsAhead, behindOther + kFootLead), 0.05f, walkIn_.footStep);
      // In: the rear foot only comes up beside the other.
      if (handsAhead <= walkIn_.handsAhead + kMinFootStep) nominalFootStep = std::clamp(behindOther, 0.0f, walkIn_.footStep);
      const float length = fraction * nominalFootStep;
      // From the ankle, not the toe: with no hip twist the foot's yaw follows the
      // leg, so its toe can sit to one side, and stepping from there walked
      // the feet apart.
      m.toRotation = FootRotation(heading_, glm::radians(60.0f));
      const glm::vec3 toe = Project(ground_, r.jointPositions[rig_.end[i]] + m.toRotation * toeLocal_);
      // Back to the stance width either side of the hands' midline: feet that
      // keep their own line splay apart step by step.
      const glm::vec3 hands = 0.5f * (ContactPoint(r, Limb::kHandLeft) + ContactPoint(r, Limb::kHandRight));
      const float side = IsLeft(limb) ? 1.0f : -1.0f;
      const glm::vec3 across = left * (side * kCrawlHalfStance - glm::dot(toe - hands, left));
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
    feetIn_ = nominalFootStep >= 2.0f * kMinFootStep && glm::dot(best.limbs[i].to - best.limbs[i].from, heading_) < kMinFootStep;
  }
  return best;
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
  glm::vec3 pelvis(0.0f);
  for (int leg = 2; leg < 4; ++leg) {
    const float shinLength = glm::length(def_.skeleton.joints[rig_.end[leg]].restOffset);
    const float thighLength = glm::length(def_.skeleton.joints[rig_.lower[leg]].restOffset);
    auto along = [&](float pitch) { return kUp * std::cos(pitch) + heading_ * std::sin(pitch); };
    const std::array<float, 2>& from = move.legPitches[leg - 2];
    const glm::vec3 ankle = r.jointPositions[rig_.end[leg]];
    pelvis += 0.5f * (ankle + shinLength * along(from[0] * (1.0f - e)) + thighLength * along(from[1] * (1.0f - e)));
  }
  return pelvis;
}

RiseController::Move RiseController::PlanRise(const BodyReading& r) {
  Move move;
  move.name = "rise";
  move.phase = RisePhase::kRise;
  move.duration = 2.6;
  move.keepComOverFeet = true;
  for (int leg = 2; leg < 4; ++leg) move.legPitches[leg - 2] = LegPitches(r, leg);
  move.from = MeasuredTrunk(r);
  move.to.pelvisRotation = move.to.chestRotation = TrunkRotation(heading_, 0.5f * kPi);
  move.to.pelvis = FeetCentre(r) + kUp * standPelvisHeight_ * 0.985f;
  for (int i = 0; i < 2; ++i) {
    LimbMove& m = move.limbs[i];
    const glm::quat chest = r.jointRotations[rig_.chest];
    m.mode = LimbMode::kBody;
    m.from = glm::inverse(chest) * (r.jointPositions[rig_.end[i]] - r.jointPositions[rig_.upper[i]]);
    m.fromRotation = glm::inverse(chest) * r.jointRotations[rig_.end[i]];
    m.to = def_.skeleton.BindPositions()[rig_.end[i]] - def_.skeleton.BindPositions()[rig_.upper[i]];
    m.toRotation = glm::quat(1, 0, 0, 0);
    m.span = 0.6f;
  }
  for (int i = 2; i < 4; ++i) {
    move.limbs[i] = ToePivot(r, static_cast<Limb>(i), 0.0f);
    move.limbs[i].span = 0.5f;
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
  const bool holding = hasMove_ && (move_.phase == RisePhase::kRise || move_.phase == RisePhase::kStand);
  const glm::vec3 offset = balanceOffset_;
  const float lean = balanceLean_;
  const TrunkPose held = move_.to;
  Move move = PlanRise(r);
  if (holding) {
    move.from = held;
    move.legPitches = {};
    balanceOffset_ = offset;
    balanceLean_ = lean;
  }
  move.name = "stand";
  move.phase = RisePhase::kStand;
  move.duration = 1.0;
  for (int i = 0; i < 2; ++i) move.limbs[i].from = move.limbs[i].to, move.limbs[i].fromRotation = move.limbs[i].toRotation;
  if (standTime_ < 0.0) standTime_ = r.time;
  return move;
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

void RiseController::FeedForward(const BodyReading& r, const glm::vec3& comGoal, std::vector<glm::vec3>& out) const {
  const Skeleton& sk = def_.skeleton;
  out.assign(sk.joints.size(), glm::vec3(0.0f));
  // Only once the body is up on its hands and feet are the supports known;
  // lying, the trunk rests on the ground and needs no help.
  if (phase_ == RisePhase::kSettle || phase_ == RisePhase::kRoll || phase_ == RisePhase::kPlace || !hasMove_) return;

  const glm::vec3 gravity(0.0f, -9.81f, 0.0f);
  // Phase 2 balances on the feet alone: the ground's push is aimed so the CoM
  // accelerates toward the balance point. For an inverted pendulum that push
  // presses at the centre of pressure h a / g behind the CoM's ground point
  // (a the wanted acceleration, h the CoM's height), inside the feet. Pressing
  // right below the CoM instead only holds the weight: a body drifting off
  // the balance point at the end of a rise kept drifting until it fell.
  glm::vec3 pressure = r.com, balanceForce(0.0f);
  if (phase_ == RisePhase::kRise || phase_ == RisePhase::kStand) {
    glm::vec3 accel = kBalanceStiffness * (BalancePoint(r) - r.com) - kBalanceDamping * r.comVelocity;
    accel.y = 0.0f;
    const glm::vec2 wanted = Ground(r.com - accel * (Height(ground_, r.com) / 9.81f));
    const SupportPolygon feet = FeetRegion(r);
    const glm::vec2 cop = feet.SignedDistance(wanted) < 0.0f ? wanted : feet.Closest(wanted);
    pressure = Project(ground_, glm::vec3(cop.x, 0.0f, cop.y));
    // The horizontal push that goes with that pressure point (clipped to the
    // feet, it may be less than wanted): m g / h times the CoM's offset from it.
    balanceForce = totalMass_ * 9.81f / std::max(0.2f, Height(ground_, r.com)) * Horizontal(r.com - pressure);
    balanceForce -= ground_.normal * glm::dot(balanceForce, ground_.normal);
  }
  // Share the weight among planted, touching supports: the least-norm weights
  // whose weighted centre is the pressure point, negatives dropped.
  std::array<glm::vec3, kLimbCount> point{};
  std::array<float, kLimbCount> share{};
  std::vector<int> supports;
  for (int i = 0; i < kLimbCount; ++i) {
    if (!planted_[i] || !r.touching[i]) continue;
    point[i] = SupportPoint(r, static_cast<Limb>(i), pressure);
    supports.push_back(i);
  }
  if (supports.empty()) return;
  const glm::vec2 c = Ground(pressure);
  for (int pass = 0; pass < 3; ++pass) {
    // Solve A A^T y = b, w = A^T y with A = [1; x; z] over the supports.
    glm::mat3 normal(0.0f);
    for (int i : supports) {
      const glm::vec3 a(1.0f, point[i].x, point[i].z);
      normal += glm::outerProduct(a, a);
    }
    const float det = glm::determinant(normal);
    bool clipped = false;
    if (std::fabs(det) > 1e-8f) {
      const glm::vec3 y = glm::inverse(normal) * glm::vec3(1.0f, c.x, c.y);
      for (int i : supports) share[i] = glm::dot(y, glm::vec3(1.0f, point[i].x, point[i].z));
    } else {
      for (int i : supports) share[i] = 1.0f / static_cast<float>(supports.size());
    }
    for (size_t k = 0; k < supports.size();) {
      if (share[supports[k]] < 0.0f) share[supports[k]] = 0.0f, supports.erase(supports.begin() + k), clipped = true;
      else ++k;
    }
    if (!clipped || supports.empty()) break;
  }
  float total = 0.0f;
  for (int i : supports) total += share[i];
  if (total <= 0.0f) return;
  std::array<glm::vec3, kLimbCount> force{};
  // On hands and feet, a virtual force on the CoM (Coros et al. 2010) pulls it
  // toward the plan's CoM: a spring-damper shared among the supports like the
  // weight, its ground forces turned into joint torques with the rest.
  glm::vec3 virtualForce = balanceForce;
  if (OnHandsAndFeet(phase_)) {
    virtualForce = totalMass_ * (kVirtualStiffness * (comGoal - r.com) - kVirtualDamping * r.comVelocity);
    virtualForce -= ground_.normal * glm::dot(virtualForce, ground_.normal);
    const float limit = kMaxVirtualForce * totalMass_ * 9.81f;
    if (glm::length(virtualForce) > limit) virtualForce *= limit / glm::length(virtualForce);
  }
  for (int i : supports) force[i] = (virtualForce - gravity * totalMass_) * (share[i] / total);

  for (int j = 1; j < sk.JointCount(); ++j) {
    if (!sk.joints[j].hasBox) continue;
    const glm::vec3 pivot = r.jointPositions[j];
    glm::vec3 torque(0.0f);
    for (int s : subtree_[j]) {
      if (!sk.joints[s].hasBox) continue;
      const glm::vec3 centre = r.jointPositions[s] + r.jointRotations[s] * sk.joints[s].box.center;
      torque -= glm::cross(centre - pivot, gravity * def_.bones[s].massKg);
      for (int i = 0; i < kLimbCount; ++i) {
        if (rig_.end[i] == s && glm::length(force[i]) > 0.0f) torque -= glm::cross(point[i] - pivot, force[i]);
      }
    }
    out[j] = torque;
  }
}

// ---------------------------------------------------------------------------
// The control step

void RiseController::Update(const BodyReading& reading, ServoTargets& out) {
  RISE_ASSERT(static_cast<int>(reading.jointPositions.size()) == def_.skeleton.JointCount());
  const double dt = hasMove_ || phase_ != RisePhase::kSettle ? reading.time - lastTime_ : 0.0;
  lastTime_ = reading.time;

  if (phase_ == RisePhase::kSettle && !hasMove_) {
    // Hold whatever pose the body fell into until it has come to rest.
    const float restSpeed = givingUp_ ? kFinalRestSpeed : kRestSpeed;
    const bool still = reading.maxBodySpeed < restSpeed && reading.maxAngularSpeed < kRestSpin;
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
    // Down again: wait for rest and start over, kMaxRetries times.
    givingUp_ = retries_ == kMaxRetries;
    retries_ = std::min(retries_ + 1, kMaxRetries);
    hasMove_ = false;
    phase_ = RisePhase::kSettle;
    restSince_ = -1.0;
    standTime_ = -1.0;
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
      if (glm::length(crawlOffset_) > kMaxCrawlOffset) crawlOffset_ *= kMaxCrawlOffset / glm::length(crawlOffset_);
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
    if (move_.name == "sit back" && FeetRegion(reading).SignedDistance(Ground(reading.com)) < -kRiseMargin) progress_ = 1.0f;
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
      PlanNext(reading);
    } else if (progress_ >= 1.0f && (lag < kGateStop || rolling)) {
      if (phase_ == RisePhase::kStand) {
        finished_ = Standing(reading.time) && reading.maxBodySpeed < kRestSpeed;
        if (!finished_) PlanNext(reading);
      } else {
        PlanNext(reading);
      }
    }
  }

  if (hasMove_ && (move_.name == "sit back" || move_.name == "heels down")) ReleaseLiftedHands(reading);
  // The pose to track.
  out.local.assign(def_.skeleton.joints.size(), glm::quat(1, 0, 0, 0));
  out.gainScale.assign(def_.skeleton.joints.size(), 1.0f);
  if (!hasMove_) {
    FeedForward(reading, reading.com, out.feedForward);
    // Settling: servos hold the joints where they are, softly.
    out.local = LocalRotations(def_.skeleton, reading.jointRotations);
    std::fill(out.gainScale.begin(), out.gainScale.end(), 0.3f);
  } else {
    std::optional<BodyPose> solved;
    const PoseGoal goal = GoalAt(move_, progress_, reading, true, &solved);
    pelvisGoal_ = goal.pelvisPosition;
    const BodyPose pose = solved ? std::move(*solved) : SolveBodyPose(def_.skeleton, rig_, goal);
    out.local = LocalRotations(def_.skeleton, pose.worldRotations);
    // The plan's CoM is only needed for the virtual force on hands and feet.
    const glm::vec3 comGoal = OnHandsAndFeet(phase_) ? PoseCom(GoalAt(move_, progress_, reading, false)) : reading.com;
    FeedForward(reading, comGoal, out.feedForward);
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
  trace_.heading = heading_;
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
