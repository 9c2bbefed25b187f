// SPDX-License-Identifier: MIT
// Joint solver shared by all joint types: point part, axis locks, limits and the PD motor.
//
// Every joint is the point part plus angular rows produced by its type (joint_*.cpp):
//   point:  C = pB - pA (3 rows), see SolvePointPart.
//   lock:   C = position about a world axis u, Cdot = u . (wB - wA), J = [0, -u, 0, u].
//   limit:  C = angle - lower >= 0 and C = upper - angle >= 0 with J = +-[0, -u, 0, u].
//   motor:  the rotation vector e of (qB frameB) conj(qA frameA target), projected on the free
//           axes, c_i = u_i . e, Cdot_i = u_i . (wB - wA); solved as an implicit PD spring.
// Solve order within a joint: motor, limits, locks, point, so the hard parts have the last word.
// Angular rows, their effective masses, the motor error and the lever arms are rebuilt whenever
// the poses change (UpdateJointGeometry, at prepare and after every position integration): the
// axes turn during a step and the limits must see the angle the sub-step actually reached.
#include "physics/joint.h"

#include "base/assert.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace rise::physics {

namespace {

void UpdateRows(const Joint& joint, const glm::quat& frameA, const glm::quat& frameB, AngularRows& rows) {
  switch (joint.type) {
    case JointType::kBall:
      BallRows(joint, frameA, frameB, rows);
      return;
    case JointType::kHinge:
      HingeRows(joint, frameA, frameB, rows);
      return;
    case JointType::kUniversal:
      UniversalRows(joint, frameA, frameB, rows);
      return;
    case JointType::kGimbal:
      GimbalRows(joint, frameA, frameB, rows);
      return;
  }
  RISE_ASSERT_MSG(false, "unknown joint type");
}

// Rotation vector (axis * angle, shortest way round) of a unit quaternion.
glm::vec3 RotationVector(glm::quat q) {
  if (q.w < 0.0f) q = -q;
  const glm::vec3 v(q.x, q.y, q.z);
  const float s = glm::length(v);
  if (s < 1e-6f) return 2.0f * v;
  return (2.0f * std::atan2(s, q.w) / s) * v;
}

MotorGains MotorGainsOf(const MotorDef& motor) {
  return MotorGains{motor.stiffness, motor.damping, motor.maxTorque, motor.feedForwardTorque, motor.maxSpeed};
}

// Sum of J^T lambda of all angular rows, as one world impulse on B.
glm::vec3 AngularImpulse(const Joint& joint, const AngularRows& rows) {
  glm::vec3 impulse(0.0f);
  for (int i = 0; i < rows.lockCount; ++i) impulse += joint.lockImpulse[i] * rows.lockAxis[i];
  for (int i = 0; i < rows.limitCount; ++i) impulse += (joint.lowerImpulse[i] - joint.upperImpulse[i]) * rows.limitAxis[i];
  for (int i = 0; i < rows.motorCount; ++i) impulse += joint.motorImpulse[i] * rows.motorAxis[i];
  return impulse;
}

// The joint frames in world space and the bodies' summed inverse inertia: what both the rows and
// the motor are built from, evaluated once for the two.
struct JointPose {
  glm::quat frameA, frameB;
  glm::mat3 invInertiaSum;
};

JointPose PoseOf(const Joint& joint, const Body& a, const Body& b) {
  return JointPose{a.transform.rotation * joint.localFrameA, b.transform.rotation * joint.localFrameB,
                   a.invInertiaWorld + b.invInertiaWorld};
}

// The pose-only part of UpdateJointGeometry: rows, their effective masses and the lever arms.
void UpdateJointRows(Joint& joint, const Body& a, const Body& b, const JointPose& pose) {
  AngularRows& rows = joint.rows;
  UpdateRows(joint, pose.frameA, pose.frameB, rows);
  const glm::mat3& invInertiaSum = pose.invInertiaSum;
  for (int i = 0; i < rows.lockCount; ++i) rows.lockMass[i] = AngularEffectiveMass(invInertiaSum, rows.lockAxis[i]);
  for (int i = 0; i < rows.limitCount; ++i) rows.limitMass[i] = AngularEffectiveMass(invInertiaSum, rows.limitAxis[i]);
  joint.leverA = a.transform.rotation * joint.localAnchorA;
  joint.leverB = b.transform.rotation * joint.localAnchorB;
  joint.rowsCurrent = true;
}

// The motor's error and terms also depend on its target and gains (set between steps) and on h.
void UpdateMotorRows(Joint& joint, const JointPose& pose, const SolverContext& context) {
  const AngularRows& rows = joint.rows;
  if (!joint.motor.enabled || rows.motorCount == 0) return;
  const glm::quat targetB = pose.frameA * joint.motor.target;
  const glm::vec3 error = RotationVector(pose.frameB * glm::conjugate(targetB));
  float motorError[3];
  for (int i = 0; i < rows.motorCount; ++i) motorError[i] = glm::dot(rows.motorAxis[i], error);
  joint.motorTerms = MakeMotorPartTerms(pose.invInertiaSum, rows.motorAxis, motorError, rows.motorCount,
                                        MotorGainsOf(joint.motor), context.h);
}

}  // namespace

