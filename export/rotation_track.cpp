// SPDX-License-Identifier: MIT
// Rotation keys as files need them: unit length and one hemisphere.
#include "export/rotation_track.h"

#include "base/assert.h"

namespace rise {

glm::quat ContinueRotationTrack(const glm::quat& q, const glm::quat& previous) {
  const float length = glm::length(q);
  RISE_ASSERT_MSG(length > 1e-6f, "a rotation key has zero length");
  const glm::quat unit = q / length;
  return glm::dot(unit, previous) < 0.0f ? -unit : unit;
}

void MakeRotationTrackContinuous(std::vector<glm::quat>& track) {
  if (track.empty()) return;
  // Any sign works for the first key; w >= 0 makes files reproducible.
  track[0] = ContinueRotationTrack(track[0], glm::quat(1.0f, 0.0f, 0.0f, 0.0f));
  for (size_t i = 1; i < track.size(); ++i) track[i] = ContinueRotationTrack(track[i], track[i - 1]);
}

}  // namespace rise
