// SPDX-License-Identifier: MIT
// Joints between two bodies: ball-socket, hinge, 2-DOF universal and 3-DOF gimbal, each with
// limits and a PD motor.
//
// Joint frame: every joint is given one world-space frame (anchor point + orientation) at the
// bind pose. Its x axis is the twist axis (ball, universal: usually along the child bone) or the
// hinge axis. The frame is stored relative to each body, so the joint measures the rotation of
// B's frame relative to A's frame, which is the identity at the bind pose:
//   qRel = conj(qA * frameInA) * (qB * frameInB).
//
// Degrees of freedom and limits, all in radians:
//   kBall:      3 rotations. Swing cone: the angle between A's and B's x axes <= swingCone.
//               Twist: the rotation about x of the swing-twist decomposition of qRel in twistLimits.
//   kHinge:     1 rotation about x (A's x and B's x stay aligned); the angle in twistLimits.
//   kUniversal: 2 rotations, twist about x locked (Cardan joint): first about A's y by angle
//               alpha (in swingYLimits), then about B's z by angle beta (in swingZLimits),
//               qRel = Ry(alpha) Rz(beta). Used for hips, shoulders, wrists and ankles.
//   kGimbal:    3 rotations, qRel = Ry(alpha) Rz(beta) Rx(gamma), each angle in its own range
//               (swingYLimits, swingZLimits, twistLimits). Used for the spine and neck.
//
// Motor: a PD servo that drives qRel to motor.target (identity = bind pose), acting only on the
// joint's free axes (all three for kBall and kGimbal, x for kHinge, A's y and B's z for kUniversal).
#pragma once

#include "physics/body.h"
#include "physics/constraint_parts.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <limits>
#include <vector>

namespace rise::physics {

enum class JointType : uint8_t { kBall, kHinge, kUniversal, kGimbal };

struct AngleRange {
  float lower = 0.0f;  // rad
  float upper = 0.0f;  // rad
};

struct MotorDef {
  bool enabled = false;
  glm::quat target{1.0f, 0.0f, 0.0f, 0.0f};  // wanted qRel
  float stiffness = 0.0f;                    // kp, N m / rad
  float damping = 0.0f;                      // kd, N m s / rad
  float maxTorque = std::numeric_limits<float>::infinity();  // N m, norm clamp incl. feed-forward
  glm::vec3 feedForwardTorque{0.0f};         // N m, world, on B (A gets the opposite)
  float maxSpeed = std::numeric_limits<float>::infinity();  // rad/s the spring drives toward the target at most
};

struct JointId {
  int32_t index = -1;
  bool IsValid() const { return index >= 0; }
};

struct JointDef {
  JointType type = JointType::kBall;
  BodyId bodyA = kWorldBody;  // parent (or the static world)
  BodyId bodyB;               // child, must be a body
  glm::vec3 anchor{0.0f};                    // world, at the bind pose
  glm::quat frame{1.0f, 0.0f, 0.0f, 0.0f};   // world orientation of the joint frame at the bind pose

  bool enableLimits = false;
  AngleRange twistLimits{-3.14159265f, 3.14159265f};  // kBall twist, kHinge angle, kGimbal gamma
  float swingCone = 3.14159265f;                      // kBall cone half-angle
  AngleRange swingYLimits{-1.5f, 1.5f};               // kUniversal and kGimbal alpha
  AngleRange swingZLimits{-1.5f, 1.5f};               // kUniversal and kGimbal beta

  MotorDef motor;
};

// The rows a joint type adds on top of the point part, measured at the current poses.
struct AngularRows {
  int lockCount = 0;
  glm::vec3 lockAxis[2];
  float lockPosition[2] = {};  // C of each equality row

  // Limited angles: row i keeps angle[i] within range[i] about limitAxis[i].
  int limitCount = 0;
  glm::vec3 limitAxis[3];
  float angle[3] = {};
  AngleRange range[3];

  int motorCount = 0;
  glm::vec3 motorAxis[3];

