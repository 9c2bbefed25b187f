// SPDX-License-Identifier: MIT
// The public physics API: create bodies, static geometry and joints, step, and read the state.
//
// Typical controller loop (one call per fixed step, settings.timeStep seconds):
//   world.SetMotorTarget(joint, q); world.SetMotorGains(joint, kp, kd, maxTorque); ...
//   const StepStatus status = world.Step();  // stop if !status.Ok()
//   world.GetTransform(body); world.GetJointRelativeRotation(joint); world.GetMotorTorque(joint);
//   world.GetGroundContacts(body, contacts);  // support points and normal forces
// Ids are indices in creation order; nothing is ever destroyed, so an id stays valid for the
// World's lifetime. Passing an id from another World or out of range is a programmer error
// (RISE_ASSERT).
#pragma once

#include "physics/body.h"
#include "physics/joint.h"
#include "physics/settings.h"
#include "physics/solver.h"
#include "physics/static_geometry.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace rise::physics {

// One contact point of a body, as seen from that body.
struct ContactInfo {
  glm::vec3 point{0.0f};     // world, m
  glm::vec3 normal{0.0f};    // unit, world; the direction the contact pushes this body
  float normalForce = 0.0f;  // N, >= 0; average over the last sub-step; 0 for a point that is near
                             // but not pressing (speculative)
  float separation = 0.0f;   // m at the start of the last step, negative when overlapping
  BodyId otherBody = kWorldBody;      // kWorldBody when the other side is static geometry
  StaticShapeId staticShape;          // valid when the other side is static geometry
};

class World {
 public:
  explicit World(const WorldSettings& settings = WorldSettings{});

  // Read at every step; may be changed between steps.
  WorldSettings& Settings() { return state_.settings; }
  const WorldSettings& Settings() const { return state_.settings; }

  BodyId CreateBody(const BodyDef& def);
  // The ground y = 0 is AddStaticPlane({{0, 1, 0}, 0}, friction); any unit normal makes a slope.
  StaticShapeId AddStaticPlane(const PlaneShape& plane, float friction);
  StaticShapeId AddStaticBox(const BoxShape& box, const Transform& transform, float friction);
  // Static geometry filter bits (same rule as BodyDef's).
  void SetStaticFilter(StaticShapeId shape, uint32_t categoryBits, uint32_t maskBits);
  // Bodies joined by a joint stop colliding with each other.
  JointId CreateJoint(const JointDef& def);

  // Advances settings.timeStep seconds and reports the health of the new state.
  StepStatus Step();
  StepStatus LastStatus() const { return state_.status; }
  double Time() const { return time_; }  // s, total simulated

  // Bodies.
  int BodyCount() const { return int(state_.bodies.size()); }
  const Transform& GetTransform(BodyId body) const;
  glm::vec3 GetLinearVelocity(BodyId body) const;   // m/s, world, of the centre of mass
  glm::vec3 GetAngularVelocity(BodyId body) const;  // rad/s, world
  float GetMass(BodyId body) const;                 // kg
  const BoxShape& GetBox(BodyId body) const;
  void SetTransform(BodyId body, const Transform& transform);
  void SetLinearVelocity(BodyId body, const glm::vec3& velocity);
  void SetAngularVelocity(BodyId body, const glm::vec3& velocity);
  // Adds a force (N) at a world point for the next step only (e.g. a push for a disturbance test).
  void ApplyForce(BodyId body, const glm::vec3& force, const glm::vec3& worldPoint);
  // Adds a torque (N m, world) for the next step only.
  void ApplyTorque(BodyId body, const glm::vec3& torque);
  // Kinetic energy of all bodies plus their potential energy in gravity, J.
  double TotalEnergy() const;

  // Joints.
  int JointCount() const { return int(state_.joints.size()); }
  // Rotation of B's joint frame relative to A's; identity at the bind pose.
  glm::quat GetJointRelativeRotation(JointId joint) const;
  // World position of the joint's anchor as carried by body B, m.
  glm::vec3 GetJointAnchor(JointId joint) const;
  // Distance between the joint's two anchor points, m; the joint's position error.
  float GetJointAnchorSeparation(JointId joint) const;
  // Torque the motor applied to body B in the last sub-step (A got the opposite), N m, world.
  glm::vec3 GetMotorTorque(JointId joint) const;
  const MotorDef& GetMotor(JointId joint) const;
  void SetMotorEnabled(JointId joint, bool enabled);
  void SetMotorTarget(JointId joint, const glm::quat& target);
  void SetMotorGains(JointId joint, float stiffness, float damping, float maxTorque);
  void SetMotorFeedForward(JointId joint, const glm::vec3& worldTorque);

  // Contacts found by the last step. Both clear `out` first, so a caller can reuse one vector.
  void GetGroundContacts(BodyId body, std::vector<ContactInfo>& out) const;  // static geometry only
  void GetContacts(BodyId body, std::vector<ContactInfo>& out) const;        // static and bodies

 private:
  const Body& BodyAt(BodyId body) const;
  Body& BodyAt(BodyId body);
  const Joint& JointAt(JointId joint) const;
  Joint& JointAt(JointId joint);
  void CollectContacts(BodyId body, bool staticOnly, std::vector<ContactInfo>& out) const;

  WorldState state_;
  double time_ = 0.0;
};

}  // namespace rise::physics
