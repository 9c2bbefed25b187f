// SPDX-License-Identifier: MIT
// Gimbal (3-axis Cardan) joint for the spine and neck: point part, a limit on each of its three
// angles, 3-axis motor.
//
// The joint allows qRel = Ry(alpha) Rz(beta) Rx(gamma): swing about A's y, then about the middle
// axis, then twist about B's x (the bone). Each angle has its own range (swingYLimits,
// swingZLimits, twistLimits), which a swing cone cannot express: the lower spine flexes 45 deg
// but bends sideways only 25.
//   Axes (world): a1 = qA frameA e_y, b3 = qB frameB e_x, m = (b3 x a1) / cos(beta), the z axis
//   after the first rotation; a1 . m = b3 . m = 0.
//   Angles: with R = mat(qRel), R e_x = (cos alpha cos beta, sin beta, -sin alpha cos beta) and
//   R^T e_y = (sin beta, cos beta cos gamma, -cos beta sin gamma).
//   Rates: wB - wA = alpha' a1 + beta' m + gamma' b3. The three axes are not orthogonal, so each
//   rate is the dot product with its dual vector, e.g. alpha' = (m x b3) . (wB - wA) / D with
//   D = a1 . (m x b3) = cos(beta); the limit rows use the duals as their (non-unit) axes.
// Gimbal lock sits at beta = +-90 deg, where D vanishes; keep swingZLimits inside it.
// The motor acts on all three world axes.
#include "physics/joint.h"

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>

#include <algorithm>
#include <cmath>

namespace rise::physics {

void GimbalRows(const Joint& joint, const glm::quat& frameA, const glm::quat& frameB, AngularRows& rows) {
  rows.lockCount = 0;
  rows.motorCount = 3;
  rows.motorAxis[0] = glm::vec3(1.0f, 0.0f, 0.0f);
  rows.motorAxis[1] = glm::vec3(0.0f, 1.0f, 0.0f);
  rows.motorAxis[2] = glm::vec3(0.0f, 0.0f, 1.0f);
  rows.limitCount = 0;
  if (!joint.enableLimits) return;

  const glm::mat3 r = glm::mat3_cast(glm::conjugate(frameA) * frameB);
  const float alpha = std::atan2(-r[0].z, r[0].x);
  const float beta = std::atan2(r[0].y, std::sqrt(r[1].y * r[1].y + r[2].y * r[2].y));
  const float gamma = std::atan2(-r[2].y, r[1].y);

  const glm::vec3 a1 = frameA * glm::vec3(0.0f, 1.0f, 0.0f);
  const glm::vec3 b3 = frameB * glm::vec3(1.0f, 0.0f, 0.0f);
  // Clamped away from the gimbal lock, where the rows would demand unbounded rates.
  const float cosBeta = std::max(std::cos(beta), 0.05f);
  const glm::vec3 m = glm::cross(b3, a1) / cosBeta;
  rows.limitCount = 3;
  rows.limitAxis[0] = glm::cross(m, b3) / cosBeta;
  rows.angle[0] = alpha;
  rows.range[0] = joint.swingYLimits;
  rows.limitAxis[1] = m;
  rows.angle[1] = beta;
  rows.range[1] = joint.swingZLimits;
  rows.limitAxis[2] = glm::cross(a1, m) / cosBeta;
  rows.angle[2] = gamma;
  rows.range[2] = joint.twistLimits;
}

}  // namespace rise::physics
