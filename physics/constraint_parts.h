// SPDX-License-Identifier: MIT
// Building blocks shared by contacts and joints: soft-constraint coefficients, the 3-D point part,
// 1-D angular equality and limit rows, and the n-axis PD motor part.
//
// Notation: bodies A and B, velocities v, w; inverse mass m, inverse world inertia I^-1.
// A velocity constraint is Cdot = J V with V = (vA, wA, vB, wB); an impulse lambda changes the
// velocities by M^-1 J^T lambda; the effective mass is K^-1 = (J M^-1 J^T)^-1.
//
// Soft constraints (Catto, "Soft Constraints", GDC 2011; Box2D v3 b2MakeSoft). A constraint with
// position error C behaves like a damped spring of natural frequency f [Hz] and damping ratio z
// when each solve applies
//   lambda = -massScale K^-1 (Cdot + biasRate C) - impulseScale lambdaAccumulated
// with omega = 2 pi f, a1 = 2 z + h omega, a2 = h omega a1, a3 = 1 / (1 + a2):
//   biasRate = omega / a1, massScale = a2 a3, impulseScale = a3.
// The stiffness is set in Hz, so it does not change with the time step or the body masses.
//
// PD motor (a spring with absolute gains). A torque tau = -k C - c Cdot + tauFF evaluated at the
// end of the sub-step (implicit) gives, with lambda = h tau,
//   Cdot + (beta / h) C + gamma (lambda - h tauFF) = 0,
//   gamma = 1 / (h (c + h k)),  beta = h k / (c + h k),
// so each solve applies  dLambda = -(K + gamma)^-1 (Cdot + (beta/h) C + gamma (lambda - h tauFF)).
// Being implicit, any k and c are stable; |lambda| is then clamped to maxTorque h.
// Far from its target the spring asks for a relative speed of (beta/h) |C|; that bias is clamped
// to maxSpeed in norm, so a large error is closed at a bounded speed instead of a whip, while a
// small one (|C| < maxSpeed h / beta) is tracked as before.
#pragma once

#include "physics/body.h"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace rise::physics {

struct Softness {
  float biasRate = 0.0f;      // 1/s
  float massScale = 1.0f;
  float impulseScale = 0.0f;
};

// A rigid constraint: no bias, full mass, no memory.
inline constexpr Softness kRigid{};

inline Softness MakeSoftness(float hertz, float dampingRatio, float h) {
  if (hertz <= 0.0f) return kRigid;
  const float omega = 2.0f * 3.14159265358979f * hertz;
  const float a1 = 2.0f * dampingRatio + h * omega;
  const float a2 = h * omega * a1;
  const float a3 = 1.0f / (1.0f + a2);
  return Softness{omega / a1, a2 * a3, a3};
}

// Per-solve context shared by every constraint of one sub-step.
struct SolverContext {
  float h = 0.0f;     // sub-step, s
  float invH = 0.0f;  // 1/s
  Softness contactSoftness;
  Softness staticContactSoftness;  // against static geometry: twice as stiff (Box2D v3)
  Softness jointSoftness;
  float contactPushMaxSpeed = 0.0f;  // m/s
  float contactRigidDepth = 0.0f;    // m (WorldSettings: hard contacts)
  float contactImpactSpeed = 0.0f;   // m/s
  float stepTime = 0.0f;             // s, the whole step: how far ahead the rigid depth looks
  bool warmStart = true;
};

inline glm::mat3 SkewMatrix(const glm::vec3& v) {
  return glm::mat3(0.0f, v.z, -v.y, -v.z, 0.0f, v.x, v.y, -v.x, 0.0f);
}

inline glm::vec3 PointVelocity(const Body& body, const glm::vec3& r) {
  return body.linearVelocity + glm::cross(body.angularVelocity, r);
}

// Applies +impulse at rB on B and -impulse at rA on A.
inline void ApplyLinearImpulse(Body& a, Body& b, const glm::vec3& rA, const glm::vec3& rB, const glm::vec3& impulse) {
  a.linearVelocity -= a.invMass * impulse;
  a.angularVelocity -= a.invInertiaWorld * glm::cross(rA, impulse);
  b.linearVelocity += b.invMass * impulse;
  b.angularVelocity += b.invInertiaWorld * glm::cross(rB, impulse);
}

// Applies +impulse to B's rotation and -impulse to A's (J = [0, -axis, 0, axis] for each axis).
inline void ApplyAngularImpulse(Body& a, Body& b, const glm::vec3& impulse) {
  a.angularVelocity -= a.invInertiaWorld * impulse;
  b.angularVelocity += b.invInertiaWorld * impulse;
}

// 1 / (J M^-1 J^T) for a linear row along n at lever arms rA, rB.
inline float LinearEffectiveMass(const Body& a, const Body& b, const glm::vec3& rA, const glm::vec3& rB,
                                 const glm::vec3& n) {
  const glm::vec3 rnA = glm::cross(rA, n);
  const glm::vec3 rnB = glm::cross(rB, n);
  const float k = a.invMass + b.invMass + glm::dot(rnA, a.invInertiaWorld * rnA) + glm::dot(rnB, b.invInertiaWorld * rnB);
  return k > 0.0f ? 1.0f / k : 0.0f;
}

