// SPDX-License-Identifier: MIT
// Rotation keys as files need them: unit length and one hemisphere.
//
// q and -q are the same rotation, but a viewer that interpolates keys
// component-wise (glTF LINEAR, Euler curves built from quaternions) turns a
// limb the long way round when two neighbouring keys have dot(q_i, q_i+1) < 0.
// Both writers pass every track through here, so the rule lives in one place.
#pragma once

#include <glm/gtc/quaternion.hpp>
#include <vector>

namespace rise {

// `q` normalised and, if needed, negated so that dot(result, previous) >= 0.
// `previous` must already be a unit key of the same track.
glm::quat ContinueRotationTrack(const glm::quat& q, const glm::quat& previous);

// Normalises every key of `track` and flips signs so that consecutive keys lie
// in one hemisphere. The first key keeps w >= 0.
void MakeRotationTrackContinuous(std::vector<glm::quat>& track);

}  // namespace rise
