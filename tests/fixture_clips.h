// SPDX-License-Identifier: MIT
// Synthetic clips of a 1.75 m box body, shared by the clip-quality and preview tests.
#pragma once

#include <cmath>
#include <glm/gtc/quaternion.hpp>
#include <glm/trigonometric.hpp>
#include <string>

#include "export/clip.h"

namespace rise::test {

// The biped's joint names and 1.75 m proportions (head top at 1.75 m, soles
// at y = 0, head joint at the neck at 1.50 m), with one box per body segment.
inline Skeleton FixtureSkeleton() {
  auto joint = [](const char* name, int parent, glm::vec3 offset) {
    return SkeletonJoint{name, parent, offset, false, {}};
  };
  auto boxed = [](const char* name, int parent, glm::vec3 offset, glm::vec3 center, glm::vec3 half) {
    return SkeletonJoint{name, parent, offset, true, {center, half}};
  };
  Skeleton skeleton;
  skeleton.joints = {
      boxed("pelvis", -1, {0, 0.95f, 0}, {0, 0, 0}, {0.15f, 0.08f, 0.10f}),
      boxed("abdomen", 0, {0, 0.12f, 0}, {0, 0.08f, 0}, {0.13f, 0.08f, 0.09f}),
      boxed("chest", 1, {0, 0.18f, 0}, {0, 0.11f, 0}, {0.17f, 0.11f, 0.10f}),
      boxed("head", 2, {0, 0.25f, 0}, {0, 0.12f, 0.01f}, {0.08f, 0.12f, 0.10f}),
      joint("head_end", 3, {0, 0.25f, 0}),
      boxed("upper_arm_l", 2, {0.20f, 0.20f, 0}, {0, -0.14f, 0}, {0.045f, 0.14f, 0.045f}),
      boxed("forearm_l", 5, {0, -0.28f, 0}, {0, -0.13f, 0}, {0.04f, 0.13f, 0.04f}),
      boxed("hand_l", 6, {0, -0.26f, 0}, {0, -0.08f, 0}, {0.025f, 0.08f, 0.05f}),
      joint("hand_l_end", 7, {0, -0.17f, 0}),
      boxed("upper_arm_r", 2, {-0.20f, 0.20f, 0}, {0, -0.14f, 0}, {0.045f, 0.14f, 0.045f}),
      boxed("forearm_r", 9, {0, -0.28f, 0}, {0, -0.13f, 0}, {0.04f, 0.13f, 0.04f}),
      boxed("hand_r", 10, {0, -0.26f, 0}, {0, -0.08f, 0}, {0.025f, 0.08f, 0.05f}),
      joint("hand_r_end", 11, {0, -0.17f, 0}),
      boxed("thigh_l", 0, {0.10f, -0.05f, 0}, {0, -0.21f, 0}, {0.07f, 0.21f, 0.07f}),
      boxed("shin_l", 13, {0, -0.43f, 0}, {0, -0.20f, 0}, {0.05f, 0.20f, 0.05f}),
      boxed("foot_l", 14, {0, -0.40f, 0}, {0, -0.035f, 0.06f}, {0.05f, 0.035f, 0.12f}),
      joint("foot_l_end", 15, {0, -0.06f, 0.17f}),
      boxed("thigh_r", 0, {-0.10f, -0.05f, 0}, {0, -0.21f, 0}, {0.07f, 0.21f, 0.07f}),
      boxed("shin_r", 17, {0, -0.43f, 0}, {0, -0.20f, 0}, {0.05f, 0.20f, 0.05f}),
      boxed("foot_r", 18, {0, -0.40f, 0}, {0, -0.035f, 0.06f}, {0.05f, 0.035f, 0.12f}),
      joint("foot_r_end", 19, {0, -0.06f, 0.17f}),
  };
  return skeleton;
}

// A clip of `frames` frames in the bind (standing) pose.
inline Clip StandingClip(int frames, double fps = 30.0) {
  Clip clip;
  clip.skeleton = FixtureSkeleton();
  clip.fps = fps;
  clip.rootTranslation.assign(frames, clip.skeleton.joints[0].restOffset);
  clip.rotations.assign(clip.skeleton.joints.size(), std::vector<glm::quat>(frames, glm::quat(1, 0, 0, 0)));
  return clip;
}

// The bottom edge of the heels in the bind pose (body coordinates, any x).
inline glm::vec3 HeelEdge() {
  return {0.0f, 0.0f, -0.06f};
}

// Poses frame f as the rigid standing body rotated by `tilt` about the heels'
// bottom edge, which stays at `pivot`.
inline void SetPlankPose(Clip& clip, int f, const glm::quat& tilt, const glm::vec3& pivot = glm::vec3(0.0f)) {
  clip.rotations[0][f] = tilt;
  clip.rootTranslation[f] = pivot + tilt * (clip.skeleton.joints[0].restOffset - HeelEdge());
}

// The plank angle about +X (degrees) at which the body lies on its back: the
// heels' edge stays on the ground and nothing else goes below it.
constexpr float kLyingDeg = -85.0f;

// Lying on the back to standing: the straight body turns about its heels'
// bottom edge from kLyingDeg to upright over riseSeconds, then stands still
// for holdSeconds. No box goes below the ground and the heels never slide.
inline Clip RiseClip(double riseSeconds = 2.0, double holdSeconds = 1.0, double fps = 30.0) {
  const int riseFrames = static_cast<int>(std::lround(riseSeconds * fps));
  const int frames = riseFrames + static_cast<int>(std::lround(holdSeconds * fps)) + 1;
  Clip clip = StandingClip(frames, fps);
  for (int f = 0; f < frames; ++f) {
    const float s = f < riseFrames ? static_cast<float>(f) / riseFrames : 1.0f;
    SetPlankPose(clip, f, glm::angleAxis(glm::radians(kLyingDeg * (1.0f - s)), glm::vec3(1, 0, 0)));
  }
  clip.metadata.phases = {{"rise", 0.0, riseSeconds}, {"stand", riseSeconds, clip.Duration()}};
  return clip;
}

}  // namespace rise::test