// 1 / (J M^-1 J^T) for an angular row about axis; invInertiaSum = IA^-1 + IB^-1.
inline float AngularEffectiveMass(const glm::mat3& invInertiaSum, const glm::vec3& axis) {
  const float k = glm::dot(axis, invInertiaSum * axis);
  return k > 0.0f ? 1.0f / k : 0.0f;
}

// Point part (ball socket): C = (xB + rB) - (xA + rA) = 0, three rows solved together.
//   Cdot = vB + wB x rB - vA - wA x rA
//   K = (mA + mB) 1 - [rA]x IA^-1 [rA]x - [rB]x IB^-1 [rB]x
// K^-1 is computed once per step (PointPartMass) from the step's starting pose, as contacts do;
// C and Cdot use the lever arms rA, rB where the bodies are now.
inline glm::mat3 PointPartMass(const Body& a, const Body& b, const glm::vec3& localAnchorA,
                               const glm::vec3& localAnchorB) {
  const glm::mat3 sA = SkewMatrix(a.transform.rotation * localAnchorA);
  const glm::mat3 sB = SkewMatrix(b.transform.rotation * localAnchorB);
  return glm::inverse(glm::mat3(a.invMass + b.invMass) - sA * a.invInertiaWorld * sA - sB * b.invInertiaWorld * sB);
}

inline void SolvePointPart(Body& a, Body& b, const glm::vec3& rA, const glm::vec3& rB, const glm::mat3& mass,
                           glm::vec3& accumulated, const SolverContext& context, bool useBias) {
  const glm::vec3 cdot = PointVelocity(b, rB) - PointVelocity(a, rA);
  glm::vec3 bias(0.0f);
  Softness soft = kRigid;
  if (useBias) {
    const glm::vec3 c = (b.transform.position + rB) - (a.transform.position + rA);
    soft = context.jointSoftness;
    bias = soft.biasRate * c;
  }
  const glm::vec3 impulse = -soft.massScale * (mass * (cdot + bias)) - soft.impulseScale * accumulated;
  accumulated += impulse;
  ApplyLinearImpulse(a, b, rA, rB, impulse);
}

// Angular equality row: C = position (measured about axis) = 0, Cdot = axis . (wB - wA);
// mass is the row's AngularEffectiveMass.
inline void SolveAngularEquality(Body& a, Body& b, const glm::vec3& axis, float mass, float position,
                                 float& accumulated, const SolverContext& context, bool useBias) {
  const float cdot = glm::dot(axis, b.angularVelocity - a.angularVelocity);
  const Softness soft = useBias ? context.jointSoftness : kRigid;
  const float bias = useBias ? soft.biasRate * position : 0.0f;
  const float impulse = -soft.massScale * mass * (cdot + bias) - soft.impulseScale * accumulated;
  accumulated += impulse;
  ApplyAngularImpulse(a, b, impulse * axis);
}

// Angular inequality row: C = position >= 0 along axis, impulse >= 0, with cdot = axis . (wB - wA)
// measured by the caller. Always active: while the limit is not reached the bias C/h lets the
// bodies close the gap in this sub-step but no further (speculative, like contacts), so a fast limb
// cannot jump past its limit. Returns whether it changed the velocities.
inline bool SolveAngularLimit(Body& a, Body& b, const glm::vec3& axis, float cdot, float mass, float position,
                              float& accumulated, const SolverContext& context, bool useBias) {
  float bias = 0.0f;
  Softness soft = kRigid;
  if (position > 0.0f) {
    bias = position * context.invH;
  } else if (useBias) {
    soft = context.jointSoftness;
    bias = soft.biasRate * position;
  }
  // An idle row that would only pull is clamped to zero anyway.
  if (accumulated == 0.0f && cdot + bias >= 0.0f) return false;
  const float impulse = -soft.massScale * mass * (cdot + bias) - soft.impulseScale * accumulated;
  const float newAccumulated = std::max(accumulated + impulse, 0.0f);
  ApplyAngularImpulse(a, b, (newAccumulated - accumulated) * axis);
  accumulated = newAccumulated;
  return true;
}

// Both rows of a limited angle: lower <= angle <= upper about axis. The upper row is the lower
// one with the axis reversed, so while the lower row leaves the velocities alone its Cdot is the
// negated lower one (negation is exact in floating point) and is not measured twice.
inline void SolveAngularRange(Body& a, Body& b, const glm::vec3& axis, float mass, float angle, float lower,
                              float upper, float& lowerAccumulated, float& upperAccumulated,
                              const SolverContext& context, bool useBias) {
  float cdot = glm::dot(axis, b.angularVelocity - a.angularVelocity);
  if (SolveAngularLimit(a, b, axis, cdot, mass, angle - lower, lowerAccumulated, context, useBias)) {
    cdot = glm::dot(axis, b.angularVelocity - a.angularVelocity);
  }
  SolveAngularLimit(a, b, -axis, -cdot, mass, upper - angle, upperAccumulated, context, useBias);
}

