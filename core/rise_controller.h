// SPDX-License-Identifier: MIT
// The rise controller (Kenwright, "Real-Time Character Rise Motions"): reads the
// simulated body, plans where the hands, feet and CoM go with the point-mass
// model, maps the plan to a full-body pose by IK, and hands the pose to the PD
// servos. It never moves the body itself; the servos' torques do.
//
// The plan is a chain of moves. Each move blends the trunk (pelvis position,
// pelvis and chest orientation) from where the body *is* when the move starts
// to a goal, while each hand and foot is held where it touches, swung along a
// Bezier path to a new place, or carried with the trunk. A move is planned
// from the measured state when the previous one ends, so errors and pushes
// are corrected by the next plan (the paper's feedback loop); a move whose
// tracking error grows is slowed down, and a fall sends the plan back to the
// phase that can recover from it.
//
// Phases (names as written into the clip's metadata):
//   settle  wait until the fallen body is at rest
//   roll    Phase 0: roll onto the front (from the back, a side or any pose)
//   place   Phase 0: hands beside the chest, toes tucked under (and a rise
//           tipping forward off its toes catches itself on its hands here)
//   push    Phase 0: push up onto hands and feet
//   crawl   Phase 1: shift the CoM toward the feet; move the free hand beside
//           the CoM; swap the support hand; repeat until the CoM is over the feet
//   rise    Phase 2: release the hands, extend the legs, keep the CoM over the feet
//   stand   upright, arms at the sides, still
//
// Its definitions are split by what they hold: rise_controller.cpp (the state
// machine and the control step), rise_roll.cpp, rise_place.cpp (place and
// push), rise_crawl.cpp and rise_stand.cpp (rise and stand) plan the phases'
// moves; rise_pose_goal.cpp turns a move into the pose the servos track;
// rise_body_geometry.cpp measures the body; rise_feed_forward.cpp adds the
// gravity compensation and virtual forces. rise_controller_detail.h holds what
// they share.
#pragma once

#include "core/biped_def.h"
#include "core/body_pose_ik.h"
#include "core/body_reading.h"
#include "core/rise_spec.h"
#include "core/support_polygon.h"
#include "physics/collide.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <optional>
#include <random>
#include <string>
#include <vector>

namespace rise {

enum class RisePhase { kSettle, kRoll, kPlace, kPush, kCrawl, kRise, kStand };
const char* RisePhaseName(RisePhase phase);

// One line of the debug trace, written per control step.
struct TraceSample {
  double time = 0.0;
  RisePhase phase = RisePhase::kSettle;
  std::string move;
  glm::vec3 com{0.0f};
  glm::vec3 comVelocity{0.0f};  // m/s
  glm::vec3 comGoal{0.0f};
  // Where the feed-forward aims the body's weight, on the ground: in the rise
  // and the stand the balance's centre of pressure, otherwise under the CoM.
  glm::vec3 pressure{0.0f};
  glm::vec3 heading{0.0f, 0.0f, 1.0f};  // the way the plan faces the body, along the ground
  SupportPolygon support;
  float feetDistance = 0.0f;  // CoM ground projection to the feet's soles, m (negative inside)
  std::array<glm::vec3, kLimbCount> limbTargets{};
  std::array<glm::vec3, kLimbCount> limbPositions{};  // measured wrist/ankle
  std::array<float, kLimbCount> clearance{};           // lowest corner of the hand/foot box above the ground, m
  std::array<bool, kLimbCount> touching{};
  std::array<bool, kLimbCount> planted{};
  std::array<float, kLimbCount> load{};  // share of the weight the feed-forward puts on each hand/foot
  float trackingError = 0.0f;
  // The roll (Phase 0): the side the body rolls over (+1 its left, -1 its right;
  // 0 before one is chosen) and how far pelvis and chest have turned toward it
  // from lying on the back, rad (0 on the back, pi/2 on that side, pi on the front).
  float rollSide = 0.0f;
  float pelvisRoll = 0.0f, chestRoll = 0.0f;
  // Per skeleton joint: the magnitude of the motor torque over the step that
  // follows this sample, N*m (0 where no motor: the root and the end joints).
  // Filled by GenerateClip.
  std::vector<float> jointTorques;
};

class RiseController {
 public:
  // With tracing, each Update also fills LastTrace() (an IK solve and two
  // support hulls a step, which a clip without a trace does not pay for).
  RiseController(const BipedDef& def, const RiseSpec& spec, bool tracing = false);

