// SPDX-License-Identifier: MIT
// Contact solver: non-penetration and friction rows of every manifold point.
//
// Normal row (per point, n from A to B, anchors rA = p - xA, rB = p - xB fixed for the step):
//   C = s >= 0, the separation at the current sub-step, from the body deltas since the step began:
//       s = separation + n . (dxB - dxA) + dthetaB . (rB x n) - dthetaA . (rA x n)
//   Cdot = n . (vB - vA) + wB . (rB x n) - wA . (rA x n);  J = [-n, -rA x n, n, rB x n];
//   K = mA + mB + (rA x n) . IA^-1 (rA x n) + (rB x n) . IB^-1 (rB x n).
//   s > 0 (speculative): bias = s / h, so the bodies may close the gap this sub-step but not more.
//   s <= 0 and useBias: soft, bias = max(biasRate s, -pushMaxSpeed); impulse scaled by the
//   softness (constraint_parts.h), twice as stiff against static geometry. Accumulated impulse >= 0.
//   At rest the soft normal row settles at s = -g / (2 pi f)^2: 0.07 mm on the ground at 60 Hz.
//   Hard points on static geometry (WorldSettings, "hard contacts"): s < -d/2 and
//   s + min(Cdot, 0) T < -d (d the rigid depth, T the step), or Cdot < -impact speed. The row of a
//   hard overlapping point is rigid (massScale 1, impulseScale 0) with the same bias.
//   Why: the soft row's steady state under a load of lambda per sub-step is
//   s = -lambda / (a2 m biasRate), with m the effective mass at the point, so a light hand pressed
//   by a heavy trunk through its joints settles centimetres deep however stiff the spring is.
// Friction rows along the tangents t1, t2 (same form with t instead of n), no bias; the
// accumulated tangent impulse vector is clamped to the disc |lambda_t| <= mu lambda_n (Coulomb cone).
// Anchors, inverse inertias and effective masses are frozen at PrepareContacts, as in Box2D v3:
// within one 1/240 s step a body turns by a few hundredths of a radian at most.
//
// Why soft step + relax: the biased solve pushes overlap out as a damped spring, but the
// velocity it adds to do so is removed by the unbiased relax pass after positions are
// integrated, so position correction moves bodies without leaving them kinetic energy (no
// "pop" out of the ground, no bounce from Baumgarte). Restitution is 0, so there is no
// restitution pass.
#include "physics/contact_solver.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace rise::physics {

