// SPDX-License-Identifier: MIT
#include "core/support_polygon.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <limits>

namespace rise {
namespace {

// z-component of (b - a) x (c - a) in the (x, z) plane viewed from +Y.
// Positive when a -> b -> c turns counter-clockwise seen from above.
float Turn(const glm::vec2& a, const glm::vec2& b, const glm::vec2& c) {
  // Seen from +Y the (x, z) axes form a left-handed 2D frame, so the usual
  // cross product's sign is inverted.
  return -((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x));
}

glm::vec2 ClosestOnSegment(const glm::vec2& p, const glm::vec2& a, const glm::vec2& b) {
  const glm::vec2 ab = b - a;
  const float len2 = glm::dot(ab, ab);
  const float t = len2 > 0.0f ? std::clamp(glm::dot(p - a, ab) / len2, 0.0f, 1.0f) : 0.0f;
  return a + ab * t;
}

}  // namespace

SupportPolygon SupportPolygon::FromPoints(const std::vector<glm::vec2>& points) {
  // Andrew's monotone chain.
  std::vector<glm::vec2> sorted = points;
  std::sort(sorted.begin(), sorted.end(),
            [](const glm::vec2& a, const glm::vec2& b) { return a.x < b.x || (a.x == b.x && a.y < b.y); });
  sorted.erase(std::unique(sorted.begin(), sorted.end()), sorted.end());
  SupportPolygon polygon;
  if (sorted.size() < 3) {
    polygon.hull = sorted;
    return polygon;
  }
  std::vector<glm::vec2> hull(2 * sorted.size());
  size_t k = 0;
  for (size_t i = 0; i < sorted.size(); ++i) {
    while (k >= 2 && Turn(hull[k - 2], hull[k - 1], sorted[i]) <= 0.0f) --k;
    hull[k++] = sorted[i];
  }
  for (size_t i = sorted.size() - 1, lower = k + 1; i > 0; --i) {
    while (k >= lower && Turn(hull[k - 2], hull[k - 1], sorted[i - 1]) <= 0.0f) --k;
    hull[k++] = sorted[i - 1];
  }
  hull.resize(k - 1);
  polygon.hull = hull;
  return polygon;
}

glm::vec2 SupportPolygon::Closest(const glm::vec2& p) const {
  if (hull.empty()) return p;
  if (hull.size() == 1) return hull[0];
  if (SignedDistance(p) <= 0.0f) return p;
  glm::vec2 best = hull[0];
  float bestDistance = std::numeric_limits<float>::max();
  for (size_t i = 0; i < hull.size(); ++i) {
    const glm::vec2 c = ClosestOnSegment(p, hull[i], hull[(i + 1) % hull.size()]);
    const float d = glm::length(p - c);
    if (d < bestDistance) bestDistance = d, best = c;
  }
  return best;
}

float SupportPolygon::SignedDistance(const glm::vec2& p) const {
  if (hull.empty()) return std::numeric_limits<float>::max();
  if (hull.size() == 1) return glm::length(p - hull[0]);
  float boundary = std::numeric_limits<float>::max();
  bool inside = hull.size() >= 3;
  for (size_t i = 0; i < hull.size(); ++i) {
    const glm::vec2& a = hull[i];
    const glm::vec2& b = hull[(i + 1) % hull.size()];
    boundary = std::min(boundary, glm::length(p - ClosestOnSegment(p, a, b)));
    if (Turn(a, b, p) < 0.0f) inside = false;
  }
  return inside ? -boundary : boundary;
}

glm::vec2 SupportPolygon::Centroid() const {
  if (hull.empty()) return {0.0f, 0.0f};
  glm::vec2 sum(0.0f);
  for (const glm::vec2& p : hull) sum += p;
  return sum / static_cast<float>(hull.size());
}

}  // namespace rise
