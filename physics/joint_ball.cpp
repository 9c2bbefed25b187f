// SPDX-License-Identifier: MIT
// Ball-socket joint: point part, swing-cone and twist limits, 3-axis motor.
//
// With xA = qA frameA e_x and xB = qB frameB e_x (the twist axes of both sides in world space):
//   Swing cone: phi = acos(xA . xB) <= swingCone. Its rate is dphi/dt = n . (wB - wA) with
//               n = (xA x xB) / |xA x xB|, so the row is the upper limit about n.
//   Twist:      qRel = qSwing qTwist with qTwist = (w, x, 0, 0) / |.| about e_x;
//               theta = 2 atan2(x, w) in twistLimits, measured about t = (xA + xB) / |xA + xB|,
//               the axis that bisects both twist axes (as Jolt's SwingTwistConstraint).
// The motor acts on all three world axes.
#include "physics/joint.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace rise::physics {

void BallRows(const Joint& joint, const glm::quat& frameA, const glm::quat& frameB, AngularRows& rows) {
  rows.lockCount = 0;
  rows.limitCount = 0;
  rows.motorCount = 3;
  rows.motorAxis[0] = glm::vec3(1.0f, 0.0f, 0.0f);
  rows.motorAxis[1] = glm::vec3(0.0f, 1.0f, 0.0f);
  rows.motorAxis[2] = glm::vec3(0.0f, 0.0f, 1.0f);
  if (!joint.enableLimits) return;

  const glm::vec3 xA = frameA * glm::vec3(1.0f, 0.0f, 0.0f);
  const glm::vec3 xB = frameB * glm::vec3(1.0f, 0.0f, 0.0f);

  glm::quat rel = glm::conjugate(frameA) * frameB;
  if (rel.w < 0.0f) rel = -rel;
  const glm::vec3 bisector = xA + xB;
  const float bisectorLength = glm::length(bisector);
  rows.limitAxis[0] = bisectorLength > 1e-6f ? bisector / bisectorLength : xA;
  rows.angle[0] = 2.0f * std::atan2(rel.x, rel.w);
  rows.range[0] = joint.twistLimits;

  // Near zero swing the cone axis is undefined, but the limit is then far away and any axis
  // perpendicular to the twist axis keeps the row (and its warm-start slot) harmless.
  const glm::vec3 normal = glm::cross(xA, xB);
  const float normalLength = glm::length(normal);
  rows.limitAxis[1] = normalLength > 1e-6f ? normal / normalLength : frameA * glm::vec3(0.0f, 1.0f, 0.0f);
  rows.angle[1] = std::acos(std::clamp(glm::dot(xA, xB), -1.0f, 1.0f));
  rows.range[1] = AngleRange{-1.0f, joint.swingCone};
  rows.limitCount = 2;
}

}  // namespace rise::physics
