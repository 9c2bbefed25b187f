// SPDX-License-Identifier: MIT
// From the simulator's samples (its own rate, e.g. 240 Hz) to a Clip at the
// requested frame rate.
//
// Timing rule: a recording of duration D (last time - first time) becomes
// N = round(D * fps) + 1 frames. Frame 0 holds the first sample and frame N-1
// holds the last sample exactly, so the start pose and the final still stand
// survive untouched and nothing accumulates over long clips. In between, frame i
// reads the recording at first + i * D / (N - 1). When D is a whole number of
// frames this is exactly i / fps; otherwise the motion is retimed by the factor
// (N - 1) / (fps * D), which differs from 1 by at most 1 / (2 * fps * D) (under
// 0.3 % for a 5 s clip at 30 fps) -- the price of keeping both ends and an exact
// fps. Metadata times are retimed by the same factor.
// Translation is interpolated linearly, rotations by shortest-path slerp.
#pragma once

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>
#include <vector>

#include "export/clip.h"

namespace rise {

// Motion recorded at the simulator's rate, in rise-gen's conventions (clip.h).
struct MotionSamples {
  std::vector<double> times;                      // seconds, strictly increasing
  std::vector<glm::vec3> rootTranslation;         // [sample]: root world position
  std::vector<std::vector<glm::quat>> rotations;  // [joint][sample]: local rotations
};

// Builds the clip at `fps` (> 0). `metadata` times are seconds since the first
// sample. The result's rotation tracks are unit and sign-continuous.
Clip ResampleClip(const Skeleton& skeleton, const MotionSamples& samples, double fps, const ClipMetadata& metadata);

}  // namespace rise