Joint MakeJoint(const JointDef& def, const Body& a, const Body& b) {
  Joint joint;
  joint.type = def.type;
  joint.bodyA = def.bodyA.index;
  joint.bodyB = def.bodyB.index;
  const glm::quat frame = glm::normalize(def.frame);
  joint.localAnchorA = glm::conjugate(a.transform.rotation) * (def.anchor - a.transform.position);
  joint.localAnchorB = glm::conjugate(b.transform.rotation) * (def.anchor - b.transform.position);
  joint.localFrameA = glm::normalize(glm::conjugate(a.transform.rotation) * frame);
  joint.localFrameB = glm::normalize(glm::conjugate(b.transform.rotation) * frame);
  joint.enableLimits = def.enableLimits;
  joint.twistLimits = def.twistLimits;
  joint.swingCone = def.swingCone;
  joint.swingYLimits = def.swingYLimits;
  joint.swingZLimits = def.swingZLimits;
  joint.motor = def.motor;
  return joint;
}

glm::quat RelativeRotation(const Joint& joint, const Body& a, const Body& b) {
  return glm::conjugate(a.transform.rotation * joint.localFrameA) * (b.transform.rotation * joint.localFrameB);
}

float AnchorSeparation(const Joint& joint, const Body& a, const Body& b) {
  const glm::vec3 pA = a.transform.position + a.transform.rotation * joint.localAnchorA;
  const glm::vec3 pB = b.transform.position + b.transform.rotation * joint.localAnchorB;
  return glm::length(pB - pA);
}

void PrepareJoint(Joint& joint, const Body& a, const Body& b, const SolverContext& context) {
  if (!joint.pointInTree) joint.pointMass = PointPartMass(a, b, joint.localAnchorA, joint.localAnchorB);
  if (!context.warmStart) {
    joint.linearImpulse = glm::vec3(0.0f);
    joint.lockImpulse[0] = joint.lockImpulse[1] = 0.0f;
    for (int i = 0; i < 3; ++i) joint.lowerImpulse[i] = joint.upperImpulse[i] = 0.0f;
    joint.motorImpulse = glm::vec3(0.0f);
    joint.angularImpulse = glm::vec3(0.0f);
  }
  if (!joint.enableLimits) {
    for (int i = 0; i < 3; ++i) joint.lowerImpulse[i] = joint.upperImpulse[i] = 0.0f;
  }
  if (!joint.motor.enabled) {
    // A motor switched off must not be warm-started by its last impulse; the other rows lose
    // theirs for this one step too, as the combined warm-start vector cannot be split.
    if (joint.motorImpulse != glm::vec3(0.0f)) joint.angularImpulse = glm::vec3(0.0f);
    joint.motorImpulse = glm::vec3(0.0f);
    joint.motorTorqueWorld = glm::vec3(0.0f);
  }
  const JointPose pose = PoseOf(joint, a, b);
  // The last position integration of the previous step left the rows at these very poses.
  if (!joint.rowsCurrent) UpdateJointRows(joint, a, b, pose);
  UpdateMotorRows(joint, pose, context);
}

void UpdateJointGeometry(Joint& joint, const Body& a, const Body& b, const SolverContext& context) {
  const JointPose pose = PoseOf(joint, a, b);
  UpdateJointRows(joint, a, b, pose);
  UpdateMotorRows(joint, pose, context);
}

namespace {

void SolveJoint(Joint& joint, Body& a, Body& b, const SolverContext& context, bool useBias) {
  const AngularRows& rows = joint.rows;

  if (joint.motor.enabled && rows.motorCount > 0) {
    SolveMotorPart(a, b, rows.motorAxis, rows.motorCount, MotorGainsOf(joint.motor), joint.motorTerms,
                   joint.motorImpulse, context);
  }

  for (int i = 0; i < rows.limitCount; ++i) {
    SolveAngularRange(a, b, rows.limitAxis[i], rows.limitMass[i], rows.angle[i], rows.range[i].lower,
                      rows.range[i].upper, joint.lowerImpulse[i], joint.upperImpulse[i], context, useBias);
  }

  for (int i = 0; i < rows.lockCount; ++i) {
    SolveAngularEquality(a, b, rows.lockAxis[i], rows.lockMass[i], rows.lockPosition[i], joint.lockImpulse[i], context,
                         useBias);
  }

  if (!joint.pointInTree) {
    SolvePointPart(a, b, joint.leverA, joint.leverB, joint.pointMass, joint.linearImpulse, context, useBias);
  }
}

}  // namespace

void WarmStartJoints(std::vector<Joint>& joints, std::vector<Body>& bodies, Body& staticBody) {
  for (Joint& joint : joints) {
    Body& a = joint.bodyA >= 0 ? bodies[joint.bodyA] : staticBody;
    Body& b = bodies[joint.bodyB];
    ApplyAngularImpulse(a, b, joint.angularImpulse);
    ApplyLinearImpulse(a, b, joint.leverA, joint.leverB, joint.linearImpulse);
  }
}

void SolveJoints(std::vector<Joint>& joints, std::vector<Body>& bodies, Body& staticBody, const SolverContext& context,
                 bool useBias) {
  for (Joint& joint : joints) {
    SolveJoint(joint, joint.bodyA >= 0 ? bodies[joint.bodyA] : staticBody, bodies[joint.bodyB], context, useBias);
  }
}

void StoreJointWarmStarts(std::vector<Joint>& joints, const SolverContext& context) {
  for (Joint& joint : joints) {
    const AngularRows& rows = joint.rows;
    joint.angularImpulse = AngularImpulse(joint, rows);
    if (joint.motor.enabled && rows.motorCount > 0) {
      glm::vec3 torque(0.0f);
      for (int i = 0; i < rows.motorCount; ++i) torque += joint.motorImpulse[i] * rows.motorAxis[i];
      joint.motorTorqueWorld = context.invH * torque;
    }
  }
}

}  // namespace rise::physics