  // One control step: reads the body, writes the servo targets.
  void Update(const BodyReading& reading, ServoTargets& out);

  // How the body's weight is shared among the planted supports: their centre
  // of pressure and each one's part (see FeedForward).
  struct WeightShare {
    glm::vec3 pressure{0.0f};
    std::array<float, kLimbCount> share{};
  };
  // The settle's servo targets: every joint held softly where it is, so a body
  // not yet at rest sinks into the pose it lies in. GenerateClip holds a
  // laid-down start so until it lies still, before the clip's first frame.
  WeightShare HoldAsItLies(const BodyReading& reading, ServoTargets& out) const;
  // Under the rest speeds the settle waits for (the paper rises from rest);
  // the body is at rest once it has stayed so for kRestHold.
  static bool Still(const BodyReading& reading);
  static constexpr double kRestHold = 0.25;  // s

  RisePhase Phase() const { return phase_; }
  // True once the body has stood still, upright, long enough to end the clip.
  bool Finished() const { return finished_; }
  // True if the body is in the stand phase and has held it for `seconds` by
  // `time`, still or not (a body that sways on a slope never finishes, yet it
  // stood). The clip ends early once it has held it kStandHold and is still.
  bool StandingFor(double time, double seconds) const;
  // Time the body first reached the stand phase and held it; < 0 before.
  double StandTime() const { return standTime_; }
  // Limbs the plan treats as planted supports right now.
  const std::array<bool, kLimbCount>& Planted() const { return planted_; }
  const TraceSample& LastTrace() const;
  // How many times a fall sent the plan back to an earlier phase.
  int Retries() const { return retries_; }
  // True once the body has fallen after its last retry and come to rest: it
  // will not get up, and the clip can end.
  bool GaveUp() const { return gaveUp_; }

 private:
  struct TrunkPose {
    glm::vec3 pelvis{0.0f};
    glm::quat pelvisRotation{1.0f, 0.0f, 0.0f, 0.0f};
    glm::quat chestRotation{1.0f, 0.0f, 0.0f, 0.0f};
  };
  enum class LimbMode { kWorld, kToePivot, kBody, kJoint };
  // The roll's moves, in order (see PlanRoll).
  enum class RollStage { kNone, kTuck, kPush, kOver, kLie, kArmOut, kArmTurn };
  struct LimbMove {
    LimbMode mode = LimbMode::kWorld;
    // wrist/ankle (kWorld), toe point (kToePivot), in the trunk frame (kBody), or the
    // root's two angles and the hinge angle, rad (kJoint; its rotations are the end's local ones)
    glm::vec3 from{0.0f}, to{0.0f};
    glm::quat fromRotation{1.0f, 0.0f, 0.0f, 0.0f}, toRotation{1.0f, 0.0f, 0.0f, 0.0f};
    float lift = 0.0f;               // swing height; 0 keeps the path straight
    float delay = 0.0f, span = 1.0f; // fraction of the move over which the limb travels
    float turnDelay = 0.0f;          // fraction of the span the end waits before it turns
    bool planted = false;            // a support contact during this move
  };
  struct Move {
    std::string name;
    RisePhase phase = RisePhase::kSettle;
    double duration = 1.0;            // s at speed 1
    TrunkPose from, to;
    std::array<LimbMove, kLimbCount> limbs;
    bool keepComOverFeet = false;     // re-centre the pelvis so the CoM stays over the feet
    std::array<std::array<float, 2>, 2> legPitches{};  // rising: each leg's shin and thigh pitch at the start
    int landing = -1;                 // a limb being put down: the move ends when it touches
    float rolledTo = 0.0f;            // rolling: the move ends once the pelvis has turned this far (RollAngle), rad
  };