// Gains of a PD motor for one sub-step (see the header comment).
struct MotorGains {
  float stiffness = 0.0f;      // k, N m / rad
  float damping = 0.0f;        // c, N m s / rad
  float maxTorque = 0.0f;      // N m, clamp on the norm of the motor torque
  glm::vec3 feedForward{0.0f}; // N m, world, torque on B (A gets the opposite)
  float maxSpeed = std::numeric_limits<float>::infinity();  // rad/s, clamp on the norm of the spring's bias
};

// The parts of a PD motor's solve over `count` (1..3) world axes that depend only on the poses,
// the gains and h, so each pass measures nothing but Cdot (see the header comment).
struct MotorPartTerms {
  bool springy = false;       // c + h k > 0: otherwise the motor is the pure feed-forward torque
  glm::mat3 mass{0.0f};       // (K + gamma 1)^-1, K_ij = u_i . (IA^-1 + IB^-1) u_j
  float gamma = 0.0f;         // 1 / (h (c + h k))
  float bias[3] = {};         // (beta / h) c_i for the errors c_i (rad) about the axes
  float feedForward[3] = {};  // h u_i . tauFF, the feed-forward impulse about each axis
};

// Computes MotorPartTerms for errors c[i] measured about the axes. It is rebuilt whenever the
// poses change, while every pass of a sub-step reuses it.
inline MotorPartTerms MakeMotorPartTerms(const glm::mat3& invInertiaSum, const glm::vec3* axes, const float* c,
                                         int count, const MotorGains& gains, float h) {
  MotorPartTerms terms;
  for (int i = 0; i < count; ++i) terms.feedForward[i] = h * glm::dot(axes[i], gains.feedForward);
  const float kh = gains.stiffness * h + gains.damping;
  if (kh <= 0.0f) return terms;
  terms.springy = true;
  terms.gamma = 1.0f / (h * kh);
  const float betaOverH = gains.stiffness / kh;
  float biasNorm2 = 0.0f;
  for (int i = 0; i < count; ++i) {
    terms.bias[i] = betaOverH * c[i];
    biasNorm2 += terms.bias[i] * terms.bias[i];
  }
  if (biasNorm2 > gains.maxSpeed * gains.maxSpeed) {
    const float scale = gains.maxSpeed / std::sqrt(biasNorm2);
    for (int i = 0; i < count; ++i) terms.bias[i] *= scale;
  }
  // I^-1 u_j once per axis rather than once per entry of K.
  glm::vec3 inertiaAxes[3];
  for (int j = 0; j < count; ++j) inertiaAxes[j] = invInertiaSum * axes[j];
  glm::mat3 k(1.0f);
  for (int i = 0; i < count; ++i) {
    for (int j = 0; j < count; ++j) k[j][i] = glm::dot(axes[i], inertiaAxes[j]);
    k[i][i] += terms.gamma;
  }
  terms.mass = glm::inverse(k);
  return terms;
}

// PD motor part over `count` (1..3) world axes with `terms` from MakeMotorPartTerms. The
// accumulated impulse is in axis coordinates; the world torque it makes is clamped to maxTorque h
// in norm (a universal joint's axes are not orthogonal once it bends, so clamping the coordinates
// alone would let the torque exceed the cap).
inline void SolveMotorPart(Body& a, Body& b, const glm::vec3* axes, int count, const MotorGains& gains,
                           const MotorPartTerms& terms, glm::vec3& accumulated, const SolverContext& context) {
  glm::vec3 target = accumulated;
  if (terms.springy) {
    const glm::vec3 relativeW = b.angularVelocity - a.angularVelocity;
    glm::vec3 rhs(0.0f);
    for (int i = 0; i < count; ++i) {
      rhs[i] = glm::dot(axes[i], relativeW) + terms.bias[i] + terms.gamma * (accumulated[i] - terms.feedForward[i]);
    }
    target = accumulated - terms.mass * rhs;
  } else {
    // No spring and no damper: the motor is a pure torque.
    for (int i = 0; i < count; ++i) target[i] = terms.feedForward[i];
  }
  const float maxImpulse = gains.maxTorque * context.h;
  glm::vec3 worldTarget(0.0f);
  for (int i = 0; i < count; ++i) worldTarget += target[i] * axes[i];
  const float norm = glm::length(worldTarget);
  if (norm > maxImpulse) target *= maxImpulse / norm;
  glm::vec3 impulse(0.0f);
  for (int i = 0; i < count; ++i) impulse += (target[i] - accumulated[i]) * axes[i];
  accumulated = target;
  ApplyAngularImpulse(a, b, impulse);
}

}  // namespace rise::physics
