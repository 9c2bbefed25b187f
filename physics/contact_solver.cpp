// SPDX-License-Identifier: MIT
// Contact solver: non-penetration and friction rows of every manifold point.
//
// Normal row (per point, n from A to B, anchors rA, rB):
//   C = s = separation + n . (pB - pA) >= 0, the separation at the current sub-step positions;
//   Cdot = n . (vB + wB x rB - vA - wA x rA);  J = [-n, -rA x n, n, rB x n];
//   K = mA + mB + (rA x n) . IA^-1 (rA x n) + (rB x n) . IB^-1 (rB x n).
//   s > 0 (speculative): bias = s / h, so the bodies may close the gap this sub-step but not more.
//   s <= 0 and useBias: soft, bias = max(biasRate s, -pushMaxSpeed); impulse scaled by the
//   softness (constraint_parts.h). Accumulated impulse >= 0.
// Friction rows along the tangents t1, t2 (same form with t instead of n), no bias; the
// accumulated tangent impulse vector is clamped to the disc |lambda_t| <= mu lambda_n (Coulomb cone).
//
// Why soft step + relax: the biased solve pushes overlap out as a damped spring, but the
// velocity it adds to do so is removed by the unbiased relax pass after positions are
// integrated, so position correction moves bodies without leaving them kinetic energy (no
// "pop" out of the ground, no bounce from Baumgarte). Restitution is 0, so there is no
// restitution pass.
#include "physics/contact_solver.h"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>

namespace rise::physics {

namespace {

Body& SideA(const Contact& contact, std::vector<Body>& bodies, Body& staticBody) {
  return contact.bodyA >= 0 ? bodies[contact.bodyA] : staticBody;
}

}  // namespace

void PrepareContacts(std::vector<Contact>& contacts, const std::vector<Body>& bodies, const Body& staticBody,
                     const SolverContext& context) {
  for (Contact& contact : contacts) {
    const Body& a = contact.bodyA >= 0 ? bodies[contact.bodyA] : staticBody;
    const Body& b = bodies[contact.bodyB];
    for (int i = 0; i < contact.pointCount; ++i) {
      ContactPoint& cp = contact.points[i];
      const glm::vec3 rA = a.transform.rotation * cp.localAnchorA;
      const glm::vec3 rB = b.transform.rotation * cp.localAnchorB;
      cp.normalMass = LinearEffectiveMass(a, b, rA, rB, contact.normal);
      cp.tangentMass[0] = LinearEffectiveMass(a, b, rA, rB, contact.tangent[0]);
      cp.tangentMass[1] = LinearEffectiveMass(a, b, rA, rB, contact.tangent[1]);
      if (!context.warmStart) {
        cp.normalImpulse = 0.0f;
        cp.tangentImpulse[0] = cp.tangentImpulse[1] = 0.0f;
      }
    }
  }
}

void WarmStartContacts(std::vector<Contact>& contacts, std::vector<Body>& bodies, Body& staticBody) {
  for (Contact& contact : contacts) {
    Body& a = SideA(contact, bodies, staticBody);
    Body& b = bodies[contact.bodyB];
    for (int i = 0; i < contact.pointCount; ++i) {
      const ContactPoint& cp = contact.points[i];
      const glm::vec3 rA = a.transform.rotation * cp.localAnchorA;
      const glm::vec3 rB = b.transform.rotation * cp.localAnchorB;
      const glm::vec3 impulse = cp.normalImpulse * contact.normal + cp.tangentImpulse[0] * contact.tangent[0] +
                                cp.tangentImpulse[1] * contact.tangent[1];
      ApplyLinearImpulse(a, b, rA, rB, impulse);
    }
  }
}

void SolveContacts(std::vector<Contact>& contacts, std::vector<Body>& bodies, Body& staticBody,
                   const SolverContext& context, bool useBias) {
  for (Contact& contact : contacts) {
    Body& a = SideA(contact, bodies, staticBody);
    Body& b = bodies[contact.bodyB];
    const glm::vec3 n = contact.normal;

    for (int i = 0; i < contact.pointCount; ++i) {
      ContactPoint& cp = contact.points[i];
      const glm::vec3 rA = a.transform.rotation * cp.localAnchorA;
      const glm::vec3 rB = b.transform.rotation * cp.localAnchorB;
      const glm::vec3 pA = a.transform.position + rA;
      const glm::vec3 pB = b.transform.position + rB;
      const float s = cp.separation + glm::dot(n, pB - pA);

      float bias = 0.0f;
      Softness soft = kRigid;
      if (s > 0.0f) {
        bias = s * context.invH;
      } else if (useBias) {
        soft = context.contactSoftness;
        bias = std::max(soft.biasRate * s, -context.contactPushMaxSpeed);
      }
      const float vn = glm::dot(n, PointVelocity(b, rB) - PointVelocity(a, rA));
      const float impulse = -soft.massScale * cp.normalMass * (vn + bias) - soft.impulseScale * cp.normalImpulse;
      const float newImpulse = std::max(cp.normalImpulse + impulse, 0.0f);
      ApplyLinearImpulse(a, b, rA, rB, (newImpulse - cp.normalImpulse) * n);
      cp.normalImpulse = newImpulse;
    }

    for (int i = 0; i < contact.pointCount; ++i) {
      ContactPoint& cp = contact.points[i];
      const glm::vec3 rA = a.transform.rotation * cp.localAnchorA;
      const glm::vec3 rB = b.transform.rotation * cp.localAnchorB;
      const glm::vec3 dv = PointVelocity(b, rB) - PointVelocity(a, rA);
      const float old0 = cp.tangentImpulse[0];
      const float old1 = cp.tangentImpulse[1];
      float new0 = old0 - cp.tangentMass[0] * glm::dot(dv, contact.tangent[0]);
      float new1 = old1 - cp.tangentMass[1] * glm::dot(dv, contact.tangent[1]);
      const float maxFriction = contact.friction * cp.normalImpulse;
      const float lengthSquared = new0 * new0 + new1 * new1;
      if (lengthSquared > maxFriction * maxFriction) {
        const float scale = maxFriction / std::sqrt(lengthSquared);
        new0 *= scale;
        new1 *= scale;
      }
      cp.tangentImpulse[0] = new0;
      cp.tangentImpulse[1] = new1;
      ApplyLinearImpulse(a, b, rA, rB, (new0 - old0) * contact.tangent[0] + (new1 - old1) * contact.tangent[1]);
    }
  }
}

}  // namespace rise::physics