  // Effective masses of the lock and limit rows (AngularEffectiveMass; a limit's lower and upper
  // rows share one, as their axes differ only in sign). Filled by UpdateJointGeometry.
  float lockMass[2] = {};
  float limitMass[3] = {};
};

// A joint inside the World: its definition in body-local terms plus accumulated impulses that
// warm-start the next sub-step and step.
struct Joint {
  JointType type = JointType::kBall;
  int32_t bodyA = -1;  // -1: the static world
  int32_t bodyB = -1;
  glm::vec3 localAnchorA{0.0f}, localAnchorB{0.0f};
  glm::quat localFrameA{1.0f, 0.0f, 0.0f, 0.0f}, localFrameB{1.0f, 0.0f, 0.0f, 0.0f};
  bool enableLimits = false;
  AngleRange twistLimits, swingYLimits, swingZLimits;
  float swingCone = 0.0f;
  MotorDef motor;

  glm::vec3 linearImpulse{0.0f};
  float lockImpulse[2] = {};
  float lowerImpulse[3] = {};
  float upperImpulse[3] = {};
  glm::vec3 motorImpulse{0.0f};      // in motor-axis coordinates
  glm::vec3 motorTorqueWorld{0.0f};  // last sub-step's motor torque on B, N m
  // Sum of all angular row impulses on B as one world vector, kept from the last solve so the
  // warm start need not rebuild the rows.
  glm::vec3 angularImpulse{0.0f};
  glm::mat3 pointMass{0.0f};  // K^-1 of the point part for this step
  // The point part is solved with the joint forest's direct solve (joint_tree.h), not here.
  bool pointInTree = false;

  // Everything that depends only on the two bodies' poses, refreshed by UpdateJointGeometry
  // whenever they move. Positions change only in the position integration, so the relax pass of
  // one sub-step and the warm start and solve of the next share one evaluation.
  AngularRows rows;
  glm::vec3 leverA{0.0f}, leverB{0.0f};  // world anchor offsets rA, rB from the centres of mass
  // rows and lever arms were computed from the bodies' present poses: true after every position
  // integration, so the next step's PrepareJoint reuses them; World::SetTransform clears it.
  bool rowsCurrent = false;
  MotorPartTerms motorTerms;             // the motor rows' error terms and mass (when enabled)
};

// Builds the body-local joint from a world-space bind-pose definition.
Joint MakeJoint(const JointDef& def, const Body& a, const Body& b);

// qRel, the rotation of B's joint frame relative to A's.
glm::quat RelativeRotation(const Joint& joint, const Body& a, const Body& b);

// World-space distance between the two anchor points (0 when the joint is exact), m.
float AnchorSeparation(const Joint& joint, const Body& a, const Body& b);

// The solver stages every joint type goes through (dispatch in joint.cpp). PrepareJoint ends with
// UpdateJointGeometry (its pose-only part skipped while rowsCurrent); the solver calls it again
// after every position integration.
void PrepareJoint(Joint& joint, const Body& a, const Body& b, const SolverContext& context);
void UpdateJointGeometry(Joint& joint, const Body& a, const Body& b, const SolverContext& context);
// The per-pass stages run over all joints in creation order (one call, so the per-joint work is
// inlined into the loop); `staticBody` stands in for body A of joints to the world.
void WarmStartJoints(std::vector<Joint>& joints, std::vector<Body>& bodies, Body& staticBody);
void SolveJoints(std::vector<Joint>& joints, std::vector<Body>& bodies, Body& staticBody, const SolverContext& context,
                 bool useBias);
// Sums the angular rows' impulses at the present rows into angularImpulse, which the next warm
// start applies, and the motor's into motorTorqueWorld. Only their values after a sub-step's last
// pass are read, so the solver calls it there.
void StoreJointWarmStarts(std::vector<Joint>& joints, const SolverContext& context);

// Per-type geometry (joint_ball.cpp, joint_hinge.cpp, joint_universal.cpp, joint_gimbal.cpp), written into `rows`
// in place: counts, axes, positions, angles and ranges (the effective masses are the caller's).
// frameA = qA localFrameA and frameB = qB localFrameB, the joint frames in world space; the caller
// computes them once for the rows and the motor.
void BallRows(const Joint& joint, const glm::quat& frameA, const glm::quat& frameB, AngularRows& rows);
void HingeRows(const Joint& joint, const glm::quat& frameA, const glm::quat& frameB, AngularRows& rows);
void UniversalRows(const Joint& joint, const glm::quat& frameA, const glm::quat& frameB, AngularRows& rows);
void GimbalRows(const Joint& joint, const glm::quat& frameA, const glm::quat& frameB, AngularRows& rows);

}  // namespace rise::physics
