// SPDX-License-Identifier: MIT
#include "export/biped_fixture.h"
#include "export/root_motion.h"
#include "test_support.h"

namespace {

glm::vec3 Ground(const glm::vec3& p) {
  return glm::vec3(p.x, 0.0f, p.z);
}

}  // namespace

TEST_SUITE("root_motion") {
  TEST_CASE("mode names parse and print") {
    for (rise::RootMotion mode : {rise::RootMotion::kBake, rise::RootMotion::kInPlace, rise::RootMotion::kExtract}) {
      CHECK(rise::ParseRootMotion(rise::RootMotionName(mode)) == mode);
    }
    CHECK_FALSE(rise::ParseRootMotion("inplace").has_value());
  }
  TEST_CASE("heading is the twist about +Y and survives lying on the back, front and side") {
    const glm::quat yaw = glm::angleAxis(0.7f, glm::vec3(0, 1, 0));
    for (glm::vec3 tipAxis : {glm::vec3(1, 0, 0), glm::vec3(-1, 0, 0), glm::vec3(0, 0, 1)}) {
      CHECK(rise::HeadingOf(yaw * glm::angleAxis(glm::radians(90.0f), tipAxis), 9.0) ==
            doctest::Approx(0.7).epsilon(1e-5));
    }
    // Upside down the twist is undefined: the fallback is returned.
    CHECK(rise::HeadingOf(glm::angleAxis(glm::radians(180.0f), glm::vec3(1, 0, 0)), 9.0) == 9.0);
  }
  TEST_CASE("bake leaves the motion untouched") {
    const rise::Clip clip = rise::test::SwingClip(30.0, 2.0);
    const rise::Clip baked = rise::ApplyRootMotion(clip, rise::RootMotion::kBake);
    CHECK(baked.metadata.rootMotion == "bake");
    CHECK(baked.rootTranslation == clip.rootTranslation);
    CHECK(baked.rotations == clip.rotations);
  }
  TEST_CASE("in-place pins the root's ground point and heading to frame 0 and records what it removed") {
    // 10 s: the root turns 0.8 rad/s, 8 rad in all (more than a full turn), and travels (3, 0, 2) m.
    const rise::Clip clip = rise::test::SwingClip(30.0, 10.0);
    const rise::Clip still = rise::ApplyRootMotion(clip, rise::RootMotion::kInPlace);
    REQUIRE(still.Validate().empty());
    CHECK(still.metadata.rootMotion == "in-place");
    CHECK(still.metadata.removedHeading == doctest::Approx(8.0).epsilon(1e-4));
    CHECK_VEC3_NEAR(still.metadata.removedTravel, glm::vec3(3.0f, 0.0f, 2.0f), 1e-5f);
    const glm::vec3 origin = Ground(clip.rootTranslation[0]);
    for (int f = 0; f < still.FrameCount(); f += 13) {
      CHECK_VEC3_NEAR(Ground(still.rootTranslation[f]), origin, 1e-5f);
      CHECK(rise::HeadingOf(still.rotations[0][f], 0.0) == doctest::Approx(0.0).epsilon(1e-4));
      // The pose itself is kept: every joint's height and every distance to the root.
      const auto before = clip.WorldPositions(f);
      const auto after = still.WorldPositions(f);
      for (size_t j = 0; j < before.size(); ++j) {
        CHECK(after[j].y == doctest::Approx(before[j].y).epsilon(1e-5));
        CHECK(rise::test::Distance(after[j], after[0]) ==
              doctest::Approx(rise::test::Distance(before[j], before[0])).epsilon(1e-5));
      }
    }
  }
  TEST_CASE("extract adds a ground-level root under the pelvis that carries travel and heading") {
    const rise::Clip clip = rise::test::SwingClip(30.0, 10.0);
    const rise::Clip extracted = rise::ApplyRootMotion(clip, rise::RootMotion::kExtract);
    REQUIRE(extracted.Validate().empty());
    REQUIRE(extracted.skeleton.JointCount() == clip.skeleton.JointCount() + 1);
    CHECK(extracted.skeleton.joints[0].name == "root");
    CHECK(extracted.skeleton.joints[1].name == "pelvis");
    CHECK(extracted.skeleton.joints[1].parent == 0);
    CHECK(extracted.skeleton.joints[0].restOffset.y == 0.0f);
    CHECK(extracted.skeleton.Find("head") == clip.skeleton.Find("head") + 1);
    for (int f = 0; f < extracted.FrameCount(); f += 11) {
      CHECK(extracted.rootTranslation[f].y == 0.0f);
      CHECK_VEC3_NEAR(extracted.rootTranslation[f], Ground(clip.rootTranslation[f]), 1e-6f);
      const glm::quat root = extracted.rotations[0][f];
      CHECK(std::fabs(root.x) + std::fabs(root.z) < 1e-6f);
      CHECK_QUAT_NEAR(root, glm::angleAxis(0.8f * static_cast<float>(f / 30.0), glm::vec3(0, 1, 0)), 1e-4f);
      // World motion of every original joint is unchanged.
      const auto before = clip.WorldPositions(f);
      const auto after = extracted.WorldPositions(f);
      for (size_t j = 0; j < before.size(); ++j) CHECK_VEC3_NEAR(after[j + 1], before[j], 1e-5f);
    }
  }
}
