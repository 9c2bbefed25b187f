// SPDX-License-Identifier: MIT
#include <algorithm>

#include "export/biped_fixture.h"
#include "export/clip_resample.h"
#include "test_support.h"

namespace {

// Two samples of a one-joint skeleton: identity at t = 0, `end` at t = 1.
rise::MotionSamples TwoSamples(const glm::quat& end) {
  rise::MotionSamples samples;
  samples.times = {0.0, 1.0};
  samples.rootTranslation = {{0, 0, 0}, {2, 0, 0}};
  samples.rotations = {{glm::quat(1, 0, 0, 0), end}};
  return samples;
}

// Component-wise comparison up to sign: AngleBetween's acos cannot resolve
// angles below ~5e-4 rad in float.
bool SameRotation(const glm::quat& a, const glm::quat& b, float tolerance) {
  const glm::quat d = glm::dot(a, b) < 0.0f ? a + b : a - b;
  return std::max({std::fabs(d.x), std::fabs(d.y), std::fabs(d.z), std::fabs(d.w)}) <= tolerance;
}

rise::Skeleton OneJoint() {
  rise::Skeleton skeleton;
  skeleton.joints = {{"pelvis", -1, {0, 1, 0}, false, {}}};
  return skeleton;
}

}  // namespace

TEST_SUITE("clip_resample") {
  TEST_CASE(
      "frame count is round(duration * fps) + 1 and the last frame is the last sample, for common and odd rates") {
    const rise::Skeleton skeleton = rise::test::MakeBipedSkeleton();
    // 2.013 s is not a whole number of frames at any of these rates.
    const rise::MotionSamples samples = rise::test::SwingSamples(skeleton, 2.013, 240.0);
    for (double fps : {24.0, 30.0, 60.0, 120.0, 29.97, 7.0}) {
      CAPTURE(fps);
      const rise::Clip clip = rise::ResampleClip(skeleton, samples, fps, {});
      REQUIRE(clip.Validate().empty());
      CHECK(clip.FrameCount() == std::lround(2.013 * fps) + 1);
      CHECK(clip.fps == fps);
      CHECK(clip.Duration() == doctest::Approx((clip.FrameCount() - 1) / fps).epsilon(1e-12));
      CHECK(std::fabs(clip.Duration() - 2.013) <= 0.5 / fps + 1e-12);
      CHECK(clip.rootTranslation.back() == samples.rootTranslation.back());
      CHECK(clip.rootTranslation.front() == samples.rootTranslation.front());
      for (int j = 0; j < skeleton.JointCount(); ++j) {
        CHECK_QUAT_NEAR(clip.rotations[j].back(), samples.rotations[j].back(), 1e-6f);
        CHECK_QUAT_NEAR(clip.rotations[j].front(), samples.rotations[j].front(), 1e-6f);
      }
    }
  }
  TEST_CASE("a recording of a whole number of frames is sampled exactly at i / fps") {
    const rise::Skeleton skeleton = rise::test::MakeBipedSkeleton();
    const rise::MotionSamples samples = rise::test::SwingSamples(skeleton, 3.0, 240.0);
    const rise::Clip clip = rise::ResampleClip(skeleton, samples, 30.0, {});
    REQUIRE(clip.FrameCount() == 91);
    // 240 / 30 = 8 samples per frame: each frame lands on a sample.
    for (int f : {0, 1, 45, 77, 90}) {
      CHECK_VEC3_NEAR(clip.rootTranslation[f], samples.rootTranslation[8 * f], 1e-6f);
      for (int j = 0; j < skeleton.JointCount(); ++j)
        CHECK(SameRotation(clip.rotations[j][f], samples.rotations[j][8 * f], 1e-6f));
    }
  }
  TEST_CASE(
      "the frame between two samples is the slerp midpoint, along the shortest path even when the keys differ in "
      "sign") {
    const glm::quat quarterTurn = glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 1, 0));
    for (float sign : {1.0f, -1.0f}) {
      CAPTURE(sign);
      const rise::Clip clip = rise::ResampleClip(OneJoint(), TwoSamples(sign * quarterTurn), 2.0, {});
      REQUIRE(clip.FrameCount() == 3);
      CHECK_QUAT_NEAR(clip.rotations[0][1], glm::angleAxis(glm::radians(45.0f), glm::vec3(0, 1, 0)), 1e-5f);
      CHECK_VEC3_NEAR(clip.rootTranslation[1], glm::vec3(1, 0, 0), 1e-6f);
      CHECK(glm::dot(clip.rotations[0][1], clip.rotations[0][2]) >= 0.0f);
    }
  }
  TEST_CASE("resampled synthetic motion matches the closed form within the slerp error of 240 Hz sampling") {
    const rise::Skeleton skeleton = rise::test::MakeBipedSkeleton();
    const rise::Clip clip = rise::ResampleClip(skeleton, rise::test::SwingSamples(skeleton, 2.0, 240.0), 24.0, {});
    rise::Clip exact = rise::test::SwingClip(24.0, 2.0);
    REQUIRE(clip.FrameCount() == exact.FrameCount());
    for (int f = 0; f < clip.FrameCount(); f += 7) {
      const auto a = clip.WorldPositions(f);
      const auto b = exact.WorldPositions(f);
      for (size_t j = 0; j < a.size(); ++j) CHECK_VEC3_NEAR(a[j], b[j], 1e-4f);
    }
  }
  TEST_CASE("metadata times follow the frames' retiming and stay inside the clip") {
    rise::MotionSamples samples = TwoSamples(glm::quat(1, 0, 0, 0));
    samples.times = {0.0, 1.01};  // 30 fps -> round(30.3) + 1 = 31 frames, 1.0 s
    rise::ClipMetadata metadata;
    metadata.phases = {{"rise", 0.505, 1.01}};
    metadata.contacts = {{"foot_l", 0.0, 1.01, true}};
    metadata.timeToStand = 1.01;
    const rise::Clip clip = rise::ResampleClip(OneJoint(), samples, 30.0, metadata);
    REQUIRE(clip.FrameCount() == 31);
    CHECK(clip.Validate().empty());
    CHECK(clip.metadata.phases[0].start == doctest::Approx(0.5).epsilon(1e-12));
    CHECK(clip.metadata.phases[0].end == doctest::Approx(1.0).epsilon(1e-12));
    CHECK(clip.metadata.contacts[0].end == doctest::Approx(1.0).epsilon(1e-12));
    CHECK(clip.metadata.timeToStand == doctest::Approx(1.0).epsilon(1e-12));
  }
  TEST_CASE("a single sample gives a one-frame clip") {
    rise::MotionSamples samples = TwoSamples(glm::quat(1, 0, 0, 0));
    samples.times.resize(1);
    samples.rootTranslation.resize(1);
    samples.rotations[0].resize(1);
    const rise::Clip clip = rise::ResampleClip(OneJoint(), samples, 60.0, {});
    CHECK(clip.FrameCount() == 1);
    CHECK(clip.Duration() == 0.0);
    CHECK(clip.Validate().empty());
  }
}
