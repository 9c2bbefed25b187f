// SPDX-License-Identifier: MIT
// The support region: convex hull of the ground contact points projected on the
// horizontal plane (x, z). For slow motions the ZMP equals the projected CoM,
// so the body is statically balanced while the CoM projection lies inside.
#pragma once

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <vector>

namespace rise {

// Ground projection of a world point (drops the height).
inline glm::vec2 Ground(const glm::vec3& p) { return {p.x, p.z}; }

struct SupportPolygon {
  std::vector<glm::vec2> hull;  // counter-clockwise seen from +Y, no repeated points

  // Builds the convex hull of the given points (any order, duplicates allowed).
  static SupportPolygon FromPoints(const std::vector<glm::vec2>& points);

  bool Empty() const { return hull.empty(); }
  // Signed distance from p to the hull boundary: negative inside, positive outside.
  float SignedDistance(const glm::vec2& p) const;
  // The point of the hull (boundary or interior) closest to p.
  glm::vec2 Closest(const glm::vec2& p) const;
  glm::vec2 Centroid() const;
};

}  // namespace rise
