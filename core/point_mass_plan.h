// SPDX-License-Identifier: MIT
// The paper's low-dimensional model: a point mass (the CoM) on massless
// telescopic legs and arms. One Solve() is one iteration of Phase 1: with the
// feet and one support hand fixed, find the CoM that keeps every limb within
// its length limits (primary) and lies horizontally as close as possible to the
// feet support region (secondary).
#pragma once

#include "core/support_polygon.h"

#include <glm/vec3.hpp>

namespace rise {

struct LimbRange {
  float minLength = 0.0f;  // metres, CoM to contact point
  float maxLength = 0.0f;
};

struct PointMassPlan {
  // Inputs.
  glm::vec3 com{0.0f};          // current CoM
  glm::vec3 footLeft{0.0f};     // where each leg meets its foot (ankle), for leg lengths
  glm::vec3 footRight{0.0f};
  SupportPolygon feetRegion;    // ground hull of both feet; empty = the segment between the ankles
  glm::vec3 supportHand{0.0f};
  bool hasSupportHand = true;
  LimbRange leg;
  LimbRange arm;
  // Static balance once the free hand lets go: the CoM's ground projection
  // stays this far inside the support triangle (both feet + support hand).
  float balanceMargin = 0.03f;
  float minHeight = 0.1f;       // CoM may not drop below this (the body would touch the ground)
  float preferredHeight = 0.0f; // among equally good goals, the CoM height closest to this (0: none)
  float maxStep = 0.25f;        // farthest the CoM may move in one iteration, metres

  // Outputs.
  glm::vec3 target{0.0f};       // the CoM goal of this iteration
  float distanceToFeet = 0.0f;  // d_c at the goal: horizontal distance to the feet region (0 inside)
  bool overFeet = false;        // d_c == 0: Phase 2 may start
  bool feasible = false;        // some candidate met every primary constraint

  bool Validate() const;
  void Solve();

  // The support region while the free hand is off the ground.
  SupportPolygon SupportTriangle() const;
  // Every limb length (CoM to contact) within its range, with `slack` metres of tolerance.
  bool LimbsWithinRange(const glm::vec3& candidate, float slack) const;
};

}  // namespace rise
