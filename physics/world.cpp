// SPDX-License-Identifier: MIT
// World: ids, creation, accessors; the step itself is in solver.cpp.
#include "physics/world.h"

#include "base/assert.h"
#include "physics/contact.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <utility>

namespace rise::physics {

World::World(const WorldSettings& settings) {
  state_.settings = settings;
  // The static side of ground contacts and world joints: never moves, never accelerates.
  state_.staticBody.invMass = 0.0f;
  state_.staticBody.invInertiaWorld = glm::mat3(0.0f);
}

BodyId World::CreateBody(const BodyDef& def) {
  state_.bodies.push_back(MakeBody(def));
  return BodyId{int32_t(state_.bodies.size()) - 1};
}

StaticShapeId World::AddStaticPlane(const PlaneShape& plane, float friction) {
  RISE_ASSERT_MSG(std::abs(glm::length(plane.normal) - 1.0f) < 1e-3f, "plane normal must be unit length");
  StaticShape shape;
  shape.type = StaticShapeType::kPlane;
  shape.plane = plane;
  shape.friction = friction;
  state_.statics.push_back(shape);
  return StaticShapeId{int32_t(state_.statics.size()) - 1};
}

StaticShapeId World::AddStaticBox(const BoxShape& box, const Transform& transform, float friction) {
  StaticShape shape;
  shape.type = StaticShapeType::kBox;
  shape.box = box;
  shape.transform = transform;
  shape.friction = friction;
  state_.statics.push_back(shape);
  return StaticShapeId{int32_t(state_.statics.size()) - 1};
}

void World::SetStaticFilter(StaticShapeId shape, uint32_t categoryBits, uint32_t maskBits) {
  RISE_ASSERT(shape.index >= 0 && shape.index < int32_t(state_.statics.size()));
  state_.statics[shape.index].categoryBits = categoryBits;
  state_.statics[shape.index].maskBits = maskBits;
}

JointId World::CreateJoint(const JointDef& def) {
  RISE_ASSERT_MSG(def.bodyB.IsValid(), "a joint's body B must be a body");
  RISE_ASSERT_MSG(def.bodyA != def.bodyB, "a joint needs two different bodies");
  const Body& a = def.bodyA.IsValid() ? BodyAt(def.bodyA) : state_.staticBody;
  state_.joints.push_back(MakeJoint(def, a, BodyAt(def.bodyB)));
  if (def.bodyA.IsValid()) {
    const uint64_t key = BodyPairKey(std::min(def.bodyA.index, def.bodyB.index), std::max(def.bodyA.index, def.bodyB.index));
    const auto it = std::lower_bound(state_.joinedPairs.begin(), state_.joinedPairs.end(), key);
    if (it == state_.joinedPairs.end() || *it != key) state_.joinedPairs.insert(it, key);
  }
  return JointId{int32_t(state_.joints.size()) - 1};
}

StepStatus World::Step() {
  RISE_ASSERT_MSG(state_.settings.timeStep > 0.0f && state_.settings.substepCount > 0, "invalid step settings");
  time_ += double(state_.settings.timeStep);
  return physics::Step(state_);
}

const Body& World::BodyAt(BodyId body) const {
  RISE_ASSERT_MSG(body.index >= 0 && body.index < int32_t(state_.bodies.size()), "invalid body id");
  return state_.bodies[body.index];
}

Body& World::BodyAt(BodyId body) {
  RISE_ASSERT_MSG(body.index >= 0 && body.index < int32_t(state_.bodies.size()), "invalid body id");
  return state_.bodies[body.index];
}

const Joint& World::JointAt(JointId joint) const {
  RISE_ASSERT_MSG(joint.index >= 0 && joint.index < int32_t(state_.joints.size()), "invalid joint id");
  return state_.joints[joint.index];
}

Joint& World::JointAt(JointId joint) {
  RISE_ASSERT_MSG(joint.index >= 0 && joint.index < int32_t(state_.joints.size()), "invalid joint id");
  return state_.joints[joint.index];
}

const Transform& World::GetTransform(BodyId body) const { return BodyAt(body).transform; }
glm::vec3 World::GetLinearVelocity(BodyId body) const { return BodyAt(body).linearVelocity; }
glm::vec3 World::GetAngularVelocity(BodyId body) const { return BodyAt(body).angularVelocity; }
float World::GetMass(BodyId body) const { return BodyAt(body).mass; }
const BoxShape& World::GetBox(BodyId body) const { return BodyAt(body).box; }

void World::SetTransform(BodyId body, const Transform& transform) {
  Body& b = BodyAt(body);
  b.transform.position = transform.position;
  b.transform.rotation = glm::normalize(transform.rotation);
  UpdateWorldInertia(b);
  for (Joint& joint : state_.joints) {
    if (joint.bodyA == body.index || joint.bodyB == body.index) joint.rowsCurrent = false;
  }
}

void World::SetLinearVelocity(BodyId body, const glm::vec3& velocity) { BodyAt(body).linearVelocity = velocity; }
void World::SetAngularVelocity(BodyId body, const glm::vec3& velocity) { BodyAt(body).angularVelocity = velocity; }

void World::ApplyForce(BodyId body, const glm::vec3& force, const glm::vec3& worldPoint) {
  Body& b = BodyAt(body);
  b.force += force;
  b.torque += glm::cross(worldPoint - b.transform.position, force);
}

void World::ApplyTorque(BodyId body, const glm::vec3& torque) { BodyAt(body).torque += torque; }

double World::TotalEnergy() const {
  double energy = 0.0;
  for (const Body& body : state_.bodies) {
    const glm::vec3 v = body.linearVelocity;
    const glm::vec3 wLocal = glm::conjugate(body.transform.rotation) * body.angularVelocity;
    energy += 0.5 * double(body.mass) * double(glm::dot(v, v));
    energy += 0.5 * double(glm::dot(wLocal, body.inertiaLocal * wLocal));
    energy -= double(body.mass) * double(glm::dot(state_.settings.gravity, body.transform.position));
  }
  return energy;
}

glm::quat World::GetJointRelativeRotation(JointId joint) const {
  const Joint& j = JointAt(joint);
  const Body& a = j.bodyA >= 0 ? state_.bodies[j.bodyA] : state_.staticBody;
  return RelativeRotation(j, a, state_.bodies[j.bodyB]);
}

glm::vec3 World::GetJointAnchor(JointId joint) const {
  const Joint& j = JointAt(joint);
  const Body& b = state_.bodies[j.bodyB];
  return b.transform.position + b.transform.rotation * j.localAnchorB;
}

float World::GetJointAnchorSeparation(JointId joint) const {
  const Joint& j = JointAt(joint);
  const Body& a = j.bodyA >= 0 ? state_.bodies[j.bodyA] : state_.staticBody;
  return AnchorSeparation(j, a, state_.bodies[j.bodyB]);
}

glm::vec3 World::GetMotorTorque(JointId joint) const { return JointAt(joint).motorTorqueWorld; }
const MotorDef& World::GetMotor(JointId joint) const { return JointAt(joint).motor; }
void World::SetMotorEnabled(JointId joint, bool enabled) { JointAt(joint).motor.enabled = enabled; }
void World::SetMotorTarget(JointId joint, const glm::quat& target) { JointAt(joint).motor.target = glm::normalize(target); }

void World::SetMotorGains(JointId joint, float stiffness, float damping, float maxTorque) {
  RISE_ASSERT_MSG(stiffness >= 0.0f && damping >= 0.0f && maxTorque >= 0.0f, "motor gains must be non-negative");
  MotorDef& motor = JointAt(joint).motor;
  motor.stiffness = stiffness;
  motor.damping = damping;
  motor.maxTorque = maxTorque;
}

void World::SetMotorFeedForward(JointId joint, const glm::vec3& worldTorque) {
  JointAt(joint).motor.feedForwardTorque = worldTorque;
}

void World::GetGroundContacts(BodyId body, std::vector<ContactInfo>& out) const { CollectContacts(body, true, out); }
void World::GetContacts(BodyId body, std::vector<ContactInfo>& out) const { CollectContacts(body, false, out); }

void World::CollectContacts(BodyId body, bool staticOnly, std::vector<ContactInfo>& out) const {
  BodyAt(body);  // validates the id
  out.clear();
  const float invH = float(state_.settings.substepCount) / state_.settings.timeStep;
  for (const Contact& contact : state_.contacts) {
    const bool isB = contact.bodyB == body.index;
    const bool isA = contact.bodyA == body.index;
    if (!isA && !isB) continue;
    if (staticOnly && contact.bodyA >= 0) continue;
    for (int i = 0; i < contact.pointCount; ++i) {
      const ContactPoint& cp = contact.points[i];
      ContactInfo info;
      info.point = cp.point;
      info.normal = isB ? contact.normal : -contact.normal;
      info.normalForce = cp.normalImpulse * invH;
      info.separation = cp.separation;
      info.otherBody = BodyId{isB ? contact.bodyA : contact.bodyB};
      info.staticShape = StaticShapeId{contact.staticShape};
      out.push_back(info);
    }
  }
}

}  // namespace rise::physics
