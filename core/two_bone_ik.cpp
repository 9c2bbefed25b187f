// SPDX-License-Identifier: MIT
#include "core/two_bone_ik.h"

#include "base/assert.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat3x3.hpp>

#include <algorithm>
#include <cmath>

namespace rise {
namespace {

bool Finite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Any unit vector perpendicular to `v` (used when the pole is degenerate).
glm::vec3 AnyPerpendicular(const glm::vec3& v) {
  const glm::vec3 axis = std::fabs(v.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
  return glm::normalize(glm::cross(v, axis));
}

// Orthonormal frame whose first column is the bone direction and whose second
// is the bend-plane normal; rotations map the rest frame onto the current one.
glm::mat3 BoneFrame(const glm::vec3& direction, const glm::vec3& planeNormal) {
  return glm::mat3(direction, planeNormal, glm::cross(direction, planeNormal));
}

}  // namespace

bool TwoBoneIk::Validate() const {
  return upperLength > 0.0f && lowerLength > 0.0f && Finite(root) && Finite(target) && Finite(pole) &&
         std::isfinite(swivel) && maxFlexion > 0.0f && maxFlexion < 3.14159265f &&
         glm::length(restBoneDirection) > 0.5f && glm::length(restPole) > 0.5f;
}

void TwoBoneIk::Solve() {
  RISE_ASSERT(Validate());
  const float a = upperLength, b = lowerLength;
  glm::vec3 toTarget = target - root;
  float distance = glm::length(toTarget);
  const glm::vec3 axis = distance > 1e-6f ? toTarget / distance : restBoneDirection;

  // Reach limits: fully straight, and the distance at the largest allowed
  // flexion (law of cosines). The bend plane comes from the pole, so it stays
  // defined for a straight limb.
  const float maxReach = a + b;
  const float minReach = std::sqrt(a * a + b * b + 2.0f * a * b * std::cos(maxFlexion));
  reached = distance <= maxReach && distance >= minReach;
  distance = std::clamp(distance, minReach, maxReach);
  end = root + axis * distance;

  // Bend plane: the pole made perpendicular to the axis, then swivelled.
  glm::vec3 bend = pole - axis * glm::dot(pole, axis);
  bend = glm::length(bend) > 1e-6f ? glm::normalize(bend) : AnyPerpendicular(axis);
  bend = glm::angleAxis(swivel, axis) * bend;

  // Angle at the root between the axis and the upper bone (law of cosines).
  const float cosRoot = std::clamp((a * a + distance * distance - b * b) / (2.0f * a * distance), -1.0f, 1.0f);
  const float rootAngle = std::acos(cosRoot);
  const glm::vec3 upperDirection = axis * std::cos(rootAngle) + bend * std::sin(rootAngle);
  mid = root + upperDirection * a;
  const glm::vec3 lowerDirection = glm::normalize(end - mid);
  flexion = std::acos(std::clamp(glm::dot(upperDirection, lowerDirection), -1.0f, 1.0f));

  const glm::vec3 planeNormal = glm::normalize(glm::cross(axis, bend));
  const glm::vec3 restDirection = glm::normalize(restBoneDirection);
  const glm::vec3 restNormal = glm::normalize(glm::cross(restDirection, restPole));
  const glm::mat3 restFrameT = glm::transpose(BoneFrame(restDirection, restNormal));
  upperRotation = glm::normalize(glm::quat_cast(BoneFrame(upperDirection, planeNormal) * restFrameT));
  lowerRotation = glm::normalize(glm::quat_cast(BoneFrame(lowerDirection, planeNormal) * restFrameT));
}

}  // namespace rise
