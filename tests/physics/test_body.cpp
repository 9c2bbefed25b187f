// SPDX-License-Identifier: MIT
// Bodies: box inertia, world inertia, free fall, and the implicit gyroscopic step.
#include "physics/body.h"
#include "physics/world.h"
#include "test_support.h"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cmath>

using namespace rise::physics;

TEST_SUITE("physics.body") {
  TEST_CASE("box inertia matches m (b^2 + c^2) / 12") {
    // Full sizes 1 x 2 x 3 m, 12 kg: Ix = 1 * (4 + 9), Iy = 1 * (1 + 9), Iz = 1 * (1 + 4).
    const glm::vec3 inertia = BoxInertia(glm::vec3(0.5f, 1.0f, 1.5f), 12.0f);
    CHECK(inertia.x == doctest::Approx(13.0f).epsilon(1e-6));
    CHECK(inertia.y == doctest::Approx(10.0f).epsilon(1e-6));
    CHECK(inertia.z == doctest::Approx(5.0f).epsilon(1e-6));
  }

  TEST_CASE("world inverse inertia follows the rotation") {
    BodyDef def;
    def.box.halfExtents = glm::vec3(0.5f, 1.0f, 1.5f);
    def.mass = 12.0f;
    // A quarter turn about z swaps the body's x and y axes in the world.
    def.transform.rotation = glm::angleAxis(0.5f * 3.14159265f, glm::vec3(0.0f, 0.0f, 1.0f));
    const Body body = MakeBody(def);
    CHECK(body.invInertiaWorld[0][0] == doctest::Approx(1.0f / 10.0f).epsilon(1e-5));
    CHECK(body.invInertiaWorld[1][1] == doctest::Approx(1.0f / 13.0f).epsilon(1e-5));
    CHECK(body.invInertiaWorld[2][2] == doctest::Approx(1.0f / 5.0f).epsilon(1e-5));
    CHECK(std::fabs(body.invInertiaWorld[0][1]) < 1e-6f);
  }

  TEST_CASE("free fall follows y0 - g t^2 / 2") {
    const float y0 = 10.0f;
    auto fall = [&](int substeps) {
      WorldSettings settings;
      settings.substepCount = substeps;
      World world(settings);
      BodyDef def;
      def.transform.position = glm::vec3(0.0f, y0, 0.0f);
      const BodyId body = world.CreateBody(def);
      const int steps = int(std::lround(1.0f / settings.timeStep));
      for (int i = 0; i < steps; ++i) world.Step();
      return std::pair<float, float>(world.GetTransform(body).position.y, world.GetLinearVelocity(body).y);
    };
    const float g = 9.81f;
    const float exact = y0 - 0.5f * g;

    // Default settings: the velocity is exact; semi-implicit Euler leads the position by g t h / 2
    // (h = 1/960 s), a relative error of 1.0e-3 of the 4.9 m drop.
    const auto [yDefault, vDefault] = fall(WorldSettings{}.substepCount);
    CHECK(vDefault == doctest::Approx(-g).epsilon(1e-5));
    const float h = WorldSettings{}.timeStep / float(WorldSettings{}.substepCount);
    CHECK(std::fabs(yDefault - (exact - 0.5f * g * h)) < 1e-4f);
    CHECK(std::fabs(yDefault - exact) / (0.5f * g) < 1.1e-3f);

    // With 24 sub-steps per 1/240 s step the position is within 1 mm absolute.
    const auto [yFine, vFine] = fall(24);
    CHECK(std::fabs(yFine - exact) < 1e-3f);
    CHECK(vFine == doctest::Approx(-g).epsilon(1e-4));
  }

  TEST_CASE("a tumbling box keeps its angular momentum and never gains energy") {
    WorldSettings settings;
    settings.gravity = glm::vec3(0.0f);
    World world(settings);
    BodyDef def;
    def.box.halfExtents = glm::vec3(0.05f, 0.3f, 0.15f);
    def.mass = 2.0f;
    // Mostly about the intermediate axis (z), the unstable one: explicit Euler blows up here.
    def.angularVelocity = glm::vec3(0.1f, 0.2f, 8.0f);
    const BodyId body = world.CreateBody(def);
    auto momentum = [&]() {
      const Transform& t = world.GetTransform(body);
      const glm::vec3 wLocal = glm::conjugate(t.rotation) * world.GetAngularVelocity(body);
      return glm::length(BoxInertia(def.box.halfExtents, def.mass) * wLocal);
    };
    const float l0 = momentum();
    const double e0 = world.TotalEnergy();
    double highest = e0;
    for (int i = 0; i < 240 * 5; ++i) {
      world.Step();
      highest = std::max(highest, world.TotalEnergy());
    }
    const double e = world.TotalEnergy();
    INFO("L0 = " << l0 << ", L = " << momentum() << ", E0 = " << e0 << ", max E = " << highest << ", E = " << e);
    CHECK(highest <= e0 * (1.0 + 1e-5));
    CHECK(std::fabs(momentum() - l0) / l0 < 0.02f);
    CHECK(e > 0.95 * e0);
  }
}
