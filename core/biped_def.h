// SPDX-License-Identifier: MIT
// BipedDef: the immutable description of one character body (proportions, masses,
// joint kinds and limits, torque caps, servo gains), built from height and mass.
//
// Proportions follow Winter, "Biomechanics and Motor Control of Human Movement"
// (segment lengths as fractions of body height H), mass fractions follow
// Dempster as tabulated by Winter (trunk 49.7 % split into pelvis 14.2 %,
// abdomen 13.9 %, thorax 21.6 %).
//
// Body layout (bind pose = standing, facing +Z, left = +X, soles on y = 0; every
// joint frame is aligned with the world axes in the bind pose, see export/skeleton.h):
//
//   joint         parent       sits at                         kind      box
//   pelvis        (root)       mid-point of the hip joints     free      yes
//   abdomen       pelvis       lumbar spine                    ball      yes
//   chest         abdomen      thoracolumbar junction          ball      yes
//   head          chest        base of the neck (box = head+neck) ball   yes
//   head_end      head         top of the head                 end       no
//   upper_arm_l/r chest        shoulder                        universal yes
//   forearm_l/r   upper_arm    elbow                           hinge     yes
//   hand_l/r      forearm      wrist                           universal yes
//   hand_l/r_end  hand         finger tips                     end       no
//   thigh_l/r     pelvis       hip                             universal yes
//   shin_l/r      thigh        knee                            hinge     yes
//   foot_l/r      shin         ankle                           universal yes
//   foot_l/r_end  foot         toe tips, on the sole           end       no
//
// 21 skeleton joints, 16 boxes (bodies), 15 physical joints between them.
//
// Joint angles. A joint's local rotation (child relative to parent) is the
// product of its degrees of freedom in the order listed, each a rotation by its
// angle about its axis (axes in the parent joint frame = world axes in the bind
// pose): q = R(axis0, a0) * R(axis1, a1) * R(axis2, a2). Each axis points so
// that a positive angle is the anatomical motion named by the DOF (flexion,
// abduction, ...), mirrored between left and right. Limits in degrees:
//
//   joint (bone)    DOF 0                     DOF 1                       DOF 2
//   abdomen         flexion +X  [-25, 45]     bend left -Z  [-25, 25]     twist left +Y [-30, 30]
//   chest           flexion +X  [-20, 40]     bend left -Z  [-20, 20]     twist left +Y [-35, 35]
//   head (neck)     flexion +X  [-50, 60]     bend left -Z  [-40, 40]     twist left +Y [-70, 70]
//   upper_arm       flexion -X  [-60, 170]    abduction +-Z [-30, 100]
//   forearm (elbow) flexion -X  [0, 150]      (forearm swings forward)
//   hand (wrist)    flexion -+Z [-70, 80]     radial dev. -X [-35, 20]
//   thigh (hip)     flexion -X  [-30, 120]    abduction +-Z [-30, 50]
//   shin (knee)     flexion +X  [0, 150]      (shin swings backward)
//   foot (ankle)    dorsiflexion -X [-50, 40] inversion -+Z [-20, 35]
// where "+-Z" means +Z on the left side and -Z on the right (and "-+Z" the reverse).
// A universal joint's second angle stays well inside +-90 deg: there the Cardan joint of the
// engine (physics/joint.h) is in gimbal lock, so arms go overhead by flexion, not abduction.
#pragma once

#include <array>
#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "export/skeleton.h"

