// SPDX-License-Identifier: MIT
// Joints: pendulum period, hanging chain, limits under load, PD motor.
#include "physics/world.h"
#include "physics/joint_solver_tags.h"
#include "physics/world_helpers.h"
#include "test_support.h"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

using namespace rise::physics;
using rise::test::AddBox;
using rise::test::MeasurePendulum;
using rise::test::PendulumSwing;

namespace {

constexpr float kPi = 3.14159265358979f;
constexpr float kDegree = kPi / 180.0f;

// A 2 kg rod along +z hinged to the world at (0, 1, 0) about world x; gravity turns it to +angle.
struct HingedRod {
  World world;
  BodyId rod;
  JointId hinge;
  static constexpr float kMass = 2.0f;
  static constexpr float kHalfLength = 0.25f;

  explicit HingedRod(const WorldSettings& settings, const MotorDef& motor = MotorDef{}, bool limits = false,
                     AngleRange range = {})
      : world(settings) {
    rod = AddBox(world, glm::vec3(0.0f, 1.0f, kHalfLength), glm::vec3(0.03f, 0.03f, kHalfLength), kMass);
    JointDef def;
    def.type = JointType::kHinge;
    def.bodyB = rod;
    def.anchor = glm::vec3(0.0f, 1.0f, 0.0f);
    def.enableLimits = limits;
    def.twistLimits = range;
    def.motor = motor;
    hinge = world.CreateJoint(def);
  }
  float Angle() const {
    const glm::quat q = world.GetJointRelativeRotation(hinge);
    return 2.0f * std::atan2(q.x, q.w);
  }
};

}  // namespace

