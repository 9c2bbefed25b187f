// SPDX-License-Identifier: MIT
// Contacts: resting, friction on a slope, stacking, energy, reported normal forces, a fast impact
// (the 2 cm ground bar of every clip).
#include "physics/world.h"
#include "physics/world_helpers.h"
#include "test_support.h"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace rise::physics;
using rise::test::LowestCornerHeight;

namespace {

constexpr float kPi = 3.14159265358979f;


BodyId AddBox(World& world, glm::vec3 position, glm::vec3 halfExtents, float mass, float friction,
              glm::quat rotation = glm::quat(1.0f, 0.0f, 0.0f, 0.0f)) {
  BodyDef def;
  def.box.halfExtents = halfExtents;
  def.mass = mass;
  def.friction = friction;
  def.transform.position = position;
  def.transform.rotation = rotation;
  return world.CreateBody(def);
}

// A box resting on a slope of `angle` with friction mu; returns the displacement along the
// downhill direction after `seconds` and the speed then.
std::pair<float, float> SlideOnSlope(float angle, float mu, float seconds) {
  World world;
  const glm::vec3 normal(0.0f, std::cos(angle), std::sin(angle));  // slope descends towards +z
  world.AddStaticPlane(PlaneShape{normal, 0.0f}, mu);
  const glm::quat tilt = glm::angleAxis(angle, glm::vec3(1.0f, 0.0f, 0.0f));
  const glm::vec3 half(0.25f);
  const BodyId box = AddBox(world, normal * half.y, half, 5.0f, mu, tilt);
  const glm::vec3 start = world.GetTransform(box).position;
  const int steps = int(std::lround(seconds / world.Settings().timeStep));
  for (int i = 0; i < steps; ++i) world.Step();
  const glm::vec3 down(0.0f, -std::sin(angle), std::cos(angle));
  return {glm::dot(world.GetTransform(box).position - start, down), glm::length(world.GetLinearVelocity(box))};
}

}  // namespace

