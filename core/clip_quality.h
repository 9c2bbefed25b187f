// SPDX-License-Identifier: MIT
// The quality bars every clip must meet, measured from the clip alone (ours or
// another tool's), for `rise-gen check` and the batch index.
//
// The bars (the product's definition; every threshold is a QualityOptions field):
// - Starts lying: at the first frame the head joint is below 40 % of its standing
//   height and the trunk (pelvis-to-chest line, pelvis-to-head without a chest)
//   is within 45 deg of the ground plane.
// - Ends standing: over the last 0.5 s the head joint is at >= 90 % of its
//   standing height, the pelvis-to-head line is within 15 deg of vertical, and
//   the lowest point of each foot is within 2 cm of the ground. timeToStand is
//   the first time from which these hold on every frame to the end; the clip
//   ends standing when that stretch lasts at least the 0.5 s window.
// - Ground penetration: no vertex of any body box more than 2 cm below ground.
// - Contact slip: a hand or foot whose lowest point is within 1 cm of the
//   ground is in contact; it slides less than 5 cm before it lifts again. The
//   slide is followed on the body's material: from frame to frame we move the
//   point that touched on the earlier frame (the lowest box vertex) with the
//   body, so rolling over a heel or toe is not sliding, and a contact's slip is
//   the largest distance along the ground that point gets from where it was
//   planted (jitter cancels out instead of adding up).
// - No teleport: between two frames no joint moves farther than
//   maxJointSpeed * frameTime + jumpSlack (10 m/s, well above a limb's peak
//   speed in a get-up, plus 1 cm for rounding in exported files).
//
// Heights are signed distances to the ground plane (y = 0 by default, or a
// slope through groundPoint with normal groundNormal). "Horizontal" and
// "lying" are measured along that plane, because a body lies and slides on
// the slope; "vertical" for standing is world +Y, because a body stands
// against gravity, not perpendicular to a slope.
//
// Standing heights come from the bind pose (Skeleton::BindPositions), which is
// the standing pose by convention (export/skeleton.h). A hand's or foot's
// lowest point is the lowest vertex of the boxes of the effector joint and its
// descendants; a skeleton without boxes (another tool's clip) falls back to
// those joints' positions, and box-vertex bars then use all joints.
//
// Joints are found by their canonical names (pelvis, chest, head, hand_l,
// hand_r, foot_l, foot_r); a clip of another rig is renamed to them first
// (export/joint_names.h CanonicalJointName).
#pragma once

#include <glm/vec3.hpp>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "export/clip.h"

namespace rise {

struct QualityOptions {
  // Ground plane: the points p with dot(p - groundPoint, groundNormal) = 0.
  glm::vec3 groundPoint{0.0f};
  glm::vec3 groundNormal{0.0f, 1.0f, 0.0f};  // need not be unit length; must not be zero

  double lyingHeadRatio = 0.40;   // head below this fraction of standing head height
  double lyingTrunkDeg = 45.0;    // trunk within this angle of the ground plane
  double standWindow = 0.5;       // seconds the standing conditions must hold at the end
  double standHeadRatio = 0.90;   // head at or above this fraction of standing head height
  double standTiltDeg = 15.0;     // pelvis-to-head line within this angle of +Y
  double standFootHeight = 0.02;  // metres: |lowest point of each foot| within this
  double maxPenetration = 0.02;   // metres below ground any box vertex may reach
  double contactHeight = 0.01;    // metres: an effector this close to the ground touches it
  double maxSlip = 0.05;          // metres an effector may slide during one contact
  double maxJointSpeed = 10.0;    // m/s: the teleport bound
  double jumpSlack = 0.01;        // metres added to the teleport bound per frame
};

// One contact of an effector with the ground and how far it slid.
struct ContactSlide {
  double start = 0.0;  // seconds
  double end = 0.0;
  double slip = 0.0;  // metres
};

// The worst slide of one effector over the whole clip.
struct EffectorSlip {
  std::string effector;      // "hand_l", "hand_r", "foot_l", "foot_r"
  double slip = 0.0;         // metres, worst contact
  double contactStart = -1;  // seconds, the worst contact's span; < 0 when never in contact
  double contactEnd = -1;
  int contacts = 0;  // number of separate contacts
  std::vector<ContactSlide> overBar;  // every contact that slid maxSlip or more, in time order
};

struct QualityReport {
  // Non-empty when the clip cannot be measured (invalid clip, a required joint
  // missing); all figures are then unset and passed is false.
  std::string error;

  double duration = 0.0;  // seconds
  int frames = 0;
  double fps = 0.0;
  double standingHeadHeight = 0.0;  // metres, head joint in the bind pose

  // Start.
  double startHeadRatio = 0.0;  // head height / standing head height, first frame
  double startTrunkDeg = 0.0;   // trunk angle from the ground plane, first frame
  bool startsLying = false;

  // End.
  double timeToStand = -1.0;     // seconds; < 0 when the last frame is not standing
  double headHeightRatio = 0.0;  // last frame
  double trunkTiltEnd = 0.0;     // deg, pelvis-to-head line from +Y, last frame
  double footHeightEndL = 0.0;   // metres, lowest point of each foot, last frame
  double footHeightEndR = 0.0;
  bool endsStanding = false;

  // Ground penetration.
  double maxPenetration = 0.0;   // metres below ground (0 when never below)
  std::string penetrationJoint;  // whose box (or joint) went deepest
  int penetrationFrame = -1;
  bool penetrationOk = false;

  // Contact slip.
  std::vector<EffectorSlip> slips;  // hand_l, hand_r, foot_l, foot_r
  double maxSlip = 0.0;
  std::string maxSlipEffector;
  bool slipOk = false;

  // Teleports.
  double maxJointJump = 0.0;  // m/s: largest one-frame displacement / frame time
  double maxJointJumpMeters = 0.0;
  std::string jumpJoint;
  int jumpFrame = -1;  // the frame arrived at
  bool jumpOk = false;

  bool passed = false;  // every bar above holds

  // Every figure, for `check --json` and the batch index.
  nlohmann::json ToJson() const;
  // A few lines for a person: each bar with PASS/FAIL and its figures.
  std::string Summary() const;
};

QualityReport MeasureClip(const Clip& clip, const QualityOptions& options = {});

// Every joint's world position on every frame: [frame][joint].
std::vector<std::vector<glm::vec3>> JointPositionSequence(const Clip& clip);

// The fastest any box's centre moved from one frame to the next. Not a quality bar: a health
// figure (a simulation blowing up whips a limb) for the stress runner and tests, meaningful
// when the clip is recorded at the engine's step rate so no fast step falls between frames.
struct FastestBox {
  double speed = 0.0;  // m/s
  int body = -1;       // skeleton joint whose box it is; -1 when no box moved
  int frame = -1;      // the frame arrived at
};
FastestBox MeasureFastestBox(const Clip& clip);

// The largest distance between corresponding entries of two position
// sequences ([frame][joint], e.g. one clip read back from BVH and from glTF).
// nullopt when their shapes differ.
std::optional<double> MaxPositionDistance(const std::vector<std::vector<glm::vec3>>& a,
                                          const std::vector<std::vector<glm::vec3>>& b);

}  // namespace rise
