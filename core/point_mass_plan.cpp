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

// How far a candidate violates the primary constraints, summed (0 when feasible):
// the limb length limits and static balance over the support triangle.
float Violation(const PointMassPlan& plan, const SupportPolygon& support, const glm::vec3& c) {
  auto over = [](float length, const LimbRange& range) {
    return std::fmax(0.0f, range.minLength - length) + std::fmax(0.0f, length - range.maxLength);
  };
  float v = over(glm::length(c - plan.footLeft), plan.leg) + over(glm::length(c - plan.footRight), plan.leg);
  if (plan.hasSupportHand) v += over(glm::length(c - plan.supportHand), plan.arm);
  if (!support.Empty()) v += std::fmax(0.0f, support.SignedDistance(Ground(c)) + plan.balanceMargin);
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

SupportPolygon PointMassPlan::SupportTriangle() const {
  std::vector<glm::vec2> points = feetRegion.hull;
  if (points.empty()) points = {Ground(footLeft), Ground(footRight)};
  if (hasSupportHand) points.push_back(Ground(supportHand));
  return SupportPolygon::FromPoints(points);
}

void PointMassPlan::Solve() {
  RISE_ASSERT(Validate());
  const SupportPolygon support = SupportTriangle();
  const SupportPolygon feet =
      feetRegion.Empty() ? SupportPolygon::FromPoints({Ground(footLeft), Ground(footRight)}) : feetRegion;

  // A deterministic search over a grid of candidates within maxStep of the
  // CoM (the model has 3 unknowns, so a grid is both cheap and free of the
  // local minima a gradient method meets at the length and balance limits).
  // Lexicographic cost: primary violation first, then horizontal distance to
  // the feet (to 2 mm), then a comfortable height and a short move.
  const float lowest = std::fmax(minHeight, com.y - maxStep);
  const float highest = com.y + maxStep;
  float bestViolation = std::numeric_limits<float>::max();
  float bestDistance = std::numeric_limits<float>::max();
  float bestMove = std::numeric_limits<float>::max();
  glm::vec3 best = com;
  auto consider = [&](const glm::vec3& candidate) {
    const float violation = Violation(*this, support, candidate);
    const float distance = std::fmax(0.0f, feet.SignedDistance(Ground(candidate)));
    const float move = glm::length(candidate - com) +
                       (preferredHeight > 0.0f ? 2.0f * std::fabs(candidate.y - preferredHeight) : 0.0f);
    const bool better = violation < bestViolation - 1e-5f ||
                        (violation <= bestViolation + 1e-5f &&
                         (distance < bestDistance - 0.002f || (distance <= bestDistance + 0.002f && move < bestMove)));
    if (better) bestViolation = violation, bestDistance = distance, bestMove = move, best = candidate;
  };
  // A coarse pass over the disc of radius maxStep, then a fine pass around the
  // best coarse candidate, so narrow feasible regions are not stepped over.
  constexpr int kAcross = 8, kHeights = 10;
  const float coarse = maxStep / kAcross;
  for (int i = -kAcross; i <= kAcross; ++i) {
    for (int j = -kAcross; j <= kAcross; ++j) {
      const glm::vec2 offset = glm::vec2(i, j) * coarse;
      if (glm::length(offset) > maxStep + 1e-6f) continue;
      for (int k = 0; k <= kHeights; ++k) {
        const float height = lowest + (highest - lowest) * static_cast<float>(k) / kHeights;
        consider(glm::vec3(com.x + offset.x, height, com.z + offset.y));
      }
    }
  }
  const glm::vec3 centre = best;
  const float fine = coarse / kAcross;
  const float heightStep = (highest - lowest) / kHeights;
  for (int i = -kAcross; i <= kAcross; ++i) {
    for (int j = -kAcross; j <= kAcross; ++j) {
      for (int k = -2; k <= 2; ++k) {
        const glm::vec3 candidate = centre + glm::vec3(i * fine, 0.5f * k * heightStep, j * fine);
        if (glm::length(Ground(candidate) - Ground(com)) > maxStep + 1e-6f) continue;
        if (candidate.y < lowest || candidate.y > highest) continue;
        consider(candidate);
      }
    }
  }
  target = best;
  feasible = bestViolation <= 1e-5f;
  distanceToFeet = bestDistance;
  overFeet = feasible && bestDistance <= 1e-3f;
}

}  // namespace rise
