// SPDX-License-Identifier: MIT
// Narrow-phase cost per call for the contact cases a ragdoll meets, as CSV.
#include <chrono>
#include <cstdio>
#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include "physics/collide.h"

namespace {

using rise::physics::BoxShape;
using rise::physics::Manifold;
using rise::physics::Transform;

constexpr int kCalls = 1000000;
constexpr float kSpeculative = 0.02f;

// Runs `collide` kCalls times on poses that differ by sub-micrometre nudges, so
// the compiler cannot hoist the call, and prints nanoseconds per call.
template <typename Collide>
void Measure(const char* name, Transform pose, Collide collide) {
  const float x0 = pose.position.x;
  long points = 0;
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < kCalls; ++i) {
    pose.position.x = x0 + 1e-7f * static_cast<float>(i & 7);
    points += collide(pose).pointCount;
  }
  const auto stop = std::chrono::steady_clock::now();
  const double ns = std::chrono::duration<double, std::nano>(stop - start).count() / kCalls;
  std::printf("%s,%.1f,%.2f\n", name, ns, static_cast<double>(points) / kCalls);
}

}  // namespace

int main() {
  // Forearm- and thigh-sized boxes.
  const BoxShape forearm{{0.04f, 0.13f, 0.04f}};
  const BoxShape thigh{{0.08f, 0.22f, 0.08f}};
  const rise::physics::PlaneShape ground;
  const Transform thighPose{{0.0f, 0.08f, 0.0f}, glm::angleAxis(1.5708f, glm::vec3(1, 0, 0))};

  std::printf("case,ns_per_call,points_per_call\n");
  Measure("plane_box_resting", {{0.0f, 0.04f - 0.001f, 0.0f}, glm::angleAxis(1.5708f, glm::vec3(0, 0, 1))},
          [&](const Transform& t) { return rise::physics::CollidePlaneBox(ground, forearm, t, kSpeculative); });
  Measure("plane_box_airborne", {{0.0f, 0.5f, 0.0f}, glm::angleAxis(0.3f, glm::vec3(0.7071f, 0.0f, 0.7071f))},
          [&](const Transform& t) { return rise::physics::CollidePlaneBox(ground, forearm, t, kSpeculative); });
  // A forearm lying across a thigh: face contact with clipping.
  Measure("box_box_face", {{0.02f, 0.16f + 0.04f - 0.001f, 0.03f}, glm::angleAxis(1.5708f, glm::vec3(0, 0, 1))},
          [&](const Transform& t) { return rise::physics::CollideBoxes(thigh, thighPose, forearm, t, kSpeculative); });
  // Both turned 45 deg about their long axes, crossing edge on edge 1 mm deep.
  const Transform thighOnEdge{thighPose.position, glm::angleAxis(0.7854f, glm::vec3(0, 0, 1)) * thighPose.rotation};
  const float edgeHeight = 0.08f + (0.08f + 0.04f) * 1.41421f - 0.001f;
  Measure(
      "box_box_edge",
      {{0.0f, edgeHeight, 0.0f},
       glm::angleAxis(0.7854f, glm::vec3(1, 0, 0)) * glm::angleAxis(1.5708f, glm::vec3(0, 0, 1))},
      [&](const Transform& t) { return rise::physics::CollideBoxes(thigh, thighOnEdge, forearm, t, kSpeculative); });
  Measure("box_box_far", {{0.6f, 0.5f, 0.0f}, glm::angleAxis(0.3f, glm::vec3(0, 1, 0))},
          [&](const Transform& t) { return rise::physics::CollideBoxes(thigh, thighPose, forearm, t, kSpeculative); });
  return 0;
}
