// SPDX-License-Identifier: MIT
// The 15-box ragdoll drop scene as plain data, shared by the physics tests and the benchmarks.
//
// The data uses only numbers, vectors and quaternions, so a benchmark can build the identical
// scene in another engine (Bullet, ODE, MuJoCo). All positions are world space at the bind pose:
// the humanoid stands at the origin facing +Z, feet on y = 0, 1.75 m tall, 70 kg, left = +X.
// The drop applies `startRotation` about the origin and then lifts the whole body so its lowest
// box corner is `dropHeight` above the ground.
#pragma once

#include "physics/joint.h"
#include "physics/world.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include <string>
#include <vector>

namespace rise::scenes {

struct RagdollBox {
  std::string name;
  glm::vec3 center{0.0f};       // m, bind pose
  glm::vec3 halfExtents{0.1f};  // m, axis-aligned at the bind pose
  float mass = 1.0f;            // kg
};

struct RagdollJoint {
  std::string name;
  int parent = 0;  // index into RagdollScene::boxes
  int child = 0;
  physics::JointType type = physics::JointType::kBall;
  glm::vec3 anchor{0.0f};                   // m, bind pose
  glm::quat frame{1.0f, 0.0f, 0.0f, 0.0f};  // joint frame; x = twist / hinge axis (see physics/joint.h)
  physics::AngleRange twistLimits;          // kBall twist, kHinge angle, rad
  float swingCone = 0.0f;                   // kBall cone half-angle, rad
  physics::AngleRange swingYLimits;         // kUniversal first axis (A's y), rad
  physics::AngleRange swingZLimits;         // kUniversal second axis (B's z), rad
};

struct RagdollScene {
  std::vector<RagdollBox> boxes;    // parents before children, pelvis first
  std::vector<RagdollJoint> joints; // root to leaf
  float friction = 0.8f;            // every box and the ground
  float dropHeight = 1.0f;          // m, lowest box corner above the ground at the start
  glm::quat startRotation{1.0f, 0.0f, 0.0f, 0.0f};  // applied to the bind pose before the drop
  float simulatedSeconds = 5.0f;    // how long the benchmark runs
};

// The 15-box humanoid: pelvis, torso, head, upper arms, forearms, hands, thighs, shins, feet,
// with ball joints at waist and neck, universal joints at hips, shoulders and ankles and hinges
// at elbows, wrists and knees. It starts lying on its back, tilted 20 deg about its long axis
// and 10 deg head-up.
RagdollScene MakeRagdollDropScene();

struct BuiltRagdoll {
  std::vector<physics::BodyId> bodies;    // same order as RagdollScene::boxes
  std::vector<physics::JointId> joints;   // same order as RagdollScene::joints
};

// Adds the ground plane y = 0 and the ragdoll at its start pose to `world`.
BuiltRagdoll BuildRagdollDrop(const RagdollScene& scene, physics::World& world);

// World-space start pose of box i (bind pose rotated and lifted as described above).
physics::Transform StartTransform(const RagdollScene& scene, int box);

// The cheapest world settings measured to meet issue 7's drop targets (peak ground penetration
// <= 10 mm, peak joint separation <= 2 mm): the direct joint-tree solver with 1 sub-step and 3
// biased solves. The benchmarks report it beside the defaults, which rise-gen's biped still uses.
physics::WorldSettings FastDropSettings();

}  // namespace rise::scenes