  // Planning (each returns the next move from the measured state).
  void PlanNext(const BodyReading& reading);
  Move PlanRoll(const BodyReading& reading);
  // How far a trunk segment has turned from lying on its back toward lying on
  // its front about its own long axis, rolling toward rollSign_'s side: 0 on the
  // back, pi/2 on that side, pi on the front; in [-pi/2, 3 pi/2).
  float RollAngle(const glm::quat& segment) const;
  // The measured trunk turned on by `angle` about its long axis toward the roll
  // side, pivoting on the edge it rolls over, the chest turned `twist` further.
  TrunkPose RolledTrunk(const BodyReading& reading, float angle, float twist) const;
  // After a roll, an arm lying overhead comes out to the side (kArmOut), then
  // turns there to be swung down beside the chest (kArmTurn); none to move: nullopt.
  // raisedOnly: the arms whose hands are off the ground come out, wherever they lie.
  std::optional<Move> PlanArmOut(const BodyReading& reading, RollStage stage, bool raisedOnly = false) const;
  Move PlanPlace(const BodyReading& reading);
  Move PlanHandsDown(const BodyReading& reading) const;  // the hands left hovering by the place come straight down
  // A rise tipping forward off its feet: the hands come straight down to catch it.
  Move PlanCatch(const BodyReading& reading) const;
  Move PlanPush(const BodyReading& reading);
  // The end of the crawl: heels down, then the CoM back over the flat soles.
  Move FinishCrawl(const BodyReading& reading);
  Move PlanCrawl(const BodyReading& reading);
  // Both soles flat on the ground.
  bool SolesDown(const BodyReading& reading) const;
  // A move that puts the CoM inside the support of all limbs but `lifted`, if
  // a reachable pose does.
  std::optional<Move> PlanShift(const BodyReading& reading, Limb lifted) const;
  // The limbs Phase 1 may move next, preferred first (none: hands and feet are together).
  std::vector<Limb> StepCandidates(const BodyReading& reading) const;
  // How far a hand is ahead of the feet's toe edges along the heading, m.
  float HandsAhead(const BodyReading& reading, Limb hand) const;
  // The same for the hands' middle.
  float HandsAhead(const BodyReading& reading) const;
  // How far `point` must move across the heading (toward the left, m) to lie
  // on `foot`'s side of the crawl stance, kCrawlHalfStance beside the hands' midline.
  float StanceAcross(const BodyReading& reading, Limb foot, const glm::vec3& point) const;
  // Ground hull of the contact points of every limb but one.
  SupportPolygon StanceWithout(const BodyReading& reading, Limb lifted) const;
  float CrawlComHeight(const BodyReading& reading) const;
  // Where the CoM is held while a foot steps.
  glm::vec3 FootLiftCom(const BodyReading& reading, Limb foot) const;
  // Whether the move's end pose puts every held or moving hand and foot on its place.
  bool Reachable(const Move& move) const;
  // Whether a pose goal puts every held or moving hand and foot of the move on its place.
  bool LimbsReach(const Move& move, const PoseGoal& goal, BodyPose* solved = nullptr) const;
  // A move on both hands and both feet, all held where they are.
  Move OnAllFours(const BodyReading& reading, const char* name, double duration) const;
  // Phase 2's move from the measured body: trunk upright over the feet, arms to the sides.
  Move RiseMove(const BodyReading& reading) const;
  // The rise's start: RiseMove, with the balance feedback begun afresh.
  Move PlanRise(const BodyReading& reading);
  std::array<float, 2> LegPitches(const BodyReading& reading, int leg) const;
  // The pelvis of a rising move at eased progress e: on the legs straightening from the feet.
  glm::vec3 RisingPelvis(const Move& move, float e, const BodyReading& reading) const;
  Move PlanStand(const BodyReading& reading);

  // Geometry of the measured body.
  TrunkPose MeasuredTrunk(const BodyReading& reading) const;
  LimbMove HoldLimb(const BodyReading& reading, Limb limb, bool planted) const;
  // A limb swung to a pose set by its joints' angles in degrees (the root's
  // two, the hinge's, the end's two), along the joints' own arcs.
  LimbMove SwingToAngles(const BodyReading& reading, Limb limb, const std::array<float, 5>& anglesDeg) const;
  // A limb swung in its joints from where it is to its angles in `pose`, its end
  // turned to the pose's: a long swing whose straight path would pass the root's
  // two angles into another branch of their solution.
  LimbMove SwingInJoints(const BodyReading& reading, Limb limb, const BodyPose& pose) const;
  // A planted foot turning about its toe edge, where it is, to the given heel lift.
  LimbMove ToePivot(const BodyReading& reading, Limb foot, float heelLift) const;
  glm::vec3 FeetCentre(const BodyReading& reading) const;
  SupportPolygon FeetRegion(const BodyReading& reading) const;
  // Where Phase 2 keeps the CoM's ground projection.
  glm::vec3 BalancePoint(const BodyReading& reading) const;
  SupportPolygon SupportRegion(const BodyReading& reading) const;
  // Where the CoM would come to rest as an inverted pendulum: CoM + velocity / omega.
  glm::vec3 CapturePoint(const BodyReading& reading) const;
  glm::vec3 HeadingForward(const BodyReading& reading) const;
  // Lying on the front: the chest faces the ground (within about 45 deg).
  bool FaceDown(const BodyReading& reading) const;

