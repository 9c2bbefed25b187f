// SPDX-License-Identifier: MIT
// Test-only stand-ins for what core/ will provide: the biped skeleton with the
// canonical joint names and plausible 1.75 m proportions, and a synthetic
// motion (swinging limbs, a root that travels, turns and tips over) known in
// closed form at any time.
#pragma once

#include <cmath>
#include <filesystem>
#include <glm/gtc/quaternion.hpp>
#include <random>
#include <string>

#include "export/clip.h"
#include "export/clip_resample.h"

namespace rise::test {

inline Skeleton MakeBipedSkeleton() {
  Skeleton s;
  const auto add = [&s](const char* name, const char* parent, glm::vec3 offset, glm::vec3 center = glm::vec3(0.0f),
                        glm::vec3 half = glm::vec3(0.0f)) {
    SkeletonJoint joint;
    joint.name = name;
    joint.parent = parent ? s.Find(parent) : -1;
    joint.restOffset = offset;
    joint.hasBox = half.x > 0.0f;
    joint.box = {center, half};
    s.joints.push_back(joint);
  };
  add("pelvis", nullptr, {0, 0.95f, 0}, {0, 0, 0}, {0.16f, 0.08f, 0.10f});
  add("abdomen", "pelvis", {0, 0.10f, 0}, {0, 0.10f, 0}, {0.14f, 0.10f, 0.09f});
  add("chest", "abdomen", {0, 0.20f, 0}, {0, 0.125f, 0}, {0.17f, 0.125f, 0.10f});
  add("head", "chest", {0, 0.27f, 0}, {0, 0.11f, 0.01f}, {0.09f, 0.115f, 0.10f});
  add("head_end", "head", {0, 0.23f, 0});
  for (const char* side : {"l", "r"}) {
    const float x = side[0] == 'l' ? 1.0f : -1.0f;  // the character's left is +X
    const std::string s_ = side;
    add(("upper_arm_" + s_).c_str(), "chest", {0.20f * x, 0.22f, 0}, {0, -0.145f, 0}, {0.05f, 0.145f, 0.05f});
    add(("forearm_" + s_).c_str(), ("upper_arm_" + s_).c_str(), {0, -0.29f, 0}, {0, -0.13f, 0},
        {0.045f, 0.13f, 0.045f});
    add(("hand_" + s_).c_str(), ("forearm_" + s_).c_str(), {0, -0.26f, 0}, {0, -0.085f, 0}, {0.04f, 0.085f, 0.02f});
    add(("hand_" + s_ + "_end").c_str(), ("hand_" + s_).c_str(), {0, -0.17f, 0});
  }
  for (const char* side : {"l", "r"}) {
    const float x = side[0] == 'l' ? 1.0f : -1.0f;
    const std::string s_ = side;
    add(("thigh_" + s_).c_str(), "pelvis", {0.09f * x, -0.07f, 0}, {0, -0.21f, 0}, {0.07f, 0.21f, 0.07f});
    add(("shin_" + s_).c_str(), ("thigh_" + s_).c_str(), {0, -0.42f, 0}, {0, -0.19f, 0}, {0.05f, 0.19f, 0.05f});
    add(("foot_" + s_).c_str(), ("shin_" + s_).c_str(), {0, -0.38f, 0}, {0, -0.04f, 0.06f}, {0.05f, 0.04f, 0.12f});
    add(("foot_" + s_ + "_end").c_str(), ("foot_" + s_).c_str(), {0, -0.07f, 0.17f});
  }
  return s;
}

// The synthetic pose at time t: root translation and local rotations. The root
// travels, turns more than a full circle over 10 s and tips over; the limbs
// swing through large angles so rotation keys cross hemispheres.
struct Pose {
  glm::vec3 rootTranslation;
  std::vector<glm::quat> rotations;
};

inline Pose SwingPose(const Skeleton& skeleton, double time) {
  const float t = static_cast<float>(time);
  const auto axis = [](float angle, glm::vec3 a) { return glm::angleAxis(angle, glm::normalize(a)); };
  Pose pose;
  pose.rootTranslation = {0.3f * t, 0.6f + 0.3f * std::sin(t), 0.2f * t};
  pose.rotations.assign(skeleton.joints.size(), glm::quat(1, 0, 0, 0));
  for (int j = 0; j < skeleton.JointCount(); ++j) {
    const std::string& name = skeleton.joints[j].name;
    const float side = name.size() > 2 && name.compare(name.size() - 2, 2, "_r") == 0 ? -1.0f : 1.0f;
    const float phase = side > 0 ? 0.0f : 1.3f;
    glm::quat& q = pose.rotations[j];
    if (name == "pelvis") q = axis(0.8f * t, {0, 1, 0}) * axis(1.4f * std::sin(1.3f * t), {1, 0, 0.2f});
    if (name == "abdomen") q = axis(0.3f * std::sin(2.0f * t), {1, 0, 0});
    if (name == "chest") q = axis(0.2f * std::sin(3.0f * t), {0, 0, 1});
    if (name == "head") q = axis(0.4f * std::sin(1.7f * t), {0, 1, 0.3f});
    if (name.rfind("upper_arm", 0) == 0) q = axis(1.6f * std::sin(2.0f * t + phase), {1, 0, 0.3f * side});
    if (name.rfind("forearm", 0) == 0) q = axis(-0.8f - 0.6f * std::sin(2.5f * t + phase), {1, 0, 0});
    if (name.rfind("hand_", 0) == 0 && name.find("_end") == std::string::npos)
      q = axis(0.5f * std::sin(4.0f * t), {0, 0, 1});
    if (name.rfind("thigh", 0) == 0) q = axis(1.0f * std::sin(1.5f * t + phase), {1, 0, 0.1f * side});
    if (name.rfind("shin", 0) == 0) q = axis(0.9f + 0.5f * std::sin(1.5f * t + phase), {1, 0, 0});
    if (name.rfind("foot_", 0) == 0 && name.find("_end") == std::string::npos)
      q = axis(0.3f * std::sin(3.0f * t), {1, 0.2f, 0});
  }
  return pose;
}

// The synthetic motion as the simulator would record it: samples at `rate` Hz
// over [0, seconds] (the last one exactly at `seconds`).
inline MotionSamples SwingSamples(const Skeleton& skeleton, double seconds, double rate) {
  MotionSamples samples;
  const int count = static_cast<int>(std::ceil(seconds * rate - 1e-9)) + 1;
  samples.rotations.resize(skeleton.joints.size());
  for (int i = 0; i < count; ++i) {
    const double t = std::min(i / rate, seconds);
    const Pose pose = SwingPose(skeleton, t);
    samples.times.push_back(t);
    samples.rootTranslation.push_back(pose.rootTranslation);
    for (int j = 0; j < skeleton.JointCount(); ++j) samples.rotations[j].push_back(pose.rotations[j]);
  }
  return samples;
}

// The synthetic motion sampled exactly at frame times i / fps.
inline Clip SwingClip(double fps, double seconds) {
  Clip clip;
  clip.skeleton = MakeBipedSkeleton();
  clip.fps = fps;
  const int frames = static_cast<int>(std::lround(seconds * fps)) + 1;
  clip.rotations.resize(clip.skeleton.joints.size());
  for (int f = 0; f < frames; ++f) {
    const Pose pose = SwingPose(clip.skeleton, f / fps);
    clip.rootTranslation.push_back(pose.rootTranslation);
    for (int j = 0; j < clip.skeleton.JointCount(); ++j) clip.rotations[j].push_back(pose.rotations[j]);
  }
  clip.metadata.phases = {{"roll", 0.0, 0.4}, {"rise", 0.4, clip.Duration()}};
  clip.metadata.contacts = {{"foot_l", 0.1, 0.9, true}, {"hand_r", 0.0, 0.3, false}};
  clip.metadata.parametersJson = R"({"height":1.75,"mass":70})";
  clip.metadata.seed = 42;
  clip.metadata.timeToStand = 0.8;
  clip.metadata.peakTorques = {{"thigh_l", 181.5}, {"shin_r", 120.25}};
  return clip;
}

// A fresh folder under the system temp folder, removed with its contents at
// the end of the test.
class TempFolder {
 public:
  TempFolder() {
    std::random_device device;
    path_ = std::filesystem::temp_directory_path() / ("rise_export_test_" + std::to_string(device()));
    std::filesystem::create_directories(path_);
  }
  ~TempFolder() {
    std::error_code ec;
    std::filesystem::remove_all(path_, ec);
  }
  TempFolder(const TempFolder&) = delete;
  TempFolder& operator=(const TempFolder&) = delete;

  std::string File(const std::string& name) const { return (path_ / name).string(); }
  const std::filesystem::path& Path() const { return path_; }
  // Names of the files in the folder.
  std::vector<std::string> Files() const {
    std::vector<std::string> names;
    for (const auto& entry : std::filesystem::directory_iterator(path_))
      names.push_back(entry.path().filename().string());
    return names;
  }

 private:
  std::filesystem::path path_;
};

}  // namespace rise::test
