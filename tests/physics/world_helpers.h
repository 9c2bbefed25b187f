// SPDX-License-Identifier: MIT
// What the physics tests share: adding a plain box, and measuring a running world (how low a box
// reaches, the period of a swinging pendulum).
#pragma once

#include "physics/world.h"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace rise::test {

// A box body of the given mass at `position`, unrotated, at rest.
inline physics::BodyId AddBox(physics::World& world, const glm::vec3& position, const glm::vec3& halfExtents, float mass) {
  physics::BodyDef def;
  def.box.halfExtents = halfExtents;
  def.mass = mass;
  def.transform.position = position;
  return world.CreateBody(def);
}

// Height of a box's lowest corner along `up`, m.
inline float LowestCornerHeight(const physics::World& world, physics::BodyId body,
                                const glm::vec3& up = glm::vec3(0.0f, 1.0f, 0.0f)) {
  const physics::Transform& t = world.GetTransform(body);
  const glm::vec3 h = world.GetBox(body).halfExtents;
  float lowest = 1e9f;
  for (int corner = 0; corner < 8; ++corner) {
    const glm::vec3 sign((corner & 1) ? 1.0f : -1.0f, (corner & 2) ? 1.0f : -1.0f, (corner & 4) ? 1.0f : -1.0f);
    lowest = std::min(lowest, glm::dot(up, t.position + t.rotation * (sign * h)));
  }
  return lowest;
}

struct PendulumSwing {
  double period = 0.0;    // s, mean time between downward zero crossings
  size_t crossings = 0;
};

// Steps the world and times the bob's swing angle (toward `swing`, a horizontal unit vector,
// from straight below the pivot) through zero on the way down, crossings linearly interpolated.
inline PendulumSwing MeasurePendulum(physics::World& world, physics::BodyId bob, const glm::vec3& pivot,
                                     const glm::vec3& swing, int steps) {
  std::vector<double> crossings;
  auto angleOf = [&] {
    const glm::vec3 r = world.GetTransform(bob).position - pivot;
    return std::atan2(glm::dot(r, swing), -r.y);
  };
  float previous = angleOf();
  for (int i = 0; i < steps; ++i) {
    world.Step();
    const float angle = angleOf();
    if (previous > 0.0f && angle <= 0.0f) {
      crossings.push_back(world.Time() - world.Settings().timeStep * double(angle / (angle - previous)));
    }
    previous = angle;
  }
  PendulumSwing result;
  result.crossings = crossings.size();
  if (crossings.size() >= 2) result.period = (crossings.back() - crossings.front()) / double(crossings.size() - 1);
  return result;
}

}  // namespace rise::test
