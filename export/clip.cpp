// SPDX-License-Identifier: MIT
#include "export/clip.h"

#include <cmath>

namespace rise {
namespace {

bool IsFinite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

}  // namespace

double Clip::Duration() const { return FrameCount() > 1 ? (FrameCount() - 1) / fps : 0.0; }

std::string Clip::Validate() const {
  if (std::string problem = skeleton.Validate(); !problem.empty()) return problem;
  if (!(fps > 0.0) || !std::isfinite(fps)) return "fps must be a positive number";
  const int frames = FrameCount();
  if (frames < 1) return "clip has no frames";
  if (static_cast<int>(rotations.size()) != skeleton.JointCount()) {
    return "clip needs one rotation track per joint";
  }
  for (int j = 0; j < skeleton.JointCount(); ++j) {
    if (static_cast<int>(rotations[j].size()) != frames) {
      return "rotation track of '" + skeleton.joints[j].name + "' does not hold one key per frame";
    }
    for (const glm::quat& q : rotations[j]) {
      const float len = std::sqrt(q.x * q.x + q.y * q.y + q.z * q.z + q.w * q.w);
      if (!std::isfinite(len) || std::fabs(len - 1.0f) > 1e-3f) {
        return "rotation track of '" + skeleton.joints[j].name + "' holds a non-unit quaternion";
      }
    }
  }
  for (const glm::vec3& t : rootTranslation) {
    if (!IsFinite(t)) return "root translation holds a non-finite value";
  }
  if (!translations.empty()) {
    if (static_cast<int>(translations.size()) != skeleton.JointCount() || !translations[0].empty()) {
      return "translations needs one track per joint and none for the root";
    }
    for (int j = 1; j < skeleton.JointCount(); ++j) {
      if (!translations[j].empty() && static_cast<int>(translations[j].size()) != frames) {
        return "translation track of '" + skeleton.joints[j].name + "' does not hold one key per frame";
      }
      for (const glm::vec3& t : translations[j]) {
        if (!IsFinite(t)) return "translation track of '" + skeleton.joints[j].name + "' holds a non-finite value";
      }
    }
  }
  const double duration = Duration() + 1e-9;
  for (const PhaseSpan& phase : metadata.phases) {
    if (phase.start < 0.0 || phase.end > duration || phase.start > phase.end) {
      return "phase '" + phase.name + "' lies outside the clip";
    }
  }
  for (const ContactSpan& contact : metadata.contacts) {
    if (contact.start < 0.0 || contact.end > duration || contact.start > contact.end) {
      return "contact of '" + contact.effector + "' lies outside the clip";
    }
  }
  return {};
}

std::vector<glm::quat> Clip::WorldRotations(int frame) const {
  std::vector<glm::quat> world(skeleton.joints.size());
  for (int j = 0; j < skeleton.JointCount(); ++j) {
    const int parent = skeleton.joints[j].parent;
    world[j] = parent < 0 ? rotations[j][frame] : world[parent] * rotations[j][frame];
  }
  return world;
}

glm::vec3 Clip::LocalTranslation(int joint, int frame) const {
  if (joint == 0) return rootTranslation[frame];
  if (!translations.empty() && !translations[joint].empty()) return translations[joint][frame];
  return skeleton.joints[joint].restOffset;
}

std::vector<glm::vec3> Clip::WorldPositions(int frame) const {
  std::vector<glm::vec3> positions(skeleton.joints.size());
  std::vector<glm::quat> world = WorldRotations(frame);
  for (int j = 0; j < skeleton.JointCount(); ++j) {
    const int parent = skeleton.joints[j].parent;
    positions[j] = parent < 0 ? rootTranslation[frame]
                              : positions[parent] + world[parent] * LocalTranslation(j, frame);
  }
  return positions;
}

}  // namespace rise
