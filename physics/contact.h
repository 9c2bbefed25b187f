// SPDX-License-Identifier: MIT
// Contacts: the Collide stage (broad phase, narrow phase, filtering) and manifold persistence
// that carries each point's impulses into the next step for warm starting.
#pragma once

#include "physics/body.h"
#include "physics/collide.h"
#include "physics/settings.h"
#include "physics/static_geometry.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace rise::physics {

struct ContactPoint {
  glm::vec3 point{0.0f};     // world, at the Collide stage
  float separation = 0.0f;   // m, at the Collide stage, negative when overlapping
  uint32_t id = 0;           // feature id from the narrow phase

  float normalImpulse = 0.0f;        // N s, per sub-step, >= 0
  float tangentImpulse[2] = {};      // N s, per sub-step

  // Row data fixed for one step (PrepareContacts), as Box2D: row 0 is the normal, rows 1 and 2
  // the tangents. crossA/B = r x direction; turnA/B = I^-1 crossA/B, the angular velocity change
  // per unit impulse. Side A's rows are left unset against static geometry, which never moves.
  glm::vec3 crossA[3];
  glm::vec3 crossB[3];
  glm::vec3 turnA[3];
  glm::vec3 turnB[3];
  float mass[3] = {};
};

struct Contact {
  uint64_t key = 0;          // orders contacts deterministically and pairs them across steps
  int32_t bodyA = -1;        // -1 when A is static geometry
  int32_t bodyB = -1;
  int32_t staticShape = -1;  // index of the static shape when bodyA is -1
  glm::vec3 normal{0.0f, 1.0f, 0.0f};  // from A to B
  glm::vec3 tangent[2];
  float friction = 0.0f;
  ContactPoint points[kMaxManifoldPoints];
  int pointCount = 0;
  bool hard = false;  // static contacts: a point was hard in the last solve (WorldSettings)
};

struct Aabb {
  glm::vec3 min{0.0f};
  glm::vec3 max{0.0f};
};

// Storage the Collide stage reuses from step to step, so steady-state steps do not allocate.
struct CollideScratch {
  std::vector<Contact> contacts;
  std::vector<OrientedBox> bodyBoxes;
  std::vector<Aabb> bodyBounds;
};

// Friction of a surface pair: the geometric mean (as Box2D), so either surface can make the
// pair frictionless and two equal surfaces keep their coefficient.
float MixFriction(float frictionA, float frictionB);

// Key of a (bodyA, bodyB) pair used by the joined-pairs filter; bodyA < bodyB.
uint64_t BodyPairKey(int32_t bodyA, int32_t bodyB);

// The Collide stage: finds every touching or nearly touching (speculative) static-body and
// body-body pair in a fixed order, builds its manifold, and copies impulses from `contacts` (last
// step) into matching points (same pair, same feature id, moved less than the match distance).
// `joinedPairs` (sorted BodyPairKeys) lists bodies that must not collide. The result replaces
// `contacts`.
void Collide(const std::vector<Body>& bodies, const std::vector<StaticShape>& statics,
             const std::vector<uint64_t>& joinedPairs, const WorldSettings& settings, std::vector<Contact>& contacts,
             CollideScratch& scratch);

}  // namespace rise::physics