namespace {

// kStaticA: side A is static geometry, which never moves and takes no impulse, so its terms are
// compiled out of the rows (most contacts of a ragdoll lying on the ground are of this kind).

// Relative velocity of B against A along row `row` of a point.
template <bool kStaticA>
float RowVelocity(const Body& a, const Body& b, const ContactPoint& cp, const glm::vec3& direction, int row) {
  if constexpr (kStaticA) {
    return glm::dot(direction, b.linearVelocity) + glm::dot(b.angularVelocity, cp.crossB[row]);
  } else {
    return glm::dot(direction, b.linearVelocity - a.linearVelocity) + glm::dot(b.angularVelocity, cp.crossB[row]) -
           glm::dot(a.angularVelocity, cp.crossA[row]);
  }
}

template <bool kStaticA>
void ApplyRowImpulse(Body& a, Body& b, const ContactPoint& cp, const glm::vec3& direction, int row, float impulse) {
  if constexpr (!kStaticA) {
    a.linearVelocity -= (a.invMass * impulse) * direction;
    a.angularVelocity -= impulse * cp.turnA[row];
  }
  b.linearVelocity += (b.invMass * impulse) * direction;
  b.angularVelocity += impulse * cp.turnB[row];
}

template <bool kStaticA>
void PrepareContact(Contact& contact, const Body& a, const Body& b, const SolverContext& context) {
  const glm::vec3 directions[3] = {contact.normal, contact.tangent[0], contact.tangent[1]};
  for (int i = 0; i < contact.pointCount; ++i) {
    ContactPoint& cp = contact.points[i];
    const glm::vec3 rA = cp.point - a.transform.position;
    const glm::vec3 rB = cp.point - b.transform.position;
    for (int row = 0; row < 3; ++row) {
      cp.crossB[row] = glm::cross(rB, directions[row]);
      cp.turnB[row] = b.invInertiaWorld * cp.crossB[row];
      float k = 0.0f;
      if constexpr (kStaticA) {
        k = b.invMass + glm::dot(cp.crossB[row], cp.turnB[row]);
      } else {
        cp.crossA[row] = glm::cross(rA, directions[row]);
        cp.turnA[row] = a.invInertiaWorld * cp.crossA[row];
        k = a.invMass + b.invMass + glm::dot(cp.crossA[row], cp.turnA[row]) + glm::dot(cp.crossB[row], cp.turnB[row]);
      }
      cp.mass[row] = k > 0.0f ? 1.0f / k : 0.0f;
    }
    if (!context.warmStart) {
      cp.normalImpulse = 0.0f;
      cp.tangentImpulse[0] = cp.tangentImpulse[1] = 0.0f;
    }
  }
}

template <bool kStaticA>
void WarmStartContact(const Contact& contact, Body& a, Body& b) {
  for (int i = 0; i < contact.pointCount; ++i) {
    const ContactPoint& cp = contact.points[i];
    // A new or speculative point has nothing to apply.
    if (cp.normalImpulse == 0.0f && cp.tangentImpulse[0] == 0.0f && cp.tangentImpulse[1] == 0.0f) continue;
    ApplyRowImpulse<kStaticA>(a, b, cp, contact.normal, 0, cp.normalImpulse);
    ApplyRowImpulse<kStaticA>(a, b, cp, contact.tangent[0], 1, cp.tangentImpulse[0]);
    ApplyRowImpulse<kStaticA>(a, b, cp, contact.tangent[1], 2, cp.tangentImpulse[1]);
  }
}

// Returns whether a point of a static contact was hard. Inlined into its loop as it was before
// it had a second caller (ResolveHardContact): 1 % of the fast drop's instructions per step.
template <bool kStaticA>
[[gnu::always_inline]] inline bool SolveContact(Contact& contact, Body& a, Body& b, const SolverContext& context,
                                                bool useBias) {
  const glm::vec3 n = contact.normal;
  // Static geometry has no step deltas: its side of the separation update is zero.
  const float approach =
      kStaticA ? glm::dot(n, b.deltaPosition) : glm::dot(n, b.deltaPosition - a.deltaPosition);
  const Softness& pushSoftness = kStaticA ? context.staticContactSoftness : context.contactSoftness;
  bool hard = false;

  for (int i = 0; i < contact.pointCount; ++i) {
    ContactPoint& cp = contact.points[i];
    float s = cp.separation + approach + glm::dot(b.deltaRotation, cp.crossB[0]);
    if constexpr (!kStaticA) s -= glm::dot(a.deltaRotation, cp.crossA[0]);
    const float vn = RowVelocity<kStaticA>(a, b, cp, n, 0);
    // Between bodies every row stays soft: two limbs overlapping deeply (a start pose, a hand in
    // the trunk) are also held by joints, and rigid rows fighting them threw limbs at 10-29 m/s
    // in the stress runner.
    bool rigid = false;
    if constexpr (kStaticA) {
      rigid = s < -0.5f * context.contactRigidDepth &&
              s + std::min(vn, 0.0f) * context.stepTime < -context.contactRigidDepth;
      hard = hard || rigid || vn < -context.contactImpactSpeed;
    }
    float bias = 0.0f;
    Softness soft = kRigid;
    if (s > 0.0f) {
      bias = s * context.invH;
    } else if (useBias) {
      soft = rigid ? kRigid : pushSoftness;
      bias = std::max(pushSoftness.biasRate * s, -context.contactPushMaxSpeed);
    }
    // A speculative point that is not closing its gap this sub-step stays at zero impulse.
    if (cp.normalImpulse == 0.0f && vn + bias >= 0.0f) continue;
    const float impulse = -soft.massScale * cp.mass[0] * (vn + bias) - soft.impulseScale * cp.normalImpulse;
    const float newImpulse = std::max(cp.normalImpulse + impulse, 0.0f);
    ApplyRowImpulse<kStaticA>(a, b, cp, n, 0, newImpulse - cp.normalImpulse);
    cp.normalImpulse = newImpulse;
  }

  for (int i = 0; i < contact.pointCount; ++i) {
    ContactPoint& cp = contact.points[i];
    // Without normal impulse the friction disc is a point: nothing to apply or to remove.
    if (cp.normalImpulse == 0.0f && cp.tangentImpulse[0] == 0.0f && cp.tangentImpulse[1] == 0.0f) continue;
    const float old0 = cp.tangentImpulse[0];
    const float old1 = cp.tangentImpulse[1];
    float new0 = old0 - cp.mass[1] * RowVelocity<kStaticA>(a, b, cp, contact.tangent[0], 1);
    float new1 = old1 - cp.mass[2] * RowVelocity<kStaticA>(a, b, cp, contact.tangent[1], 2);
    const float maxFriction = contact.friction * cp.normalImpulse;
    const float lengthSquared = new0 * new0 + new1 * new1;
    if (lengthSquared > maxFriction * maxFriction) {
      const float scale = maxFriction / std::sqrt(lengthSquared);
      new0 *= scale;
      new1 *= scale;
    }
    cp.tangentImpulse[0] = new0;
    cp.tangentImpulse[1] = new1;
    ApplyRowImpulse<kStaticA>(a, b, cp, contact.tangent[0], 1, new0 - old0);
    ApplyRowImpulse<kStaticA>(a, b, cp, contact.tangent[1], 2, new1 - old1);
  }
  return hard;
}

// The second solve of a hard static contact (SolveContacts), out of line so that the first,
// which every static contact takes, stays inlined in its loop.
[[gnu::noinline]] void ResolveHardContact(Contact& contact, Body& staticBody, Body& b, const SolverContext& context,
                                          bool useBias) {
  SolveContact<true>(contact, staticBody, b, context, useBias);
}

}  // namespace

