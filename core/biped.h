// SPDX-License-Identifier: MIT
// The simulated biped: the 16 boxes and 15 joints of a BipedDef inside a physics::World, the
// start poses (bind pose and the lying postures), and the state read back for the controller
// and the recorder.
//
// Poses are given in the skeleton's convention (export/skeleton.h): a root transform (world
// position and rotation of the pelvis joint frame) plus one local rotation per skeleton joint
// (child relative to parent, identity at the bind pose). A segment's box hangs rigidly in its
// joint frame, so the world pose of every body follows by forward kinematics.
//
// Engine joints (physics/joint.h) measure qRel in a joint frame F fixed in both bodies at the
// bind pose; F is BipedDef::JointFrame, whose axes carry the joint's DOFs the way the engine's
// joint types expect (x: hinge or twist axis; y then z: the universal joint's two angles). A
// skeleton local rotation q and the engine's qRel relate by qRel = conj(F) q F, so motor targets
// are set in skeleton terms with SetLocalTarget.
//
// Limits: hinge and universal limits are the BoneDef's DOF limits exactly. A ball joint (spine,
// neck) has the BoneDef's twist limit and one swing cone whose half-angle is the largest of its
// flexion and side-bend limits, since the engine limits swing by a cone.
#pragma once

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>
#include <optional>
#include <string>
#include <vector>

#include "core/biped_def.h"
#include "core/rise_spec.h"
#include "physics/world.h"

namespace rise {

struct BipedPose {
  physics::Transform root;       // world pose of the pelvis joint frame
  std::vector<glm::quat> local;  // per skeleton joint; local[0] is ignored (the root is `root`)
};

// Lowest box corners are put this far above the ground, so the first step starts without overlap.
constexpr float kGroundClearance = 0.005f;

// World settings for simulating the biped: the engine defaults with stiffer contacts. The soft
// contact is relative to the mass of the body touching the ground, so a light box carrying the
// trunk through a joint sinks: lying on a side, the 2 kg upper arm under the chest sank 13 mm
// at the default 30 Hz and 3 mm at 60 Hz (measured, 1.75 m / 70 kg, 240 Hz with 4 sub-steps).
physics::WorldSettings BipedWorldSettings();

// The ground of a terrain: a plane through the origin rising toward +Z by slopeDeg.
physics::PlaneShape GroundPlane(double slopeDeg);
// Adds that plane to the world with the terrain's friction.
physics::StaticShapeId AddGround(physics::World& world, const TerrainSpec& terrain);

// The standing bind pose: every local rotation identity, the pelvis at its rest offset.
BipedPose BindPose(const BipedDef& def);

// The start pose of a clip: the posture's root rotation and joint angles (start.jointsDeg
// replacing the posture's own), turned by start.headingDeg about +Y, tilted onto the slope, and
// moved along the ground normal so the lowest box corner is kGroundClearance + start.dropHeightM
// above the ground. Postures are described in rise_spec.h.
BipedPose StartPose(const BipedDef& def, const StartSpec& start, double slopeDeg);

// Two boxes of the body that pass into each other in a pose, of the pairs the simulation
// collides (limbs with limbs and with the head; the trunk's boxes pass through the limbs').
struct SelfOverlap {
  std::string boxA, boxB;  // the joints that carry them
  float depthM = 0.0f;     // how far they pass into each other, > 0
};
// The deepest such overlap, as the engine's narrow phase measures it; none: nullopt. A start
// pose that deep inside itself is pushed apart by the contacts at once, which whips the limbs.
std::optional<SelfOverlap> DeepestSelfOverlap(const BipedDef& def, const BipedPose& pose);
// The deepest a start pose may be (the input loader rejects deeper). Boxes are a coarse body: the
// side postures' thighs overlap 3.5 cm and are pushed apart gently; the stress runs whipped by
// the push began 6-16 cm deep.
inline constexpr float kMaxStartOverlapM = 0.05f;

// World transform of every skeleton joint frame for a pose (end joints included).
std::vector<physics::Transform> JointWorldTransforms(const BipedDef& def, const BipedPose& pose);

// Signed distance of the lowest box corner of the pose above a plane, m (negative: below it).
float LowestCorner(const BipedDef& def, const BipedPose& pose, const physics::PlaneShape& plane);

class Biped {
 public:
  // Creates the bodies and joints of `def` in `world` at `pose`, with joint limits on and servos
  // off (a ragdoll). Every box gets the friction given (use the terrain's, so that the engine's
  // geometric-mean mixing keeps the terrain's coefficient). Bodies joined by a joint do not
  // collide with each other (the engine filters jointed pairs); every other pair does.
  Biped(const BipedDef& def, physics::World& world, const BipedPose& pose, float friction);

  const BipedDef& Def() const { return def_; }

  // Engine ids by skeleton joint index: invalid for end joints (no body) and for the root (no joint).
  physics::BodyId BodyOf(int joint) const { return bodies_[joint]; }
  // The joint whose box is the engine's body `bodyIndex`; -1 when none is.
  int JointOfBody(int32_t bodyIndex) const;
  physics::JointId JointOf(int joint) const { return joints_[joint]; }

  // Moves every body to a pose with zero velocity (e.g. to restart an attempt).
  void SetPose(const BipedPose& pose);

  // State, read from the world.
  std::vector<physics::Transform> JointWorldTransforms() const;  // every skeleton joint, ends included
  BipedPose Pose() const;                                        // root + local rotations (clip keys)
  glm::vec3 CenterOfMass() const;                                // whole body, world, m
  glm::vec3 CenterOfMassVelocity() const;                        // m/s
  float MaxBodySpeed() const;                                    // largest |v| of a box centre, m/s
  float LowestCorner(const physics::PlaneShape& plane) const;    // as the free function, for the live state

  // Servos (the engine's PD motors). Gains and torque caps default to the BipedDef's.
  void SetServosEnabled(bool enabled);
  void SetServoGains(int joint, float kp, float kd, float maxTorqueNm);
  // Target local rotation of a joint in skeleton terms (child relative to parent).
  void SetLocalTarget(int joint, const glm::quat& local);
  void SetTargetPose(const BipedPose& pose);  // every jointed bone's local rotation
  // Local rotation of a joint as the engine measures it (skeleton terms).
  glm::quat LocalRotation(int joint) const;

 private:
  BipedDef def_;
  physics::World* world_;
  std::vector<physics::BodyId> bodies_;   // per skeleton joint
  std::vector<physics::JointId> joints_;  // per skeleton joint
  std::vector<glm::quat> frames_;         // F per skeleton joint (identity where no joint)
};

}  // namespace rise
