// SPDX-License-Identifier: MIT
// Universal (Cardan, swing-only) joint for hips and shoulders: point part, twist lock, per-axis
// limits, 2-axis motor.
//
// a1 = qA frameA e_y (first axis, on A); b2 = qB frameB e_z (second axis, on B). The joint allows
// qRel = Ry(alpha) Rz(beta) and nothing else, i.e. twist about the bone (e_x) is locked.
//   Lock: C = a1 . b2 = 0 (the two axes stay perpendicular); Cdot = (wB - wA) . (b2 x a1).
//   Angles: with R = mat(qRel), R e_z = (sin alpha, 0, cos alpha) and R^T e_y = (sin beta, cos beta, 0):
//     alpha = atan2(R[2].x, R[2].z),  beta = atan2(R[0].y, R[1].y).
//   Rates: wB - wA = alpha' a1 + beta' b2 and a1 . b2 = 0, so alpha' = a1 . (wB - wA) and
//   beta' = b2 . (wB - wA): the limit rows are exact 1-D rows about a1 and b2.
// At beta = +-90 deg the bone lies along a1, so alpha turns it about itself; the lock keeps
// |b2 x a1| = 1 and the angles stay defined, so nothing degenerates there.
// The motor acts about a1 and b2.
#include "physics/joint.h"

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include <cmath>

namespace rise::physics {

void UniversalRows(const Joint& joint, const glm::quat& frameA, const glm::quat& frameB, AngularRows& rows) {
  const glm::vec3 a1 = frameA * glm::vec3(0.0f, 1.0f, 0.0f);
  const glm::vec3 b2 = frameB * glm::vec3(0.0f, 0.0f, 1.0f);

  rows.lockCount = 1;
  rows.lockAxis[0] = glm::cross(b2, a1);
  rows.lockPosition[0] = glm::dot(a1, b2);

  rows.motorCount = 2;
  rows.motorAxis[0] = a1;
  rows.motorAxis[1] = b2;

  rows.limitCount = 0;
  if (joint.enableLimits) {
    const glm::mat3 r = glm::mat3_cast(glm::conjugate(frameA) * frameB);
    rows.limitCount = 2;
    rows.limitAxis[0] = a1;
    rows.angle[0] = std::atan2(r[2].x, r[2].z);
    rows.range[0] = joint.swingYLimits;
    rows.limitAxis[1] = b2;
    rows.angle[1] = std::atan2(r[0].y, r[1].y);
    rows.range[1] = joint.swingZLimits;
  }
}

}  // namespace rise::physics
