// SPDX-License-Identifier: MIT
// Exact linear-time solve of the point parts of tree-structured joints (JointSolver::kDirectTree).
//
// The joints form a forest over the bodies (the static world counts as one node, so two joints
// to the world on one chain close a loop). Each joint of the forest is a link from a parent body
// (nearer the root, or the world) to a child body. A joint that would close a loop is left out
// and keeps its sequential-impulse point part. See joint_tree.cpp for the math.
#pragma once

#include "physics/body.h"
#include "physics/joint.h"

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace rise::physics {

// One joint of the forest with its part of the factorisation.
struct JointTreeLink {
  int32_t joint = -1;
  int32_t parent = -1;  // body index, -1: the static world
  int32_t child = -1;   // body index
  float sign = 1.0f;    // +1 when the child is the joint's body B, -1 when it is body A
  int32_t childSlot = -1;   // index into JointTree::inverses when the child has links below it
  int32_t parentSlot = -1;  // the parent's index into JointTree::inverses, -1 for the world
  // The lever arms r_c, r_p the forest was factorised with, so a solve never needs the joint's
  // A/B sides sorted out again.
  glm::vec3 childLever{0.0f}, parentLever{0.0f};
  // L = D_child^-1 G_child^T, split into its linear and angular 3x3 blocks (the linear block of
  // a leaf child is its inverse mass times 1 and is not stored).
  glm::mat3 lowerLinear{0.0f}, lowerAngular{0.0f};
  glm::mat3 invMass{0.0f};  // S^-1: the inverse of the subtree's effective inverse mass at the joint
  glm::vec3 x{0.0f};        // scratch of the solve
};

// D^-1 of a body that has links below it, kept factorised. D = [[A, B], [B^T, C]] is its mass
// plus the subtree hanging from it, acting on (v, w); with X = A^-1 B and T = (C - B^T X)^-1,
// D^-1 (v, w) = (A^-1 v - X w', w') where w' = T (w - X^T v).
struct JointTreeInverse {
  glm::mat3 linearInverse{0.0f};  // A^-1
  glm::mat3 coupling{0.0f};       // X
  glm::mat3 schurInverse{0.0f};   // T
};

// Bodies with links below them are numbered by "slot"; everything per body that the factorisation
// and the solve keep is stored per slot, as a leaf child needs none of it.
struct JointTree {
  bool active = false;
  int32_t builtJointCount = -1;  // the joint count the forest was built for
  bool factorCurrent = false;    // factorised at the bodies' present poses
  std::vector<JointTreeLink> links;       // root to leaf: every parent link before its children
  std::vector<int32_t> levelStarts;       // links of depth d are [levelStarts[d], levelStarts[d + 1])
  std::vector<int32_t> slotBodies;        // per slot: its body
  std::vector<int32_t> rootSlots;         // slots of root bodies (no link above them)
  std::vector<JointTreeInverse> inverses; // per slot
  // Per slot: D blocks while factorising, velocity changes while solving.
  std::vector<glm::mat3> scratchA, scratchB, scratchC;
  std::vector<glm::vec3> deltaV, deltaW;
};

// Builds the forest of `joints` (creation order decides which joint of a loop stays out) and sets
// every joint's pointInTree; with active false it only clears them.
void BuildJointTree(JointTree& tree, std::vector<Joint>& joints, int bodyCount, bool active);

// Factorises the forest at the bodies' present poses and the joints' present lever arms (the
// solver does this after every position integration, when it refreshes the lever arms).
void FactorJointTree(JointTree& tree, const std::vector<Joint>& joints, const std::vector<Body>& bodies);

// Applies the impulses that make every tree joint's anchor velocity Cdot + biasRate C zero
// (biasRate 0: no bias) and adds them to the joints' linearImpulse. Exact when the lever arms
// are those of the last FactorJointTree.
void SolveJointTree(JointTree& tree, std::vector<Joint>& joints, std::vector<Body>& bodies, const Body& staticBody,
                    float biasRate);

}  // namespace rise::physics
