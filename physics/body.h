// SPDX-License-Identifier: MIT
// Rigid bodies: definition, mass and box inertia, and the per-sub-step integrators.
#pragma once

#include "physics/collide.h"

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace rise::physics {

// Index of a body in its World; kWorldBody stands for the static world in JointDef::bodyA.
struct BodyId {
  int32_t index = -1;
  bool IsValid() const { return index >= 0; }
  friend bool operator==(BodyId a, BodyId b) { return a.index == b.index; }
  friend bool operator!=(BodyId a, BodyId b) { return a.index != b.index; }
};
inline constexpr BodyId kWorldBody{-1};

// How a dynamic body is created. Every body is one box centred on its centre of mass;
// static geometry is added to the World separately (World::AddStaticPlane / AddStaticBox).
struct BodyDef {
  BoxShape box;
  float mass = 1.0f;      // kg, > 0
  Transform transform;    // world pose of the centre of mass
  glm::vec3 linearVelocity{0.0f};   // m/s, world
  glm::vec3 angularVelocity{0.0f};  // rad/s, world
  float friction = 0.6f;  // Coulomb coefficient; mixed with the other surface by geometric mean

  // Collision filter: bodies a and b collide when (a.category & b.mask) and (b.category & a.mask)
  // are both non-zero. Bodies joined by a joint never collide with each other.
  uint32_t categoryBits = 0x1u;
  uint32_t maskBits = 0xFFFFFFFFu;

  // Velocity damping, 1/s. Zero keeps free motion exact; a ragdoll may use a little.
  float linearDamping = 0.0f;
  float angularDamping = 0.0f;
};

// Principal moments of inertia of a solid box about its centre, kg m^2:
// I_x = m (h_y^2 + h_z^2) / 3 with h the half extents (= m (b^2 + c^2) / 12 with full sizes).
glm::vec3 BoxInertia(const glm::vec3& halfExtents, float mass);

// The simulated state of one dynamic body. Owned by the World; read through World accessors.
struct Body {
  Transform transform;
  glm::vec3 linearVelocity{0.0f};
  glm::vec3 angularVelocity{0.0f};

  // External force and torque accumulated by World::ApplyForce, applied during the next step.
  glm::vec3 force{0.0f};
  glm::vec3 torque{0.0f};

  BoxShape box;
  float mass = 0.0f;
  float invMass = 0.0f;
  glm::vec3 inertiaLocal{0.0f};     // principal moments in the body frame
  glm::vec3 invInertiaLocal{0.0f};
  glm::mat3 invInertiaWorld{0.0f};  // R diag(1/I) R^T, refreshed whenever the rotation changes

  // Motion since the step began (Box2D v3's body deltas): the contact solver measures current
  // separations from them without re-running the narrow phase. deltaRotation is the integrated
  // rotation vector, exact to first order over one step's small rotation.
  glm::vec3 deltaPosition{0.0f};
  glm::vec3 deltaRotation{0.0f};

  float friction = 0.6f;
  float linearDamping = 0.0f;
  float angularDamping = 0.0f;
  uint32_t categoryBits = 0x1u;
  uint32_t maskBits = 0xFFFFFFFFu;
};

Body MakeBody(const BodyDef& def);

// Recomputes invInertiaWorld from the current rotation.
void UpdateWorldInertia(Body& body);

// Semi-implicit Euler velocity update of every body over h seconds: gravity, the accumulated
// force and torque, damping, and the gyroscopic term solved implicitly (see body.cpp).
void IntegrateVelocities(std::vector<Body>& bodies, const glm::vec3& gravity, float h);

// Position and orientation update of every body over h seconds with the new velocities; the
// quaternions are renormalised so rounding never makes them drift away from a rotation.
void IntegratePositions(std::vector<Body>& bodies, float h);

}  // namespace rise::physics