void PrepareContacts(std::vector<Contact>& contacts, std::vector<Body>& bodies, Body& staticBody,
                     const SolverContext& context) {
  for (Body& body : bodies) {
    body.deltaPosition = glm::vec3(0.0f);
    body.deltaRotation = glm::vec3(0.0f);
  }
  for (Contact& contact : contacts) {
    if (contact.bodyA >= 0) {
      PrepareContact<false>(contact, bodies[contact.bodyA], bodies[contact.bodyB], context);
    } else {
      PrepareContact<true>(contact, staticBody, bodies[contact.bodyB], context);
    }
  }
}

void WarmStartContacts(std::vector<Contact>& contacts, std::vector<Body>& bodies, Body& staticBody) {
  for (Contact& contact : contacts) {
    if (contact.bodyA >= 0) {
      WarmStartContact<false>(contact, bodies[contact.bodyA], bodies[contact.bodyB]);
    } else {
      WarmStartContact<true>(contact, staticBody, bodies[contact.bodyB]);
    }
  }
}

bool SolveContacts(std::vector<Contact>& contacts, std::vector<Body>& bodies, Body& staticBody,
                   const SolverContext& context, bool useBias) {
  bool anyHard = false;
  for (Contact& contact : contacts) {
    if (contact.bodyA >= 0) {
      SolveContact<false>(contact, bodies[contact.bodyA], bodies[contact.bodyB], context, useBias);
    } else {
      contact.hard = SolveContact<true>(contact, staticBody, bodies[contact.bodyB], context, useBias);
      anyHard = anyHard || contact.hard;
    }
  }
  // Static contacts sort first (contact.cpp), so the body pairs push last: a hand under a landing
  // trunk got the trunk's push after its ground contact had spoken and sank. A hard static
  // contact is solved once more, so the ground has the last word; no other contact comes here.
  if (!anyHard) return false;
  for (Contact& contact : contacts) {
    if (contact.bodyA >= 0) break;
    if (contact.hard) ResolveHardContact(contact, staticBody, bodies[contact.bodyB], context, useBias);
  }
  return true;
}

}  // namespace rise::physics
