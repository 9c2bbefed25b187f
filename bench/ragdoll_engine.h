// SPDX-License-Identifier: MIT
// One interface over every engine the side-by-side ragdoll benchmark runs (ours and the peers).
//
// Each engine builds scenes::RagdollScene in its own terms and exposes only what the benchmark
// measures the same way for all: box poses (centre of mass = box centre) and box velocities.
// The peers (Bullet, ODE, MuJoCo) exist only when RISE_BENCH_PEERS is on; rise-gen never links them.
#pragma once

#include "scenes/ragdoll_drop.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include <memory>

namespace rise::bench {

struct BoxState {
  glm::vec3 position{0.0f};  // m, world, box centre
  glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};
  glm::vec3 velocity{0.0f};  // m/s, world, of the box centre
};

class RagdollEngine {
 public:
  virtual ~RagdollEngine() = default;
  // Advances one fixed step of the time step the engine was built with.
  virtual void Step() = 0;
  // State of box i (scene order) after the last Step.
  virtual BoxState Box(int box) = 0;
};

#ifdef RISE_BENCH_PEERS
std::unique_ptr<RagdollEngine> MakeBulletRagdoll(const scenes::RagdollScene& scene, float timeStep);
std::unique_ptr<RagdollEngine> MakeOdeRagdoll(const scenes::RagdollScene& scene, float timeStep);
std::unique_ptr<RagdollEngine> MakeMujocoRagdoll(const scenes::RagdollScene& scene, float timeStep);
#endif

}  // namespace rise::bench
