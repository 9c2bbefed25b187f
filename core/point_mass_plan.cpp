// SPDX-License-Identifier: MIT
#include "core/point_mass_plan.h"

#include "base/assert.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <limits>

namespace rise {
namespace {

bool InRange(float length, const LimbRange& range, float slack) {
  return length >= range.minLength - slack && length <= range.maxLength + slack;
}

// How far a candidate violates the limb limits, summed (0 when feasible).
float Violation(const PointMassPlan& plan, const glm::vec3& c) {
  auto over = [](float length, const LimbRange& range) {
    return std::fmax(0.0f, range.minLength - length) + std::fmax(0.0f, length - range.maxLength);
  };
  float v = over(glm::length(c - plan.footLeft), plan.leg) + over(glm::length(c - plan.footRight), plan.leg);
  if (plan.hasSupportHand) v += over(glm::length(c - plan.supportHand), plan.arm);
  return v;
}

}  // namespace

bool PointMassPlan::Validate() const {
  return leg.minLength > 0.0f && leg.maxLength > leg.minLength && arm.minLength > 0.0f &&
         arm.maxLength > arm.minLength && maxStep > 0.0f && std::isfinite(com.x + com.y + com.z);
}

bool PointMassPlan::LimbsWithinRange(const glm::vec3& c, float slack) const {
  return InRange(glm::length(c - footLeft), leg, slack) && InRange(glm::length(c - footRight), leg, slack) &&
         (!hasSupportHand || InRange(glm::length(c - supportHand), arm, slack));
}

void PointMassPlan::Solve() {
  RISE_ASSERT(Validate());
  const SupportPolygon feet =
      feetRegion.Empty() ? SupportPolygon::FromPoints({Ground(footLeft), Ground(footRight)}) : feetRegion;
  const glm::vec2 goal = feet.Closest(Ground(com));

  // A deterministic search over a small grid of candidates around the line
  // from the CoM to its goal (the model has 3 unknowns, so a grid is both cheap
  // and free of the local minima a gradient method meets at the length limits).
  // Lexicographic cost: primary violation first, then horizontal distance to
  // the feet, then the distance moved (prefer small, smooth steps).
  const glm::vec2 start = Ground(com);
  glm::vec2 direction = goal - start;
  const float gap = glm::length(direction);
  direction = gap > 1e-6f ? direction / gap : glm::vec2(0.0f);
  const float reach = std::fmin(gap, maxStep);
  const float lowest = std::fmax(minHeight, com.y - maxStep);
  const float highest = com.y + maxStep;

  float bestViolation = std::numeric_limits<float>::max();
  float bestDistance = std::numeric_limits<float>::max();
  float bestMove = std::numeric_limits<float>::max();
  glm::vec3 best = com;
  constexpr int kAlong = 16, kHeights = 12;
  for (int i = 0; i <= kAlong; ++i) {
    const glm::vec2 ground = start + direction * (reach * static_cast<float>(i) / kAlong);
    for (int k = 0; k <= kHeights; ++k) {
      const float height = lowest + (highest - lowest) * static_cast<float>(k) / kHeights;
      const glm::vec3 candidate(ground.x, height, ground.y);
      const float violation = Violation(*this, candidate);
      const float distance = std::fmax(0.0f, feet.SignedDistance(ground));
      const float move = glm::length(candidate - com);
      const bool better = violation < bestViolation - 1e-5f ||
                          (violation <= bestViolation + 1e-5f &&
                           (distance < bestDistance - 1e-4f || (distance <= bestDistance + 1e-4f && move < bestMove)));
      if (better) bestViolation = violation, bestDistance = distance, bestMove = move, best = candidate;
    }
  }
  target = best;
  feasible = bestViolation <= 1e-5f;
  distanceToFeet = bestDistance;
  overFeet = feasible && bestDistance <= 1e-3f;
}

}  // namespace rise
