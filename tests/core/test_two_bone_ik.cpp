// SPDX-License-Identifier: MIT
#include "core/two_bone_ik.h"
#include "test_support.h"

#include <glm/geometric.hpp>

namespace {

rise::TwoBoneIk Leg(const glm::vec3& target) {
  rise::TwoBoneIk ik;
  ik.root = {0.1f, 0.9f, 0.0f};
  ik.target = target;
  ik.upperLength = 0.42f;
  ik.lowerLength = 0.41f;
  ik.pole = {0.0f, 0.0f, 1.0f};
  ik.maxFlexion = glm::radians(150.0f);
  return ik;
}

}  // namespace

TEST_SUITE("two_bone_ik") {
TEST_CASE("a reachable target is met exactly and the bones keep their lengths") {
  rise::TwoBoneIk ik = Leg({0.15f, 0.35f, 0.1f});
  ik.Solve();
  CHECK(ik.reached);
  CHECK_VEC3_NEAR(ik.end, ik.target, 1e-5f);
  CHECK(glm::length(ik.mid - ik.root) == doctest::Approx(0.42f).epsilon(1e-5));
  CHECK(glm::length(ik.end - ik.mid) == doctest::Approx(0.41f).epsilon(1e-5));
  CHECK(ik.mid.z > 0.05f);  // the knee points toward the pole
}

TEST_CASE("the rest pose gives identity rotations") {
  rise::TwoBoneIk ik = Leg({0.1f, 0.9f - 0.83f, 0.0f});
  ik.Solve();
  CHECK_QUAT_NEAR(ik.upperRotation, glm::quat(1, 0, 0, 0), 2e-3f);
  CHECK_QUAT_NEAR(ik.lowerRotation, glm::quat(1, 0, 0, 0), 2e-3f);
  CHECK(ik.flexion < 2e-3f);
}

TEST_CASE("rotations carry the rest bone onto the solved bone") {
  rise::TwoBoneIk ik = Leg({0.3f, 0.4f, 0.3f});
  ik.Solve();
  const glm::vec3 rest(0, -1, 0);
  CHECK_VEC3_NEAR(ik.upperRotation * rest, glm::normalize(ik.mid - ik.root), 1e-4f);
  CHECK_VEC3_NEAR(ik.lowerRotation * rest, glm::normalize(ik.end - ik.mid), 1e-4f);
  // A pure hinge: the knee angle is the rotation between the two bones.
  const float between = rise::test::AngleBetween(ik.upperRotation, ik.lowerRotation);
  CHECK(between == doctest::Approx(ik.flexion).epsilon(1e-3));
}

TEST_CASE("an out-of-reach target is clamped onto the reach sphere along the same line") {
  rise::TwoBoneIk ik = Leg({0.1f, -0.5f, 0.0f});
  ik.Solve();
  CHECK_FALSE(ik.reached);
  CHECK(glm::length(ik.end - ik.root) == doctest::Approx(0.83f).epsilon(1e-4));
  CHECK_VEC3_NEAR(glm::normalize(ik.end - ik.root), glm::vec3(0, -1, 0), 1e-5f);
}

TEST_CASE("a target too close never bends the joint past its limit") {
  rise::TwoBoneIk ik = Leg({0.1f, 0.85f, 0.0f});
  ik.Solve();
  CHECK_FALSE(ik.reached);
  CHECK(ik.flexion <= glm::radians(150.0f) + 1e-4f);
  CHECK(ik.flexion >= glm::radians(149.0f));
}

TEST_CASE("swivel turns the knee about the hip-ankle line") {
  rise::TwoBoneIk straight = Leg({0.1f, 0.3f, 0.0f});
  straight.Solve();
  rise::TwoBoneIk turned = Leg({0.1f, 0.3f, 0.0f});
  turned.swivel = glm::radians(90.0f);
  turned.Solve();
  CHECK_VEC3_NEAR(turned.end, straight.end, 1e-5f);
  CHECK(turned.flexion == doctest::Approx(straight.flexion).epsilon(1e-4));
  // Rotating the +Z pole by 90 deg about -Y moves the knee to -X.
  CHECK(turned.mid.x < 0.1f - 0.1f);
  CHECK(std::fabs(turned.mid.z) < 1e-4f);
}
}
