// SPDX-License-Identifier: MIT
// The simulation step as a list of named stages, and the state it advances.
#pragma once

#include "physics/body.h"
#include "physics/contact.h"
#include "physics/joint.h"
#include "physics/joint_tree.h"
#include "physics/settings.h"
#include "physics/static_geometry.h"

#include <cstdint>
#include <vector>

namespace rise::physics {

// Health of the last step (tier 3 of the error tiers): the caller checks it and stops a bake
// with a clear message instead of writing a broken clip.
enum StepStatusFlags : uint32_t {
  kStepOk = 0u,
  kStepNonFinite = 1u << 0,       // a body position, rotation or velocity became NaN or Inf
  kStepSpeedExceeded = 1u << 1,   // a body moved faster than the settings' health limits
};

struct StepStatus {
  uint32_t flags = kStepOk;
  int32_t firstBadBody = -1;  // the lowest-index body that raised a flag
  bool Ok() const { return flags == kStepOk; }
};

// Everything a World simulates. Bodies and joints are kept in creation order and solved in that
// order, so a ragdoll created root to leaf is solved root to leaf.
struct WorldState {
  WorldSettings settings;
  std::vector<Body> bodies;
  std::vector<Joint> joints;
  JointTree jointTree;                // the joint forest (JointSolver::kDirectTree)
  std::vector<StaticShape> statics;
  std::vector<uint64_t> joinedPairs;  // sorted BodyPairKeys of jointed bodies
  std::vector<Contact> contacts;      // sorted by key
  CollideScratch collideScratch;
  Body staticBody;                    // side A of static contacts and world joints
  StepStatus status;
};

// One fixed step of settings.timeStep:
//   Collide -> PrepareContacts, PrepareJoints ->
//   for each sub-step { IntegrateVelocities -> WarmStart -> Solve(useBias) -> IntegratePositions
//                       -> Relax(no bias) -> StoreJointWarmStarts } -> StoreImpulses (clear forces,
//   check health).
StepStatus Step(WorldState& state);

}  // namespace rise::physics
