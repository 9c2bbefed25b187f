// SPDX-License-Identifier: MIT
// Hinge joint: point part, two axis locks, angle limits about the hinge axis, 1-axis motor.
//
// a1 = qA frameA e_x (hinge axis on A); b2 = qB frameB e_y, c2 = qB frameB e_z (on B).
//   Lock (as Jolt's HingeRotationConstraintPart): C = (a1 . b2, a1 . c2) = 0, zero at the bind
//   pose. dC1/dt = (wA x a1) . b2 + a1 . (wB x b2) = (wB - wA) . (b2 x a1), so u1 = b2 x a1 and
//   likewise u2 = c2 x a1.
//   Angle: qRel is (nearly) a pure rotation about e_x, theta = 2 atan2(qRel.x, qRel.w), whose
//   rate is a1 . (wB - wA); limited to twistLimits.
// The motor acts about a1.
#include "physics/joint.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace rise::physics {

void HingeRows(const Joint& joint, const glm::quat& frameA, const glm::quat& frameB, AngularRows& rows) {
  const glm::vec3 a1 = frameA * glm::vec3(1.0f, 0.0f, 0.0f);
  const glm::vec3 b2 = frameB * glm::vec3(0.0f, 1.0f, 0.0f);
  const glm::vec3 c2 = frameB * glm::vec3(0.0f, 0.0f, 1.0f);

  rows.lockCount = 2;
  rows.lockAxis[0] = glm::cross(b2, a1);
  rows.lockPosition[0] = glm::dot(a1, b2);
  rows.lockAxis[1] = glm::cross(c2, a1);
  rows.lockPosition[1] = glm::dot(a1, c2);

  rows.motorCount = 1;
  rows.motorAxis[0] = a1;

  rows.limitCount = 0;
  if (joint.enableLimits) {
    glm::quat rel = glm::conjugate(frameA) * frameB;
    if (rel.w < 0.0f) rel = -rel;
    rows.limitCount = 1;
    rows.limitAxis[0] = a1;
    rows.angle[0] = 2.0f * std::atan2(rel.x, rel.w);
    rows.range[0] = joint.twistLimits;
  }
}

}  // namespace rise::physics
