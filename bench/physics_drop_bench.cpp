// SPDX-License-Identifier: MIT
// Drops the shared 15-box ragdoll (scenes/ragdoll_drop) for 5 s at 240 Hz and prints the cost
// per step, the real-time factor and the quality figures of the drop.
#include "physics/world.h"
#include "scenes/ragdoll_drop.h"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>

namespace {

using namespace rise;

// Depth of the deepest box corner below the ground y = 0, m (0 when nothing is below).
float GroundPenetration(const physics::World& world, const scenes::BuiltRagdoll& ragdoll) {
  float lowest = 0.0f;
  for (physics::BodyId body : ragdoll.bodies) {
    const physics::Transform& t = world.GetTransform(body);
    const glm::vec3 h = world.GetBox(body).halfExtents;
    for (int corner = 0; corner < 8; ++corner) {
      const glm::vec3 sign((corner & 1) ? 1.0f : -1.0f, (corner & 2) ? 1.0f : -1.0f, (corner & 4) ? 1.0f : -1.0f);
      lowest = std::min(lowest, (t.position + t.rotation * (sign * h)).y);
    }
  }
  return -lowest;
}

}  // namespace

int main() {
  const scenes::RagdollScene scene = scenes::MakeRagdollDropScene();
  const physics::WorldSettings settings;
  const int steps = int(scene.simulatedSeconds / settings.timeStep + 0.5f);

  // Quality run: measured every step, not timed.
  physics::World world(settings);
  const scenes::BuiltRagdoll ragdoll = scenes::BuildRagdollDrop(scene, world);
  float peakPenetration = 0.0f;
  float peakJointError = 0.0f;
  bool healthy = true;
  for (int i = 0; i < steps; ++i) {
    healthy = world.Step().Ok() && healthy;
    peakPenetration = std::max(peakPenetration, GroundPenetration(world, ragdoll));
    for (physics::JointId joint : ragdoll.joints) {
      peakJointError = std::max(peakJointError, world.GetJointAnchorSeparation(joint));
    }
  }

  // Timing runs: the same scene from scratch; the best of several runs filters out other load.
  // Thread CPU time is the cost on one core even when other processes share the machine; wall
  // time is printed beside it.
  constexpr int kRuns = 5;
  double bestCpuSeconds = 1e30;
  double bestWallSeconds = 1e30;
  for (int run = 0; run < kRuns; ++run) {
    physics::World timed(settings);
    scenes::BuildRagdollDrop(scene, timed);
    timespec cpuStart{}, cpuEnd{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &cpuStart);
    const auto wallStart = std::chrono::steady_clock::now();
    for (int i = 0; i < steps; ++i) timed.Step();
    const std::chrono::duration<double> wall = std::chrono::steady_clock::now() - wallStart;
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &cpuEnd);
    const double cpu = double(cpuEnd.tv_sec - cpuStart.tv_sec) + 1e-9 * double(cpuEnd.tv_nsec - cpuStart.tv_nsec);
    bestCpuSeconds = std::min(bestCpuSeconds, cpu);
    bestWallSeconds = std::min(bestWallSeconds, wall.count());
  }
  const double microsPerStep = 1e6 * bestCpuSeconds / steps;
  const double realTimeFactor = double(steps) * double(settings.timeStep) / bestCpuSeconds;

  std::printf("ragdoll drop: %zu boxes, %zu joints, %d steps of %.6f s, %d sub-steps\n", ragdoll.bodies.size(),
              ragdoll.joints.size(), steps, double(settings.timeStep), settings.substepCount);
  std::printf("us_per_step,%.2f\n", microsPerStep);
  std::printf("real_time_factor,%.0f\n", realTimeFactor);
  std::printf("wall_us_per_step,%.2f\n", 1e6 * bestWallSeconds / steps);
  std::printf("peak_ground_penetration_mm,%.3f\n", 1000.0 * double(peakPenetration));
  std::printf("peak_joint_separation_mm,%.3f\n", 1000.0 * double(peakJointError));
  std::printf("final_pelvis_height_m,%.4f\n", double(world.GetTransform(ragdoll.bodies[0]).position.y));
  std::printf("healthy,%s\n", healthy ? "yes" : "no");
  std::printf("final state (body, position m, speed m/s, angular speed rad/s, ground force N):\n");
  std::vector<physics::ContactInfo> contacts;
  for (size_t i = 0; i < ragdoll.bodies.size(); ++i) {
    const physics::BodyId body = ragdoll.bodies[i];
    const glm::vec3 p = world.GetTransform(body).position;
    world.GetGroundContacts(body, contacts);
    float force = 0.0f;
    for (const physics::ContactInfo& c : contacts) force += c.normalForce;
    std::printf("  %-16s (% .3f, % .3f, % .3f)  %.4f  %.4f  %.1f\n", scene.boxes[i].name.c_str(), double(p.x),
                double(p.y), double(p.z), double(glm::length(world.GetLinearVelocity(body))),
                double(glm::length(world.GetAngularVelocity(body))), double(force));
  }
  return healthy ? 0 : 1;
}
