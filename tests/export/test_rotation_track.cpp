// SPDX-License-Identifier: MIT
#include "export/rotation_track.h"
#include "test_support.h"

TEST_SUITE("rotation_track") {
  TEST_CASE("keys with flipped signs and scaled lengths become unit keys in one hemisphere") {
    std::vector<glm::quat> track;
    std::vector<glm::quat> original;
    for (int i = 0; i < 40; ++i) {
      const glm::quat q = glm::angleAxis(0.3f * i, glm::normalize(glm::vec3(1, 2, 3)));
      original.push_back(q);
      // Every other key negated and the lengths off unit, as a sloppy source would give.
      track.push_back((i % 2 ? -1.0f : 1.0f) * (0.5f + 0.05f * i) * q);
    }
    rise::MakeRotationTrackContinuous(track);
    for (size_t i = 0; i < track.size(); ++i) {
      CHECK(glm::length(track[i]) == doctest::Approx(1.0).epsilon(1e-6));
      CHECK_QUAT_NEAR(track[i], original[i], 1e-3f);
      if (i > 0) CHECK(glm::dot(track[i - 1], track[i]) >= 0.0f);
    }
    CHECK(track[0].w >= 0.0f);
  }
  TEST_CASE("a rotation past 180 degrees keeps turning the same way instead of flipping back") {
    // 0.3 rad steps through 4 full turns: the shortest-path sign rule must hold
    // at every step although the raw angleAxis keys change sign every 2 pi.
    std::vector<glm::quat> track;
    for (int i = 0; i < 90; ++i) track.push_back(glm::angleAxis(0.3f * i, glm::vec3(0, 1, 0)));
    rise::MakeRotationTrackContinuous(track);
    for (size_t i = 1; i < track.size(); ++i) {
      CHECK(rise::test::AngleBetween(track[i - 1], track[i]) == doctest::Approx(0.3).epsilon(1e-3));
      CHECK(glm::dot(track[i - 1], track[i]) > 0.98f);
    }
  }
  TEST_CASE("a single key continues from its predecessor") {
    const glm::quat previous = glm::angleAxis(1.0f, glm::vec3(1, 0, 0));
    const glm::quat next = rise::ContinueRotationTrack(-2.0f * glm::angleAxis(1.1f, glm::vec3(1, 0, 0)), previous);
    CHECK(glm::dot(previous, next) > 0.99f);
    CHECK(glm::length(next) == doctest::Approx(1.0).epsilon(1e-6));
  }
}
