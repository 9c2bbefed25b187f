// SPDX-License-Identifier: MIT
// Drops the shared 15-box ragdoll (scenes/ragdoll_drop) for 5 s at 240 Hz and prints the cost
// per step, the real-time factor and the quality figures of the drop, for the default world
// settings and for scenes::FastDropSettings().
#include <algorithm>
#include <chrono>
#include <cstdarg>
#include <cstdio>
#include <ctime>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <string>
#include <vector>

#include "physics/world.h"
#include "scenes/ragdoll_drop.h"

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

double ThreadSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

struct DropReport {
  std::string row;         // one CSV row of the table
  std::string finalState;  // one line per body after the drop
  bool healthy = true;
};

std::string Format(const char* format, ...) __attribute__((format(printf, 1, 2)));
std::string Format(const char* format, ...) {
  char text[512];
  va_list args;
  va_start(args, format);
  std::vsnprintf(text, sizeof(text), format, args);
  va_end(args);
  return text;
}

// Drops the ragdoll with `settings`: quality measured after every step, then timed runs.
DropReport RunConfiguration(const char* name, const physics::WorldSettings& settings,
                            const scenes::RagdollScene& scene) {
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

  // Timing runs: the same scene from scratch. Thread CPU time is the cost on one core even when
  // other processes share the machine; the median and the best run are printed, and wall time
  // (median) beside them.
  constexpr int kRuns = 7;
  std::vector<double> cpuSeconds;
  std::vector<double> wallSeconds;
  for (int run = 0; run < kRuns; ++run) {
    physics::World timed(settings);
    scenes::BuildRagdollDrop(scene, timed);
    const double cpuStart = ThreadSeconds();
    const auto wallStart = std::chrono::steady_clock::now();
    for (int i = 0; i < steps; ++i) timed.Step();
    const std::chrono::duration<double> wall = std::chrono::steady_clock::now() - wallStart;
    cpuSeconds.push_back(ThreadSeconds() - cpuStart);
    wallSeconds.push_back(wall.count());
  }
  std::sort(cpuSeconds.begin(), cpuSeconds.end());
  std::sort(wallSeconds.begin(), wallSeconds.end());
  const double medianCpu = cpuSeconds[kRuns / 2];
  const double simulated = double(steps) * double(settings.timeStep);

  DropReport report;
  report.healthy = healthy;
  report.row =
      Format("%s,%d,%d,%.2f,%.0f,%.2f,%.2f,%.3f,%.3f,%.4f,%s\n", name, settings.substepCount, settings.solveIterations,
             1e6 * medianCpu / steps, simulated / medianCpu, 1e6 * cpuSeconds[0] / steps,
             1e6 * wallSeconds[kRuns / 2] / steps, 1000.0 * double(peakPenetration), 1000.0 * double(peakJointError),
             double(world.GetTransform(ragdoll.bodies[0]).position.y), healthy ? "yes" : "no");
  report.finalState =
      Format("final state of %s (body, position m, speed m/s, angular speed rad/s, ground force N):\n", name);
  std::vector<physics::ContactInfo> contacts;
  for (size_t i = 0; i < ragdoll.bodies.size(); ++i) {
    const physics::BodyId body = ragdoll.bodies[i];
    const glm::vec3 p = world.GetTransform(body).position;
    world.GetGroundContacts(body, contacts);
    float force = 0.0f;
    for (const physics::ContactInfo& c : contacts) force += c.normalForce;
    report.finalState +=
        Format("  %-16s (% .3f, % .3f, % .3f)  %.4f  %.4f  %.1f\n", scene.boxes[i].name.c_str(), double(p.x),
               double(p.y), double(p.z), double(glm::length(world.GetLinearVelocity(body))),
               double(glm::length(world.GetAngularVelocity(body))), double(force));
  }
  return report;
}

}  // namespace

int main() {
  const scenes::RagdollScene scene = scenes::MakeRagdollDropScene();
  const physics::WorldSettings defaults;
  std::printf("ragdoll drop: %zu boxes, %zu joints, %.1f s at %.0f Hz, 7 timed runs (median and best)\n",
              scene.boxes.size(), scene.joints.size(), double(scene.simulatedSeconds),
              double(1.0f / defaults.timeStep));
  std::printf(
      "configuration,substeps,solves,us_per_step,real_time_factor,best_us_per_step,wall_us_per_step,"
      "peak_ground_penetration_mm,peak_joint_separation_mm,final_pelvis_height_m,healthy\n");
  const DropReport reports[] = {RunConfiguration("default_sequential_joints", defaults, scene),
                                RunConfiguration("fast_direct_joints", scenes::FastDropSettings(), scene)};
  bool healthy = true;
  for (const DropReport& report : reports) {
    std::fputs(report.row.c_str(), stdout);
    healthy = healthy && report.healthy;
  }
  for (const DropReport& report : reports) std::fputs(report.finalState.c_str(), stdout);
  return healthy ? 0 : 1;
}
