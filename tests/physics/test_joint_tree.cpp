// SPDX-License-Identifier: MIT
// The direct joint-tree solver (JointSolver::kDirectTree): exactness, pendulum, chains, loops,
// the ragdoll drop at 2 sub-steps, energy and determinism.
#include "physics/world.h"
#include "physics/world_helpers.h"
#include "scenes/ragdoll_drop.h"
#include "test_support.h"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>
#include <vector>

using namespace rise;
using namespace rise::physics;
using rise::test::AddBox;
using rise::test::LowestCornerHeight;
using rise::test::MeasurePendulum;
using rise::test::PendulumSwing;

namespace {

WorldSettings DirectSettings(int substeps) {
  WorldSettings settings;
  settings.jointSolver = JointSolver::kDirectTree;
  settings.substepCount = substeps;
  return settings;
}

// A chain of `links` boxes hanging down from `top` on ball joints. childIsA builds every joint
// the other way round (A = lower link), so the solver sees children on side A.
struct HangingChain {
  static constexpr float kHalfLength = 0.05f;
  std::vector<BodyId> bodies;
  std::vector<JointId> joints;
  HangingChain(World& world, int links, glm::vec3 top, bool childIsA = false, float heavyEvery = 0.0f) {
    for (int i = 0; i < links; ++i) {
      // Alternating heavy and light links (heavyEvery > 0) make the chain badly conditioned.
      const float mass = heavyEvery > 0.0f && i % 2 == 1 ? heavyEvery : 0.5f;
      bodies.push_back(AddBox(world, top - glm::vec3(0.0f, kHalfLength * float(2 * i + 1), 0.0f),
                              glm::vec3(0.02f, kHalfLength, 0.02f), mass));
      JointDef def;
      def.type = JointType::kBall;
      def.bodyA = i == 0 ? kWorldBody : bodies[i - 1];
      def.bodyB = bodies[i];
      if (childIsA && i > 0) std::swap(def.bodyA, def.bodyB);
      def.anchor = top - glm::vec3(0.0f, 2.0f * kHalfLength * float(i), 0.0f);
      joints.push_back(world.CreateJoint(def));
    }
  }
  float WorstSeparation(const World& world) const {
    float worst = 0.0f;
    for (JointId joint : joints) worst = std::max(worst, world.GetJointAnchorSeparation(joint));
    return worst;
  }
};

// Random linear and angular velocities up to `speed` per axis (m/s, rad/s) on every link; a
// fixed seed of its own, so the test does not depend on which tests ran before.
void ThrowLinks(World& world, const HangingChain& chain, float speed) {
  std::mt19937 rng(7u);
  std::uniform_real_distribution<float> uniform(-speed, speed);
  for (BodyId body : chain.bodies) {
    const glm::vec3 v(uniform(rng), uniform(rng), uniform(rng));
    const glm::vec3 w(uniform(rng), uniform(rng), uniform(rng));
    world.SetLinearVelocity(body, v);
    world.SetAngularVelocity(body, w);
  }
}

// Largest relative velocity of the two anchor points of any joint, each carried by its own body
// (link i's top is joint i's anchor, link i-1's bottom the same anchor on the link above), m/s.
float WorstAnchorSpeed(const World& world, const HangingChain& chain) {
  auto anchorVelocity = [&world](BodyId body, float end) {
    if (!body.IsValid()) return glm::vec3(0.0f);
    const Transform& t = world.GetTransform(body);
    const glm::vec3 r = t.rotation * glm::vec3(0.0f, end * HangingChain::kHalfLength, 0.0f);
    return world.GetLinearVelocity(body) + glm::cross(world.GetAngularVelocity(body), r);
  };
  float worst = 0.0f;
  for (size_t i = 0; i < chain.joints.size(); ++i) {
    const BodyId above = i == 0 ? kWorldBody : chain.bodies[i - 1];
    worst = std::max(worst, glm::length(anchorVelocity(chain.bodies[i], 1.0f) - anchorVelocity(above, -1.0f)));
  }
  return worst;
}

}  // namespace

