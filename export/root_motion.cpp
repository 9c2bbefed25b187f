// SPDX-License-Identifier: MIT
// The three `--root-motion` modes: bake, in-place and extract.
#include "export/root_motion.h"

#include <cmath>

#include "base/assert.h"
#include "export/rotation_track.h"

namespace rise {
namespace {

constexpr double kPi = 3.14159265358979323846;

glm::quat YawRotation(double heading) {
  return glm::angleAxis(static_cast<float>(heading), glm::vec3(0.0f, 1.0f, 0.0f));
}

// Headings of the root at every frame, unwrapped so that consecutive values
// never jump by more than pi (a turn of 350 degrees stays 350, not -10).
std::vector<double> UnwrappedHeadings(const Clip& clip) {
  std::vector<double> headings(clip.FrameCount());
  double previous = 0.0;
  for (int f = 0; f < clip.FrameCount(); ++f) {
    double heading = HeadingOf(clip.rotations[0][f], previous);
    if (f > 0) heading = previous + std::remainder(heading - previous, 2.0 * kPi);
    headings[f] = heading;
    previous = heading;
  }
  return headings;
}

glm::vec3 Ground(const glm::vec3& p) {
  return glm::vec3(p.x, 0.0f, p.z);
}

}  // namespace

std::optional<RootMotion> ParseRootMotion(std::string_view name) {
  if (name == "bake") return RootMotion::kBake;
  if (name == "in-place") return RootMotion::kInPlace;
  if (name == "extract") return RootMotion::kExtract;
  return std::nullopt;
}

const char* RootMotionName(RootMotion mode) {
  switch (mode) {
    case RootMotion::kBake:
      return "bake";
    case RootMotion::kInPlace:
      return "in-place";
    case RootMotion::kExtract:
      return "extract";
  }
  return "bake";
}

double HeadingOf(const glm::quat& rotation, double fallback) {
  // Twist about Y of q = (w, x, y, z) is (w, 0, y, 0) normalised.
  const double w = rotation.w, y = rotation.y;
  if (w * w + y * y < 1e-8) return fallback;
  return 2.0 * std::atan2(y, w);
}

Clip ApplyRootMotion(const Clip& clip, RootMotion mode) {
  RISE_ASSERT_MSG(clip.Validate().empty(), "ApplyRootMotion needs a valid clip");
  RISE_ASSERT_MSG(clip.skeleton.Find(kExtractedRootName) < 0, "the clip already holds an extracted root");
  Clip out = clip;
  out.metadata.rootMotion = RootMotionName(mode);
  if (mode == RootMotion::kBake) return out;

  const int frames = clip.FrameCount();
  const std::vector<double> headings = UnwrappedHeadings(clip);

  if (mode == RootMotion::kInPlace) {
    // Each frame's pose is moved by G_0 * G_f^-1, G being the ground frame.
    const glm::vec3 origin = Ground(clip.rootTranslation[0]);
    for (int f = 0; f < frames; ++f) {
      const glm::quat turn = YawRotation(headings[0] - headings[f]);
      const glm::vec3 ground = Ground(clip.rootTranslation[f]);
      out.rootTranslation[f] = origin + turn * (clip.rootTranslation[f] - ground);
      out.rotations[0][f] = turn * clip.rotations[0][f];
    }
    out.metadata.removedTravel = Ground(clip.rootTranslation[frames - 1]) - origin;
    out.metadata.removedHeading = headings[frames - 1] - headings[0];
    MakeRotationTrackContinuous(out.rotations[0]);
    return out;
  }

  // kExtract: a ground-level joint above the pelvis, standing under the
  // pelvis in the bind pose and at every frame, so the pelvis's offset from it
  // is purely vertical.
  const SkeletonJoint& pelvis = clip.skeleton.joints[0];
  SkeletonJoint root;
  root.name = kExtractedRootName;
  root.parent = -1;
  root.restOffset = Ground(pelvis.restOffset);
  out.skeleton.joints.insert(out.skeleton.joints.begin(), root);
  for (size_t j = 1; j < out.skeleton.joints.size(); ++j) out.skeleton.joints[j].parent += 1;
  out.skeleton.joints[1].restOffset = glm::vec3(0.0f, pelvis.restOffset.y, 0.0f);

  out.rotations.insert(out.rotations.begin(), std::vector<glm::quat>(frames));
  // The pelvis now moves relative to the root (it rises from the floor to
  // standing height), so it gets its own translation track.
  out.translations.assign(out.skeleton.joints.size(), {});
  for (size_t j = 1; j < clip.translations.size(); ++j) out.translations[j + 1] = clip.translations[j];
  out.translations[1].resize(frames);
  for (int f = 0; f < frames; ++f) {
    const glm::quat yaw = YawRotation(headings[f]);
    const glm::vec3 ground = Ground(clip.rootTranslation[f]);
    out.rootTranslation[f] = ground;
    out.rotations[0][f] = yaw;
    out.rotations[1][f] = glm::inverse(yaw) * clip.rotations[0][f];
    out.translations[1][f] = glm::inverse(yaw) * (clip.rootTranslation[f] - ground);
  }
  MakeRotationTrackContinuous(out.rotations[0]);
  MakeRotationTrackContinuous(out.rotations[1]);
  return out;
}

}  // namespace rise
