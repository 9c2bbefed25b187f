// SPDX-License-Identifier: MIT
#include "core/bezier.h"
#include "core/point_mass_plan.h"
#include "core/support_polygon.h"
#include "test_support.h"

#include <glm/geometric.hpp>

namespace {

// A crawling stance: feet at z = 0, the support hand 0.9 m ahead, CoM between.
rise::PointMassPlan Crawl() {
  rise::PointMassPlan plan;
  plan.footLeft = {0.12f, 0.0f, 0.0f};
  plan.footRight = {-0.12f, 0.0f, 0.0f};
  plan.supportHand = {0.2f, 0.0f, 0.9f};
  plan.com = {0.0f, 0.35f, 0.55f};
  plan.leg = {0.25f, 0.95f};
  plan.arm = {0.35f, 0.75f};
  return plan;
}

}  // namespace

TEST_SUITE("point_mass_plan") {
TEST_CASE("one iteration moves the CoM toward the feet without breaking a limb limit") {
  rise::PointMassPlan plan = Crawl();
  plan.Solve();
  CHECK(plan.feasible);
  CHECK(plan.LimbsWithinRange(plan.target, 1e-4f));
  CHECK(plan.target.z < plan.com.z - 0.1f);
  CHECK(glm::length(plan.target - plan.com) <= plan.maxStep * 1.75f);  // grid covers a box of maxStep
  CHECK_FALSE(plan.overFeet);
}

TEST_CASE("the arm's maximum length stops the CoM before the feet: the hand must move") {
  rise::PointMassPlan plan = Crawl();
  plan.maxStep = 2.0f;
  plan.Solve();
  CHECK(plan.feasible);
  // The arm can reach at most 0.75 m, so the CoM stays >= 0.9 - 0.75 = 0.15 m ahead... minus height.
  CHECK(glm::length(plan.target - plan.supportHand) <= 0.75f + 1e-4f);
  CHECK(plan.distanceToFeet > 0.0f);
  CHECK_FALSE(plan.overFeet);
}

TEST_CASE("with the hand close to the feet the CoM reaches the feet region") {
  rise::PointMassPlan plan = Crawl();
  // Two feet as boxes 26 cm long, toes at z = 0.15.
  plan.feetRegion = rise::SupportPolygon::FromPoints({{-0.17f, -0.11f}, {0.17f, -0.11f}, {0.17f, 0.15f}, {-0.17f, 0.15f}});
  plan.supportHand = {0.2f, 0.0f, 0.45f};
  plan.com = {0.0f, 0.45f, 0.35f};
  plan.maxStep = 0.5f;
  plan.Solve();
  CHECK(plan.overFeet);
  CHECK(plan.distanceToFeet <= 1e-3f);
  CHECK(plan.feetRegion.SignedDistance(rise::Ground(plan.target)) <= 0.0f);
  // Still statically balanced over the triangle of both feet and the hand.
  CHECK(plan.SupportTriangle().SignedDistance(rise::Ground(plan.target)) <= -plan.balanceMargin + 1e-4f);
}

TEST_CASE("a CoM outside the support triangle is first moved sideways into it") {
  rise::PointMassPlan plan = Crawl();
  plan.Solve();
  CHECK(plan.feasible);
  // The start (x = 0) is outside the triangle of feet (x = +-0.12) and hand
  // (x = 0.2): the goal lies toward the hand's side.
  CHECK(plan.SupportTriangle().SignedDistance(rise::Ground(plan.com)) > 0.0f);
  CHECK(plan.target.x > 0.01f);
  CHECK(plan.SupportTriangle().SignedDistance(rise::Ground(plan.target)) <= -plan.balanceMargin + 1e-4f);
}

TEST_CASE("an infeasible start reports it") {
  rise::PointMassPlan plan = Crawl();
  plan.supportHand = {0.0f, 0.0f, 5.0f};
  plan.Solve();
  CHECK_FALSE(plan.feasible);
}
}

TEST_SUITE("support_polygon") {
TEST_CASE("signed distance of a unit square") {
  const auto square = rise::SupportPolygon::FromPoints({{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0.5f, 0.5f}});
  CHECK(square.hull.size() == 4);
  CHECK(square.SignedDistance({0.5f, 0.5f}) == doctest::Approx(-0.5f));
  CHECK(square.SignedDistance({2.0f, 0.5f}) == doctest::Approx(1.0f));
  CHECK(square.SignedDistance({0.5f, 0.9f}) == doctest::Approx(-0.1f));
  const glm::vec2 c = square.Closest({2.0f, 2.0f});
  CHECK(c.x == doctest::Approx(1.0f));
  CHECK(c.y == doctest::Approx(1.0f));
  CHECK(square.Centroid().x == doctest::Approx(0.5f));
}
TEST_CASE("a segment has no inside") {
  const auto segment = rise::SupportPolygon::FromPoints({{0, 0}, {1, 0}});
  CHECK(segment.SignedDistance({0.5f, 0.0f}) == doctest::Approx(0.0f));
  CHECK(segment.SignedDistance({0.5f, 0.3f}) == doctest::Approx(0.3f));
}
}

TEST_SUITE("swing_path") {
TEST_CASE("a swing leaves and lands at its ends and peaks at the lift height") {
  rise::SwingPath path{{0, 0, 0}, {0, 0, 0.4f}, {0, 1, 0}, 0.08f};
  CHECK_VEC3_NEAR(path.At(0.0f), path.from, 1e-6f);
  CHECK_VEC3_NEAR(path.At(1.0f), path.to, 1e-6f);
  CHECK(path.At(0.5f).y == doctest::Approx(0.08f).epsilon(1e-4));
  CHECK(path.At(0.5f).z == doctest::Approx(0.2f).epsilon(1e-4));
  CHECK(rise::Ease(0.5f) == doctest::Approx(0.5f));
}
}