  // Placement helpers.
  glm::quat TrunkRotation(const glm::vec3& forward, float pitch) const;
  glm::quat FootRotation(const glm::vec3& forward, float heelLift) const;
  glm::quat HandRotation(Limb hand, const glm::vec3& fingers) const;
  glm::quat PlantedHandRotation(Limb hand) const;
  float HandSwingLift(Limb hand) const;
  // The wrist of a hand lying with `rotation` whose wrist is above groundPoint.
  glm::vec3 WristAbove(Limb hand, const glm::vec3& groundPoint, const glm::quat& rotation) const;
  glm::vec3 WristForPalm(Limb hand, const glm::vec3& palmPoint, const glm::quat& rotation) const;
  glm::vec3 AnkleForToe(const glm::vec3& toePoint, const glm::quat& rotation) const;
  // Sets move.to (and with freeHeels the heel lift of feet pivoting on their
  // toes) for a CoM goal, keeping every held hand and foot in reach.
  void PlanTrunk(Move& move, const glm::vec3& comGoal, const std::array<bool, 2>& bearingHands,
                 bool freeHeels = false) const;

  // Evaluation of the current move at progress s in [0, 1].
  // balance: apply Phase 2's balance (lean and slide) to moves that keep the CoM over the feet.
  // solved, if given, receives the pose of the returned goal when the balance
  // search already solved it (else it is left empty).
  PoseGoal GoalAt(const Move& move, float s, const BodyReading& reading, bool balance = true,
                  std::optional<BodyPose>* solved = nullptr) const;
  // The lean in [lo, hi] (within 0..kMaxBalanceLean) that brings the pose's CoM
  // to the balance point along the heading, or the end of the band nearer it.
  float BalanceLean(const Move& move, float s, const BodyReading& reading, float lo, float hi) const;
  void Lean(const Move& move, float s, float lean, PoseGoal& goal) const;
  bool FeetFlat(const PoseGoal& goal) const;
  glm::vec3 PoseCom(const PoseGoal& goal) const;
  glm::vec3 PoseCom(const BodyPose& pose) const;
  void EvaluateLimb(const LimbMove& limb, Limb which, float s, const PoseGoal& trunkGoal, LimbGoal& out) const;
  // Raises the goal of a hand or foot in a world-space swing that has not yet
  // caught up with its spot, so it comes down only once over it, its lowest
  // point kept off the ground on the way.
  void HoldAloftUntilOver(const Move& move, const BodyReading& reading, PoseGoal& goal) const;
  // A planted hand that sitting back lifts off the ground goes straight up from where it is.
  void ReleaseLiftedHands(const BodyReading& reading);
  // A foot the over holds planted from the push off lets go once it skids: lifted where it is.
  void LetGoSkiddingFeet(const BodyReading& reading);
  // The rise's hands, held where they are planted, let go once the CoM is
  // over the soles (or the hand has left the ground): each lifts off
  // (LiftOff), then goes to the side.
  void LetGoOverFeet(const BodyReading& reading);
  // A hand's move from where it is to its place at the side in the bind pose,
  // starting at fraction delay of the move.
  LimbMove ArmToSide(const BodyReading& reading, Limb hand, float delay) const;
  // A hand or foot on the ground let go: straight up from where it is, before it swings.
  LimbMove LiftOff(const BodyReading& reading, Limb limb) const;
  void StartMove(Move move);
  // A fall: back to settle, to wait for rest and try again.
  void StartOver();
  bool Fallen(const BodyReading& reading) const;
  // Crouched or standing on both feet with the CoM over them (sets the heading).
  bool OnItsFeet(const BodyReading& reading);
  // Gravity compensation and support forces through the joints (Jacobian
  // transpose): the torque each joint needs to hold its distal part and pass
  // on the ground forces of the supports below it, with the body's weight
  // shared among the planted supports so their centre of pressure is under
  // the CoM (on the feet alone, where it accelerates the CoM toward the
  // balance point). Internal torques only: nothing pushes the body from outside.
  // Returns how it shared the weight, for the trace.
  WeightShare FeedForward(const BodyReading& reading, const glm::vec3& comGoal, std::vector<glm::vec3>& out) const;
  // Height of the lowest corner of a hand or foot above the ground, m.
  float Clearance(const BodyReading& reading, Limb limb) const;
  // A length tuned on a kTunedHeight body ("m, Scaled"), for this body.
  float Scaled(float metres) const { return lengthScale_ * metres; }
  // Where a hand or foot touches the ground: the heel of a hand, the toe edge
  // of a foot on its toes, the middle of a flat sole.
  glm::vec3 ContactPoint(const BodyReading& reading, Limb limb) const;
  // Where a planted hand or foot is to press on the ground for the body's
  // centre of pressure to be at `pressure`, for FeedForward.
  glm::vec3 SupportPoint(const BodyReading& reading, Limb limb, const glm::vec3& pressure) const;

