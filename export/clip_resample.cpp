// SPDX-License-Identifier: MIT
// From the simulator's samples to a Clip at the requested frame rate.
#include "export/clip_resample.h"

#include <algorithm>
#include <cmath>

#include "base/assert.h"
#include "export/rotation_track.h"

namespace rise {

Clip ResampleClip(const Skeleton& skeleton, const MotionSamples& samples, double fps, const ClipMetadata& metadata) {
  const size_t sampleCount = samples.times.size();
  RISE_ASSERT_MSG(fps > 0.0 && std::isfinite(fps), "fps must be positive");
  RISE_ASSERT_MSG(sampleCount >= 1, "no samples to resample");
  RISE_ASSERT(samples.rootTranslation.size() == sampleCount);
  RISE_ASSERT(static_cast<int>(samples.rotations.size()) == skeleton.JointCount());

  const double first = samples.times.front();
  const double duration = samples.times.back() - first;
  const int frameCount = static_cast<int>(std::lround(duration * fps)) + 1;
  const double step = frameCount > 1 ? duration / (frameCount - 1) : 0.0;

  Clip clip;
  clip.skeleton = skeleton;
  clip.fps = fps;
  clip.rootTranslation.resize(frameCount);
  clip.rotations.assign(skeleton.joints.size(), std::vector<glm::quat>(frameCount));

  // Frame times only grow, so the bracketing sample is found by walking forward.
  size_t lower = 0;
  for (int f = 0; f < frameCount; ++f) {
    const bool last = f == frameCount - 1;
    const double t = last ? samples.times.back() : first + f * step;
    while (lower + 1 < sampleCount && samples.times[lower + 1] <= t) ++lower;
    const size_t upper = std::min(lower + 1, sampleCount - 1);
    const double span = samples.times[upper] - samples.times[lower];
    const float a = (upper == lower || span <= 0.0) ? 0.0f : static_cast<float>((t - samples.times[lower]) / span);

    clip.rootTranslation[f] = glm::mix(samples.rootTranslation[lower], samples.rootTranslation[upper], a);
    for (int j = 0; j < skeleton.JointCount(); ++j) {
      const glm::quat& from = samples.rotations[j][lower];
      const glm::quat to = ContinueRotationTrack(samples.rotations[j][upper], glm::normalize(from));
      clip.rotations[j][f] = a == 0.0f ? from : glm::slerp(glm::normalize(from), to, a);
    }
  }
  for (std::vector<glm::quat>& track : clip.rotations) MakeRotationTrackContinuous(track);

  // Metadata follows the same retiming as the frames (see the header).
  const double scale = duration > 0.0 ? clip.Duration() / duration : 0.0;
  const double end = clip.Duration();
  const auto retime = [&](double t) { return std::clamp(t * scale, 0.0, end); };
  clip.metadata = metadata;
  for (PhaseSpan& phase : clip.metadata.phases) {
    phase.start = retime(phase.start);
    phase.end = retime(phase.end);
  }
  for (ContactSpan& contact : clip.metadata.contacts) {
    contact.start = retime(contact.start);
    contact.end = retime(contact.end);
  }
  if (clip.metadata.timeToStand >= 0.0) clip.metadata.timeToStand = retime(clip.metadata.timeToStand);
  return clip;
}

}  // namespace rise