TEST_SUITE("physics.joint_tree") {
  TEST_CASE("one step leaves every tree joint's anchors moving together, either side the child") {
    for (bool childIsA : {false, true}) {
      WorldSettings settings = DirectSettings(2);
      settings.gravity = glm::vec3(0.0f);
      World world(settings);
      const HangingChain chain(world, 15, glm::vec3(0.0f, 2.0f, 0.0f), childIsA, 5.0f);
      ThrowLinks(world, chain, 3.0f);
      REQUIRE(WorstAnchorSpeed(world, chain) > 1.0f);
      REQUIRE(world.Step().Ok());
      // The last stage of the step is the exact solve at these poses: only rounding is left.
      INFO("child is A: " << childIsA << ", worst anchor speed " << WorstAnchorSpeed(world, chain) << " m/s");
      CHECK(WorstAnchorSpeed(world, chain) < 2e-4f);
    }
  }

  TEST_CASE("a ball-joint pendulum at 2 sub-steps swings with period 2 pi sqrt(L / g)") {
    World world(DirectSettings(2));
    const float length = 0.8f;
    const float amplitude = 4.0f * 3.14159265f / 180.0f;
    const glm::vec3 pivot(0.0f, 2.0f, 0.0f);
    const BodyId bob = AddBox(world, pivot + length * glm::vec3(std::sin(amplitude), -std::cos(amplitude), 0.0f),
                              glm::vec3(0.01f), 1.0f);
    JointDef def;
    def.bodyB = bob;
    def.anchor = pivot;
    world.CreateJoint(def);
    const PendulumSwing swing = MeasurePendulum(world, bob, pivot, glm::vec3(1.0f, 0.0f, 0.0f), 240 * 12);
    REQUIRE(swing.crossings >= 5);
    const double period = swing.period;
    const double expected = 2.0 * 3.14159265358979 * std::sqrt(double(length) / 9.81);
    INFO("period " << period << " s, expected " << expected << " s");
    CHECK(std::fabs(period - expected) / expected < 0.005);
  }

  TEST_CASE("a hanging 15-link chain of alternating 0.5 and 5 kg links does not sag at 2 sub-steps") {
    World world(DirectSettings(2));
    const glm::vec3 top(0.0f, 2.0f, 0.0f);
    const HangingChain chain(world, 15, top, false, 5.0f);
    for (int i = 0; i < 240 * 2; ++i) REQUIRE(world.Step().Ok());
    // The bottom anchor of the last link hangs 15 link lengths below the top when joints are exact.
    const Transform& last = world.GetTransform(chain.bodies.back());
    const glm::vec3 bottom = last.position + last.rotation * glm::vec3(0.0f, -HangingChain::kHalfLength, 0.0f);
    const float sag = (top.y - 30.0f * HangingChain::kHalfLength) - bottom.y;
    INFO("sag " << sag * 1000.0f << " mm, worst joint " << chain.WorstSeparation(world) * 1000.0f << " mm");
    CHECK(std::fabs(sag) < 1e-4f);
    CHECK(chain.WorstSeparation(world) < 2e-5f);
  }

  TEST_CASE("a kicked 15-link chain at 2 sub-steps stays within 0.1 mm and gains no energy") {
    World world(DirectSettings(2));
    const HangingChain chain(world, 15, glm::vec3(0.0f, 2.0f, 0.0f));
    const glm::vec3 kick(1.0f, 0.0f, 0.5f);
    world.SetLinearVelocity(chain.bodies.back(), kick);
    const double kickEnergy = 0.5 * 0.5 * double(glm::dot(kick, kick));
    const double e0 = world.TotalEnergy();
    float worst = 0.0f;
    double maxEnergy = e0;
    for (int i = 0; i < 240 * 5; ++i) {
      REQUIRE(world.Step().Ok());
      worst = std::max(worst, chain.WorstSeparation(world));
      maxEnergy = std::max(maxEnergy, world.TotalEnergy());
    }
    INFO("worst joint " << worst * 1000.0f << " mm, E0 " << e0 << " J, max E " << maxEnergy << " J");
    CHECK(worst < 1e-4f);
    CHECK(maxEnergy - e0 <= 0.01 * kickEnergy);
    CHECK(world.TotalEnergy() < e0);  // the relax pass only ever takes energy out
  }

  TEST_CASE("a 15-link chain of 0.5 and 5 kg links thrown at 3 m/s stays within 4 mm and gains no energy") {
    // Fast-spinning light links turn their lever arms far within a step: the solve must be redone
    // at the new poses to stay a projection (solving with levers frozen for the step exploded).
    World world(DirectSettings(2));
    const HangingChain chain(world, 15, glm::vec3(0.0f, 2.0f, 0.0f), false, 5.0f);
    ThrowLinks(world, chain, 3.0f);
    REQUIRE(world.Step().Ok());
    const double e1 = world.TotalEnergy();  // after the first step has made the velocities consistent
    double maxEnergy = e1;
    float worst = 0.0f;
    for (int i = 0; i < 240 * 2; ++i) {
      REQUIRE(world.Step().Ok());
      worst = std::max(worst, chain.WorstSeparation(world));
      maxEnergy = std::max(maxEnergy, world.TotalEnergy());
    }
    INFO("worst joint " << worst * 1000.0f << " mm, E1 " << e1 << " J, max E " << maxEnergy << " J");
    CHECK(worst < 4e-3f);
    CHECK(maxEnergy <= 1.01 * e1);
  }

  TEST_CASE("a joint that closes a loop keeps the sequential pass and the loop stays closed") {
    World world(DirectSettings(2));
    const HangingChain chain(world, 8, glm::vec3(0.0f, 2.0f, 0.0f));
    // Tie the last link's bottom back to the world beside the top: the ninth joint closes a loop.
    const Transform& last = world.GetTransform(chain.bodies.back());
    JointDef tie;
    tie.bodyB = chain.bodies.back();
    tie.anchor = last.position - glm::vec3(0.0f, HangingChain::kHalfLength, 0.0f);
    const JointId closing = world.CreateJoint(tie);
    world.SetLinearVelocity(chain.bodies[3], glm::vec3(1.0f, 0.0f, 0.0f));
    float worst = 0.0f;
    for (int i = 0; i < 240 * 2; ++i) {
      REQUIRE(world.Step().Ok());
      worst = std::max({worst, chain.WorstSeparation(world), world.GetJointAnchorSeparation(closing)});
    }
    INFO("worst joint " << worst * 1000.0f << " mm");
    CHECK(worst < 1e-3f);
  }

  TEST_CASE("the ragdoll drop at 2 sub-steps: joints within 2 mm, no box deeper than 1 cm, energy falls") {
    const scenes::RagdollScene scene = scenes::MakeRagdollDropScene();
    World world(DirectSettings(2));
    const scenes::BuiltRagdoll ragdoll = scenes::BuildRagdollDrop(scene, world);
    const double e0 = world.TotalEnergy();
    double maxEnergy = e0;
    float deepest = 0.0f;
    float worstJoint = 0.0f;
    for (int i = 0; i < 240 * 5; ++i) {
      REQUIRE(world.Step().Ok());
      for (BodyId body : ragdoll.bodies) deepest = std::max(deepest, -LowestCornerHeight(world, body));
      for (JointId joint : ragdoll.joints) worstJoint = std::max(worstJoint, world.GetJointAnchorSeparation(joint));
      maxEnergy = std::max(maxEnergy, world.TotalEnergy());
    }
    float maxSpeed = 0.0f;
    for (BodyId body : ragdoll.bodies) maxSpeed = std::max(maxSpeed, glm::length(world.GetLinearVelocity(body)));
    INFO("deepest " << deepest * 1000.0f << " mm, worst joint " << worstJoint * 1000.0f << " mm, E0 " << e0
                    << " J, max E " << maxEnergy << " J, final max speed " << maxSpeed << " m/s");
    CHECK(worstJoint <= 2e-3f);
    CHECK(deepest <= 1e-2f);
    CHECK(maxEnergy <= e0 + 1e-3 * std::fabs(e0));
    CHECK(maxSpeed < 0.01f);
  }

  TEST_CASE("switching the joint solver between steps rebuilds the forest; runs are bit-identical") {
    const scenes::RagdollScene scene = scenes::MakeRagdollDropScene();
    auto run = [&scene](bool switchMidway) {
      World world(switchMidway ? WorldSettings{} : DirectSettings(2));
      scenes::BuildRagdollDrop(scene, world);
      std::vector<float> state;
      for (int i = 0; i < 240 * 3; ++i) {
        if (i == 60) world.Settings().jointSolver = JointSolver::kDirectTree;
        world.Step();
      }
      for (int i = 0; i < world.BodyCount(); ++i) {
        const Transform& t = world.GetTransform(BodyId{i});
        state.insert(state.end(), {t.position.x, t.position.y, t.position.z, t.rotation.x, t.rotation.y});
      }
      return state;
    };
    const std::vector<float> direct = run(false);
    const std::vector<float> again = run(false);
    CHECK(std::memcmp(direct.data(), again.data(), direct.size() * sizeof(float)) == 0);
    const std::vector<float> switched = run(true);
    const std::vector<float> switchedAgain = run(true);
    CHECK(std::memcmp(switched.data(), switchedAgain.data(), switched.size() * sizeof(float)) == 0);
    // Both came to rest on the ground in nearly the same place. A foot may settle a little more
    // on its heel in one run than in the other: with the hard-contact passes of the landing
    // (physics/settings.h) the left foot's centre rests 6.4 mm higher in the switched run.
    for (size_t i = 0; i < direct.size(); i += 5) CHECK(std::fabs(direct[i + 1] - switched[i + 1]) < 0.01f);
  }
}