TEST_SUITE("physics.joint") {
  TEST_CASE_TEMPLATE("a hinge pendulum swings with period 2 pi sqrt(L / g)", T, RISE_JOINT_SOLVERS) {
    World world(rise::test::WithJointSolver<T>());
    const float length = 1.0f;
    const float amplitude = 5.0f * kDegree;
    const glm::vec3 pivot(0.0f, 2.0f, 0.0f);
    const BodyId bob = AddBox(world, pivot + length * glm::vec3(0.0f, -std::cos(amplitude), std::sin(amplitude)),
                              glm::vec3(0.01f), 1.0f);
    JointDef def;
    def.type = JointType::kHinge;
    def.bodyB = bob;
    def.anchor = pivot;
    world.CreateJoint(def);

    const PendulumSwing swing = MeasurePendulum(world, bob, pivot, glm::vec3(0.0f, 0.0f, 1.0f), 240 * 12);
    REQUIRE(swing.crossings >= 5);
    const double period = swing.period;
    const double expected = 2.0 * 3.14159265358979 * std::sqrt(double(length) / 9.81);
    INFO("period " << period << " s, expected " << expected << " s");
    CHECK(std::fabs(period - expected) / expected < 0.01);
  }

  TEST_CASE_TEMPLATE("a 15-link hanging chain stays connected and calm after a kick", T, RISE_JOINT_SOLVERS) {
    World world(rise::test::WithJointSolver<T>());
    const int links = 15;
    const float halfLength = 0.05f;
    const glm::vec3 top(0.0f, 2.0f, 0.0f);
    std::vector<BodyId> bodies;
    std::vector<JointId> joints;
    for (int i = 0; i < links; ++i) {
      bodies.push_back(AddBox(world, top - glm::vec3(0.0f, halfLength * float(2 * i + 1), 0.0f),
                              glm::vec3(0.02f, halfLength, 0.02f), 0.5f));
      JointDef def;
      def.type = JointType::kBall;
      def.bodyA = i == 0 ? kWorldBody : bodies[i - 1];
      def.bodyB = bodies[i];
      def.anchor = top - glm::vec3(0.0f, 2.0f * halfLength * float(i), 0.0f);
      joints.push_back(world.CreateJoint(def));
    }
    const glm::vec3 kick(1.0f, 0.0f, 0.5f);
    world.SetLinearVelocity(bodies.back(), kick);
    const double kickEnergy = 0.5 * 0.5 * double(glm::dot(kick, kick));
    const double e0 = world.TotalEnergy();
    float maxError = 0.0f;
    double maxEnergy = e0;
    for (int i = 0; i < 240 * 5; ++i) {
      REQUIRE(world.Step().Ok());
      for (JointId joint : joints) maxError = std::max(maxError, world.GetJointAnchorSeparation(joint));
      maxEnergy = std::max(maxEnergy, world.TotalEnergy());
    }
    INFO("max joint error " << maxError << " m, E0 " << e0 << " J, max E " << maxEnergy << " J");
    CHECK(maxError < 1e-3f);
    // Calm: the soft joints never feed energy in (within 1 % of the kick's).
    CHECK(maxEnergy - e0 <= 0.01 * kickEnergy);
  }

  TEST_CASE_TEMPLATE("a hinge limit holds within 1 deg under gravity and a torque pushing past it", T, RISE_JOINT_SOLVERS) {
    HingedRod rig(rise::test::WithJointSolver<T>(), MotorDef{}, true, AngleRange{-0.3f, 0.3f});
    float maxAngle = -1.0f;
    for (int i = 0; i < 240 * 2; ++i) {
      rig.world.ApplyTorque(rig.rod, glm::vec3(20.0f, 0.0f, 0.0f));
      rig.world.Step();
      maxAngle = std::max(maxAngle, rig.Angle());
    }
    INFO("max angle " << maxAngle / kDegree << " deg, limit " << 0.3f / kDegree << " deg");
    CHECK(maxAngle < 0.3f + kDegree);
    CHECK(maxAngle > 0.3f - kDegree);
  }

  TEST_CASE_TEMPLATE("universal, gimbal and ball limits hold within 1 deg under torques pushing past them", T,
                     RISE_JOINT_SOLVERS) {
    struct Case {
      JointType type;
      glm::vec3 torque;
    };
    // Rods along +x (the twist axis) from a world anchor; no gravity, only the pushing torque.
    const Case cases[] = {{JointType::kUniversal, {0.0f, 30.0f, 0.0f}},  // alpha, about A's y
                          {JointType::kUniversal, {0.0f, 0.0f, -30.0f}}, // beta, about B's z
                          {JointType::kGimbal, {0.0f, 30.0f, 0.0f}},     // alpha, about A's y
                          {JointType::kGimbal, {0.0f, 0.0f, -30.0f}},    // beta, the middle axis
                          {JointType::kGimbal, {30.0f, 0.0f, 0.0f}},     // gamma, the twist about B's x
                          {JointType::kGimbal, {30.0f, -30.0f, -30.0f}}, // all three at once
                          {JointType::kBall, {0.0f, 0.0f, 30.0f}},       // swing cone
                          {JointType::kBall, {30.0f, 0.0f, 0.0f}}};      // twist
    for (const Case& c : cases) {
      WorldSettings settings;
      settings.gravity = glm::vec3(0.0f);
      World world(rise::test::WithJointSolver<T>(settings));
      const BodyId rod = AddBox(world, glm::vec3(0.25f, 0.0f, 0.0f), glm::vec3(0.25f, 0.04f, 0.04f), 2.0f);
      JointDef def;
      def.type = c.type;
      def.bodyB = rod;
      def.enableLimits = true;
      def.swingYLimits = {-0.4f, 0.5f};
      def.swingZLimits = {-0.6f, 0.3f};
      def.swingCone = 0.7f;
      def.twistLimits = {-0.2f, 0.45f};
      const JointId joint = world.CreateJoint(def);
      float worst = 0.0f;  // largest violation of any limit, rad
      float reached = 0.0f;
      for (int i = 0; i < 240 * 2; ++i) {
        world.ApplyTorque(rod, c.torque);
        world.Step();
        const glm::quat q = world.GetJointRelativeRotation(joint);
        const glm::mat3 r = glm::mat3_cast(q);
        if (c.type == JointType::kUniversal) {
          const float alpha = std::atan2(r[2].x, r[2].z);
          const float beta = std::atan2(r[0].y, r[1].y);
          worst = std::max({worst, alpha - 0.5f, -0.4f - alpha, beta - 0.3f, -0.6f - beta});
          reached = std::max(std::fabs(alpha), std::fabs(beta));
        } else if (c.type == JointType::kGimbal) {
          // qRel = Ry(alpha) Rz(beta) Rx(gamma), read back as joint_gimbal.cpp defines the angles.
          const float alpha = std::atan2(-r[0].z, r[0].x);
          const float beta = std::asin(std::clamp(r[0].y, -1.0f, 1.0f));
          const float gamma = std::atan2(-r[2].y, r[1].y);
          worst = std::max({worst, alpha - 0.5f, -0.4f - alpha, beta - 0.3f, -0.6f - beta, gamma - 0.45f, -0.2f - gamma});
          reached = std::max({std::fabs(alpha), std::fabs(beta), std::fabs(gamma)});
        } else {
          const float swing = std::acos(std::clamp(r[0].x, -1.0f, 1.0f));
          const glm::quat qq = q.w < 0.0f ? -q : q;
          const float twist = 2.0f * std::atan2(qq.x, qq.w);
          worst = std::max({worst, swing - 0.7f, twist - 0.45f, -0.2f - twist});
          reached = std::max(swing, std::fabs(twist));
        }
      }
      INFO("type " << int(c.type) << ": worst violation " << worst / kDegree << " deg, reached " << reached / kDegree
                   << " deg");
      CHECK(worst < kDegree);
      CHECK(reached > 0.25f);  // the torque did drive the joint to a limit
    }
  }

  TEST_CASE_TEMPLATE("a PD motor reaches its target within 2 deg and reports the holding torque", T, RISE_JOINT_SOLVERS) {
    MotorDef motor;
    motor.enabled = true;
    const float target = -0.5f;  // rod raised 0.5 rad above horizontal, against gravity
    motor.target = glm::angleAxis(target, glm::vec3(1.0f, 0.0f, 0.0f));
    motor.stiffness = 400.0f;
    motor.damping = 40.0f;
    motor.maxTorque = 100.0f;
    HingedRod rig(rise::test::WithJointSolver<T>(), motor);
    for (int i = 0; i < 240 * 3; ++i) rig.world.Step();
    const float gravityTorque = HingedRod::kMass * 9.81f * HingedRod::kHalfLength * std::cos(rig.Angle());
    const glm::vec3 torque = rig.world.GetMotorTorque(rig.hinge);
    INFO("angle " << rig.Angle() / kDegree << " deg, motor torque " << torque.x << " N m, gravity " << gravityTorque);
    CHECK(std::fabs(rig.Angle() - target) < 2.0f * kDegree);
    // Static balance: the motor's torque cancels gravity's (k (angle - target) = m g a cos).
    CHECK(-torque.x == doctest::Approx(gravityTorque).epsilon(0.02));
    CHECK(rig.Angle() - target == doctest::Approx(gravityTorque / 400.0f).epsilon(0.05));

    SUBCASE("feed-forward of the gravity torque removes the steady-state error") {
      rig.world.SetMotorFeedForward(rig.hinge, glm::vec3(-gravityTorque, 0.0f, 0.0f));
      for (int i = 0; i < 240 * 3; ++i) rig.world.Step();
      INFO("angle " << rig.Angle() / kDegree << " deg");
      CHECK(std::fabs(rig.Angle() - target) < 0.05f * kDegree);
    }
    SUBCASE("the torque clamp lets a weak motor sag") {
      rig.world.SetMotorGains(rig.hinge, 400.0f, 40.0f, 2.0f);
      float maxTorque = 0.0f;
      float maxAngle = -1.0f;
      for (int i = 0; i < 240 * 3; ++i) {
        rig.world.Step();
        maxTorque = std::max(maxTorque, glm::length(rig.world.GetMotorTorque(rig.hinge)));
        maxAngle = std::max(maxAngle, rig.Angle());
      }
      INFO("max torque " << maxTorque << " N m, max angle " << maxAngle / kDegree << " deg");
      CHECK(maxTorque <= 2.0f + 1e-4f);
      CHECK(maxAngle > 0.5f);  // swings well past horizontal: 2 N m cannot hold the 4.9 N m rod
    }
  }

  TEST_CASE_TEMPLATE("a PD motor's speed limit closes a large error at that speed, and a small one as before", T,
                     RISE_JOINT_SOLVERS) {
    WorldSettings settings = rise::test::WithJointSolver<T>();
    settings.gravity = glm::vec3(0.0f);
    MotorDef motor;
    motor.enabled = true;
    motor.stiffness = 400.0f;
    motor.damping = 32.0f;
    motor.maxTorque = 100.0f;
    // The peak angular speed and the final angle of a swing to `target`.
    auto swing = [&](float target, float maxSpeed) {
      MotorDef m = motor;
      m.target = glm::angleAxis(target, glm::vec3(1.0f, 0.0f, 0.0f));
      m.maxSpeed = maxSpeed;
      HingedRod rig(settings, m);
      float peak = 0.0f;
      for (int i = 0; i < 240 * 2; ++i) {
        rig.world.Step();
        peak = std::max(peak, glm::length(rig.world.GetAngularVelocity(rig.rod)));
      }
      return std::make_pair(peak, rig.Angle());
    };
    const float inf = std::numeric_limits<float>::infinity();
    // A half turn: unlimited, the 100 N m motor whips the rod past 20 rad/s.
    const auto [freePeak, freeEnd] = swing(2.5f, inf);
    const auto [limitedPeak, limitedEnd] = swing(2.5f, 6.0f);
    INFO("peak " << freePeak << " rad/s unlimited, " << limitedPeak << " rad/s limited to 6");
    CHECK(freePeak > 15.0f);
    CHECK(limitedPeak < 6.0f * 1.05f);
    CHECK(limitedPeak > 6.0f * 0.9f);
    CHECK(std::fabs(limitedEnd - 2.5f) < 1.0f * kDegree);
    CHECK(std::fabs(freeEnd - 2.5f) < 1.0f * kDegree);
    // An error the spring closes below the limit (12.5 rad/s per rad here) is untouched.
    const auto [smallFree, smallFreeEnd] = swing(0.2f, inf);
    const auto [smallLimited, smallLimitedEnd] = swing(0.2f, 6.0f);
    CHECK(smallLimited == doctest::Approx(smallFree).epsilon(1e-6));
    CHECK(smallLimitedEnd == doctest::Approx(smallFreeEnd).epsilon(1e-6));
  }
}