  const BipedDef& def_;
  RiseSpec spec_;
  BodyRig rig_;
  std::vector<std::vector<int>> subtree_;  // per skeleton joint: itself and every joint below it
  physics::PlaneShape ground_;  // the terrain (core/biped.h GroundPlane)
  std::mt19937 rng_;
  float totalMass_ = 0.0f;
  float armReach_ = 0.0f, legReach_ = 0.0f, standPelvisHeight_ = 0.0f;
  float standComHeight_ = 0.0f, crawlComHeight_ = 0.0f, shoulderHalfWidth_ = 0.0f;
  // This body's height over kTunedHeight, at most 1: Scaled lengths shrink with it.
  float lengthScale_ = 1.0f;
  // The walk-in's lengths for this body, m: kFootWalkDistance, kPikeStart and kFootStep scaled
  // with its height, and kSitBackBehindSoles Scaled.
  struct WalkInLengths {
    float handsAhead, pikeStart, footStep, sitBack;
  } walkIn_{};
  glm::vec3 toeLocal_{0.0f};  // middle of the foot's toe edge, in the foot frame

  RisePhase phase_ = RisePhase::kSettle;
  Move move_;
  bool hasMove_ = false;
  float progress_ = 0.0f;
  // The pelvis goal last handed to the servos: the move's tracking error is the
  // measured pelvis's distance from it.
  glm::vec3 pelvisGoal_{0.0f};
  double lastTime_ = 0.0;
  double restSince_ = -1.0;
  double stalledSince_ = -1.0;
  double unsupportedSince_ = -1.0;  // on hands and feet, bearing on one or none since; < 0 not so
  double standTime_ = -1.0;
  bool finished_ = false;
  int retries_ = 0;
  bool givingUp_ = false, gaveUp_ = false;
  int crawlSteps_ = 0;
  int shiftTries_ = 0;
  bool feetIn_ = false;  // the feet have come in as far as they can
  // Where each limb's last step was to land: a swing the servos leave short
  // is finished by putting the limb down there, not where it hangs.
  std::array<std::optional<glm::vec3>, kLimbCount> stepSpot_{};
  int putDowns_ = 0;  // put-downs in a row that left their limb in the air
  int catches_ = 0;  // rises tipping forward caught on the hands this try
  int placeTries_ = 0;  // places of hands and feet since the last push or fall
  float rollSign_ = 0.0f;                   // +1 rolling onto the left side, -1 onto the right; 0 before the roll
  RollStage rollStage_ = RollStage::kNone;  // the roll's last move
  int rollMoves_ = 0;                       // moves since this roll started
  bool hadPushOff_ = false;                 // this roll has had a push off (it began on the back)
  glm::vec3 heading_{0.0f, 0.0f, 1.0f};
  glm::vec3 balanceOffset_{0.0f};
  float balanceLean_ = 0.0f;
  glm::vec3 crawlOffset_{0.0f};
  std::array<bool, kLimbCount> planted_{};
  // Where each planted limb last came down in this move (LetGoSkiddingFeet).
  std::array<std::optional<glm::vec3>, kLimbCount> downAt_{};
  bool tracing_ = false;
  TraceSample trace_;
};

}  // namespace rise
