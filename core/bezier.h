// SPDX-License-Identifier: MIT
// Swing paths of hands and feet: a cubic Bezier that leaves the ground
// vertically, peaks at a given lift height and lands vertically, so a swinging
// limb never scuffs the ground at either end.
#pragma once

#include <glm/vec3.hpp>

namespace rise {

struct SwingPath {
  glm::vec3 from{0.0f};
  glm::vec3 to{0.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};  // ground normal
  float lift = 0.08f;              // peak height above the straight line, metres

  // Point at parameter t in [0, 1]; t is eased so the limb starts and stops at rest.
  glm::vec3 At(float t) const;
};

// Smooth 0 -> 1 ease with zero slope at both ends (cubic smoothstep), t clamped to [0, 1].
float Ease(float t);

}  // namespace rise
