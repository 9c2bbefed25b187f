// SPDX-License-Identifier: MIT
#include "export/clip.h"
#include "test_support.h"

TEST_SUITE("clip") {
TEST_CASE("forward kinematics of a two-joint chain rotated 90 degrees about Y") {
  rise::Clip clip;
  clip.skeleton.joints = {{"root", -1, {0, 1, 0}, false, {}}, {"tip", 0, {1, 0, 0}, false, {}}};
  clip.fps = 30;
  clip.rootTranslation = {{0, 1, 0}};
  clip.rotations = {{glm::angleAxis(glm::radians(90.0f), glm::vec3(0, 1, 0))}, {glm::quat(1, 0, 0, 0)}};
  REQUIRE(clip.Validate().empty());
  const auto positions = clip.WorldPositions(0);
  CHECK_VEC3_NEAR(positions[1], glm::vec3(0, 1, -1), 1e-5f);
}
TEST_CASE("a track with a missing key is rejected") {
  rise::Clip clip;
  clip.skeleton.joints = {{"root", -1, {0, 1, 0}, false, {}}};
  clip.rootTranslation = {{0, 1, 0}, {0, 1, 0}};
  clip.rotations = {{glm::quat(1, 0, 0, 0)}};
  CHECK(clip.Validate().find("one key per frame") != std::string::npos);
}
}