TEST_SUITE("physics.contact_solver") {
  TEST_CASE("a box rests on the ground for 10 s without sinking, drifting or jittering") {
    World world;
    world.AddStaticPlane(PlaneShape{}, 0.6f);
    const BodyId box = AddBox(world, glm::vec3(0.3f, 0.5f, -0.2f), glm::vec3(0.5f), 10.0f, 0.6f);
    const glm::vec3 start = world.GetTransform(box).position;
    float maxPenetration = 0.0f;
    for (int i = 0; i < 2400; ++i) {
      world.Step();
      maxPenetration = std::max(maxPenetration, -LowestCornerHeight(world, box));
    }
    const glm::vec3 end = world.GetTransform(box).position;
    const float drift = glm::length(glm::vec3(end.x - start.x, 0.0f, end.z - start.z));
    const float speed = glm::length(world.GetLinearVelocity(box));
    INFO("penetration " << maxPenetration << " m, drift " << drift << " m, speed " << speed << " m/s");
    CHECK(maxPenetration < 1e-3f);
    CHECK(drift < 1e-3f);
    CHECK(speed < 1e-3f);
    CHECK(glm::length(world.GetAngularVelocity(box)) < 1e-3f);

    // The reported ground forces carry the weight.
    std::vector<ContactInfo> contacts;
    world.GetGroundContacts(box, contacts);
    float force = 0.0f;
    for (const ContactInfo& c : contacts) {
      force += c.normalForce;
      CHECK_VEC3_NEAR(c.normal, glm::vec3(0.0f, 1.0f, 0.0f), 1e-6f);
    }
    CHECK(contacts.size() == 4);
    CHECK(force == doctest::Approx(10.0f * 9.81f).epsilon(0.01));
  }

  TEST_CASE("a box on a 20 deg slope stays with mu 0.6 and slides at g (sin - mu cos) with mu 0.2") {
    const float angle = 20.0f * kPi / 180.0f;
    const auto [stickDistance, stickSpeed] = SlideOnSlope(angle, 0.6f, 3.0f);
    INFO("mu 0.6: moved " << stickDistance << " m, speed " << stickSpeed << " m/s");
    CHECK(std::fabs(stickDistance) < 1e-3f);
    CHECK(stickSpeed < 1e-3f);

    // From rest, d = a t^2 / 2.
    const float seconds = 1.0f;
    const auto [slideDistance, slideSpeed] = SlideOnSlope(angle, 0.2f, seconds);
    const float expected = 9.81f * (std::sin(angle) - 0.2f * std::cos(angle));
    const float measured = 2.0f * slideDistance / (seconds * seconds);
    INFO("mu 0.2: a = " << measured << " m/s^2, expected " << expected << ", v = " << slideSpeed);
    CHECK(std::fabs(measured - expected) / expected < 0.05f);
    CHECK(std::fabs(slideSpeed - expected * seconds) / (expected * seconds) < 0.05f);
  }

  TEST_CASE("a box rests on a static box step") {
    World world;
    world.AddStaticPlane(PlaneShape{}, 0.6f);
    Transform stepPose;
    stepPose.position = glm::vec3(0.0f, 0.1f, 0.0f);
    world.AddStaticBox(BoxShape{glm::vec3(0.5f, 0.1f, 0.5f)}, stepPose, 0.6f);
    const BodyId box = AddBox(world, glm::vec3(0.1f, 0.4f, 0.0f), glm::vec3(0.2f), 8.0f, 0.6f);
    for (int i = 0; i < 240 * 3; ++i) world.Step();
    const float bottom = LowestCornerHeight(world, box);
    std::vector<ContactInfo> contacts;
    world.GetGroundContacts(box, contacts);
    float force = 0.0f;
    for (const ContactInfo& c : contacts) force += c.normalForce;
    INFO("bottom " << bottom << " m (step top 0.2 m), ground force " << force << " N");
    CHECK(std::fabs(bottom - 0.2f) < 1e-3f);
    CHECK(glm::length(world.GetLinearVelocity(box)) < 1e-3f);
    CHECK(force == doctest::Approx(8.0f * 9.81f).epsilon(0.01));
    for (const ContactInfo& c : contacts) CHECK(c.staticShape.index == 1);
  }

  TEST_CASE("a stack of 8 boxes stands for 10 s") {
    World world;
    world.AddStaticPlane(PlaneShape{}, 0.6f);
    const float half = 0.25f;
    std::vector<BodyId> boxes;
    for (int i = 0; i < 8; ++i) {
      boxes.push_back(AddBox(world, glm::vec3(0.0f, half + 2.0f * half * float(i), 0.0f), glm::vec3(half), 5.0f, 0.6f));
    }
    for (int i = 0; i < 2400; ++i) REQUIRE(world.Step().Ok());
    float maxShift = 0.0f;
    for (int i = 0; i < 8; ++i) {
      const glm::vec3 p = world.GetTransform(boxes[i]).position;
      maxShift = std::max(maxShift, glm::length(glm::vec2(p.x, p.z)));
    }
    const float topHeight = world.GetTransform(boxes[7]).position.y;
    const float topSpeed = glm::length(world.GetLinearVelocity(boxes[7]));
    INFO("max sideways shift " << maxShift << " m, top height " << topHeight << " m, top speed " << topSpeed);
    CHECK(maxShift < 1e-2f);
    CHECK(topHeight == doctest::Approx(15.0f * half).epsilon(0.01));  // soft contacts compress a little
    CHECK(topSpeed < 1e-2f);
  }

  TEST_CASE("the energy of a tumbling box with friction never increases") {
    World world;
    world.AddStaticPlane(PlaneShape{}, 0.5f);
    const glm::quat tilt = glm::angleAxis(0.4f, glm::normalize(glm::vec3(1.0f, 0.0f, 1.0f)));
    const BodyId box = AddBox(world, glm::vec3(0.0f, 0.8f, 0.0f), glm::vec3(0.3f, 0.2f, 0.15f), 4.0f, 0.5f, tilt);
    world.SetLinearVelocity(box, glm::vec3(2.0f, 0.0f, 1.0f));
    world.SetAngularVelocity(box, glm::vec3(0.0f, 3.0f, 5.0f));
    const double e0 = world.TotalEnergy();
    double lowest = e0;
    double worstRise = 0.0;
    for (int i = 0; i < 240 * 4; ++i) {
      world.Step();
      const double e = world.TotalEnergy();
      worstRise = std::max(worstRise, e - lowest);
      lowest = std::min(lowest, e);
    }
    INFO("E0 " << e0 << " J, final " << world.TotalEnergy() << " J, worst rise " << worstRise << " J");
    CHECK(worstRise <= 0.01 * e0);
    CHECK(world.TotalEnergy() < 0.5 * e0);
  }

  // 12 m/s is the fastest a hand or foot reaches the ground in the stress runner's drops: 5 cm a
  // step at 240 Hz, more than the 2 cm speculative distance. The start heights sweep one step's
  // travel, so some start has the corner just outside the speculative distance a step before it
  // would pass the ground.
  TEST_CASE("a hand-sized box thrown corner first at the ground at 12 m/s never goes 2 cm below it") {
    const glm::quat tilt = glm::angleAxis(0.5f, glm::normalize(glm::vec3(1.0f, 0.2f, 0.6f)));
    const glm::vec3 half(0.045f, 0.015f, 0.09f);
    const float speed = 12.0f;
    float deepest = 0.0f;
    float deepestStart = 0.0f;
    for (int start = 0; start < 10; ++start) {
      World world;
      world.AddStaticPlane(PlaneShape{}, 0.8f);
      const BodyId box = AddBox(world, glm::vec3(0.0f), half, 0.4f, 0.8f, tilt);
      // Lowest corner at 0.3 m plus a tenth of a step's travel per start.
      const float lift =
          0.3f + 0.1f * float(start) * speed * world.Settings().timeStep - LowestCornerHeight(world, box);
      world.SetTransform(box, Transform{glm::vec3(0.0f, lift, 0.0f), tilt});
      world.SetLinearVelocity(box, glm::vec3(1.0f, -speed, 0.0f));
      for (int i = 0; i < 120; ++i) {
        REQUIRE(world.Step().Ok());
        const float depth = -LowestCornerHeight(world, box);
        if (depth > deepest) {
          deepest = depth;
          deepestStart = float(start);
        }
      }
    }
    INFO("deepest " << deepest << " m (start " << deepestStart << ")");
    CHECK(deepest < 0.02f);
  }
}
