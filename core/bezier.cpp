// SPDX-License-Identifier: MIT
#include "core/bezier.h"

#include <algorithm>

namespace rise {

float Ease(float t) {
  t = std::clamp(t, 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

glm::vec3 SwingPath::At(float t) const {
  const float s = Ease(t);
  // Both inner control points raised by 4/3 lift: a cubic Bezier's midpoint is
  // (p0 + 3 p1 + 3 p2 + p3) / 8, so the peak sits exactly `lift` above the chord.
  const glm::vec3 p1 = from + up * (lift * 4.0f / 3.0f);
  const glm::vec3 p2 = to + up * (lift * 4.0f / 3.0f);
  const float u = 1.0f - s;
  return from * (u * u * u) + p1 * (3.0f * u * u * s) + p2 * (3.0f * u * s * s) + to * (s * s * s);
}

}  // namespace rise