namespace rise {

enum class JointKind {
  kFree,       // the root: 6 DOF, no joint to a parent
  kHinge,      // 1 DOF
  kUniversal,  // 2 DOF (swing without twist)
  kBall,       // 3 DOF with a limit per axis (the engine's gimbal joint)
  kEnd,        // end marker: no body, no DOF
};

struct JointDof {
  std::string name;      // anatomical motion of a positive angle, e.g. "flexion"
  glm::vec3 axis{0.0f};  // unit axis in the parent joint frame
  float minDeg = 0.0f;
  float maxDeg = 0.0f;
};

// Everything about one skeleton joint and the body segment it carries.
struct BoneDef {
  JointKind kind = JointKind::kEnd;
  std::vector<JointDof> dofs;  // 1, 2 or 3 entries for hinge, universal, ball; empty otherwise
  float massKg = 0.0f;         // 0 for end joints
  float maxTorqueNm = 0.0f;    // servo torque cap per axis; 0 for the root and end joints
  float servoKp = 0.0f;        // default PD stiffness, N*m/rad
  float servoKd = 0.0f;        // default PD damping, N*m*s/rad
  float servoMaxSpeed = 0.0f;  // rad/s the servo closes a large error at, at most
};

// Optional replacement of a segment's default box size or mass. length is along
// the bone (vertical for trunk, head, limbs; heel to toe for the feet); width is
// side to side (x); depth is front to back (z) -- for a foot, depth is its height
// from sole to ankle.
struct SegmentOverride {
  std::optional<float> lengthM;
  std::optional<float> widthM;
  std::optional<float> depthM;
  std::optional<float> massKg;
};
// Keyed by the name of a joint that carries a box (see SegmentNames()).
using SegmentOverrides = std::map<std::string, SegmentOverride>;

struct BipedDef {
  float heightM = 0.0f;        // the height asked for; with length overrides the bind pose height can differ
  float massKg = 0.0f;         // sum of all segment masses
  Skeleton skeleton;           // 21 joints, names as listed above, boxes in joint frames
  std::vector<BoneDef> bones;  // parallel to skeleton.joints

  int Find(const std::string& name) const { return skeleton.Find(name); }
  // Number of angles a joint takes (0 for the root and end joints).
  int DofCount(int joint) const { return static_cast<int>(bones[joint].dofs.size()); }
  // Local rotation of a joint from its DOF angles in degrees (count = DofCount).
  glm::quat JointRotation(int joint, const float* anglesDeg) const;
  // The inverse: DOF angles in degrees of a local rotation (DofCount values written). Exact for
  // rotations the joint can make; for others (e.g. a twisted universal joint) the angles of the
  // rotation's Euler decomposition along the joint's axes, dropping the part it cannot make.
  void JointAngles(int joint, const glm::quat& local, float* anglesDeg) const;
  // Frame F of a joint whose axes carry its DOFs: hinge [x]; universal [y, z]; ball [y, +-z, x]
  // (x is the hinge or twist axis; a ball joint's z is its second DOF axis or the opposite, as
  // the right-handed frame falls). A rotation in F's coordinates, conj(F) q F, is
  // Ry(a0) Rz(+-a1) Rx(a2) with the angles that are present; the engine's joint frame is this F.
  glm::quat JointFrame(int joint) const;
  // Whole-body centre of mass in the bind pose.
  glm::vec3 BindCenterOfMass() const;
  // Bind-pose height of the top of the head above the soles.
  float BindHeadTop() const;
};

// The names of the 16 joints that carry a box, root first, in skeleton order.
const std::vector<std::string>& SegmentNames();

// The body for a height and mass, with optional overrides. Masses: overridden
// segments keep their mass; the others share the rest of massKg in proportion to
// their default fractions, so the total always equals massKg.
// Preconditions (checked with RISE_ASSERT; the JSON loader reports them as input
// errors first): heightM in [1.2, 2.3], massKg in [30, 200], override names from
// SegmentNames(), override sizes > 0, overridden masses summing to < 0.9 massKg.
BipedDef MakeBipedDef(float heightM, float massKg, const SegmentOverrides& overrides = {});

// Torque caps per kilogram of body mass (N*m/kg), from the human-plausible maxima.
struct TorquePerKg {
  static constexpr float kHip = 3.5f;
  static constexpr float kKnee = 3.0f;
  static constexpr float kAnkle = 2.0f;
  static constexpr float kSpine = 3.0f;
  static constexpr float kShoulder = 1.2f;
  static constexpr float kElbow = 1.0f;
  static constexpr float kNeck = 0.5f;
  static constexpr float kWrist = 0.3f;
};

}  // namespace rise
