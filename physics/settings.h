// SPDX-License-Identifier: MIT
// World tunables: time step, sub-steps, constraint softness and health limits, with units.
#pragma once

#include <glm/vec3.hpp>

#include <cstdint>

namespace rise::physics {

// How the joints' point parts (the three rows that keep the two anchors together) are solved.
enum class JointSolver : uint8_t {
  // One sequential-impulse pass per joint per solve, like every other row (joint.cpp).
  kSequentialImpulse,
  // One exact, linear-time solve of all tree-structured point parts together (Baraff 1996,
  // joint_tree.cpp) at the end of the first and the last biased pass of a sub-step and of every
  // relax pass (solver.cpp); a joint that closes a loop keeps the sequential pass.
  kDirectTree,
};

// Everything here is read when a step starts, so changing a value between steps is allowed.
// The defaults are the ones the 15-box ragdoll (scenes/ragdoll_drop) was tuned with: lying with
// hands and feet on the ground it comes to rest without jitter and its joints stay closed.
struct WorldSettings {
  glm::vec3 gravity{0.0f, -9.81f, 0.0f};  // m/s^2

  // One World::Step advances this much time, s. Fixed so every run takes the same steps.
  float timeStep = 1.0f / 240.0f;

  // Sub-steps per step (Box2D v3 soft step). Each sub-step integrates, warm starts, solves and
  // relaxes once; several cheap sub-steps converge better than many iterations on one big step.
  int substepCount = 4;

  // Extra passes per sub-step: the biased solve (removes overlap and joint drift softly) and the
  // unbiased relax (removes the velocity the bias added, so position correction adds no energy).
  int solveIterations = 1;
  int relaxIterations = 1;

  // Contact softness: a damped spring that pushes overlapping boxes apart. The frequency is capped
  // at a quarter of the sub-step rate inside the solver, so a coarse step stays stable.
  float contactHertz = 30.0f;        // Hz
  float contactDampingRatio = 10.0f;  // over-damped: overlap is removed without bounce
  float contactPushMaxSpeed = 3.0f;   // m/s; deep overlap is pushed out no faster than this
  // Hard contacts: what a soft contact cannot hold. A soft row is only as stiff as the effective
  // mass at its own point, so a 0.3 kg hand under a landing 100 kg trunk, or a limb stopped by
  // the ground while the joints above it are still falling, sank 2-4.4 cm below the ground in
  // bench/stress_runner (51 of 1000 drops). A point on static geometry is hard while it is past
  // half the rigid depth and its present velocity would take it past the rigid depth within one
  // step, or while it closes faster than the impact speed. A hard point's row is rigid (it keeps
  // the soft push-out speed); its contact is solved once more after the body pairs, so the
  // ground has the last word; and the pass solves joints (with rigid rows) and contacts
  // hardContactIterations more times. Resting and crawling contacts stay under 7.5 mm deep and
  // 3 m/s (samples/*.json), so their clips are unchanged byte for byte; a landing like the 1 m
  // ragdoll drop's (4.4 m/s) does take these paths.
  float contactRigidDepth = 0.008f;  // m
  float contactImpactSpeed = 4.0f;   // m/s
  int hardContactIterations = 2;

  // Joint softness for the point, axis-lock and limit parts of every joint. A soft joint under a
  // load a (m/s^2 or rad/s^2 of the lighter side) settles at an error of a / (2 pi f)^2, so joints
  // are as stiff as the sub-step resolves (the solver caps f at a quarter of the sub-step rate).
  float jointHertz = 240.0f;        // Hz
  float jointDampingRatio = 5.0f;   // dimensionless

  // The default keeps every result bit-identical to the engine the controller was tuned on.
  JointSolver jointSolver = JointSolver::kSequentialImpulse;
  // kDirectTree only: the fraction of the anchors' separation the biased solve removes per
  // sub-step (dimensionless, 0..1). The exact solve is stable at any value and the relax pass
  // takes the correcting velocity back out, so this sets only how fast drift closes.
  float jointTreeErrorReduction = 0.5f;

  // Contacts are created while the surfaces are closer than this, so a fast body is stopped
  // before it passes into the ground (speculative contacts), m. Against a plane a box's band
  // widens to the distance its fastest-closing vertex travels in one step when that is more
  // (12 m/s is 5 cm a step at 240 Hz), so no vertex passes the plane between two Collide stages.
  float speculativeDistance = 0.02f;

  // A contact point keeps its warm-start impulse into the next step while it moved less than this, m.
  float warmStartMatchDistance = 0.01f;

  // Health limits: a body faster than these is reported as exploded (World::Step's status).
  float maxHealthyLinearSpeed = 100.0f;   // m/s
  float maxHealthyAngularSpeed = 200.0f;  // rad/s

  bool enableWarmStarting = true;
};

}  // namespace rise::physics
