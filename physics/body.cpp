// SPDX-License-Identifier: MIT
// Box mass properties and the semi-implicit Euler integrators with an implicit gyroscopic step.
//
// Gyroscopic term: Euler's equation in the body frame is I dw/dt + w x (I w) = tau.
// Integrating w x (I w) explicitly adds energy to a tumbling box (a thin limb spinning about its
// long axis gains speed each step). Following Catto, "Numerical Methods", GDC 2015, we take one
// Newton step of the backward-Euler equation
//   f(w2) = I (w2 - w1) + h w2 x (I w2) = 0,
//   df/dw = I + h ([w]x I - [I w]x),
//   w2 = w1 - (df/dw at w1)^-1 f(w1) = w1 - (df/dw)^-1 (h w1 x I w1),
// which is unconditionally stable and loses a little energy instead of gaining it.
#include "physics/body.h"

#include "base/assert.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>

#include <cmath>

namespace rise::physics {

namespace {

glm::mat3 Skew(const glm::vec3& v) {
  // Column-major: Skew(v) * x == cross(v, x).
  return glm::mat3(0.0f, v.z, -v.y, -v.z, 0.0f, v.x, v.y, -v.x, 0.0f);
}

}  // namespace

glm::vec3 BoxInertia(const glm::vec3& halfExtents, float mass) {
  const glm::vec3 s = halfExtents * halfExtents;
  return (mass / 3.0f) * glm::vec3(s.y + s.z, s.x + s.z, s.x + s.y);
}

Body MakeBody(const BodyDef& def) {
  RISE_ASSERT_MSG(def.mass > 0.0f, "dynamic bodies need a positive mass");
  RISE_ASSERT_MSG(def.box.halfExtents.x > 0.0f && def.box.halfExtents.y > 0.0f && def.box.halfExtents.z > 0.0f,
                  "box half extents must be positive");
  Body body;
  body.transform = def.transform;
  body.transform.rotation = glm::normalize(def.transform.rotation);
  body.linearVelocity = def.linearVelocity;
  body.angularVelocity = def.angularVelocity;
  body.box = def.box;
  body.mass = def.mass;
  body.invMass = 1.0f / def.mass;
  body.inertiaLocal = BoxInertia(def.box.halfExtents, def.mass);
  body.invInertiaLocal = 1.0f / body.inertiaLocal;
  body.friction = def.friction;
  body.linearDamping = def.linearDamping;
  body.angularDamping = def.angularDamping;
  body.categoryBits = def.categoryBits;
  body.maskBits = def.maskBits;
  UpdateWorldInertia(body);
  return body;
}

void UpdateWorldInertia(Body& body) {
  const glm::mat3 r = glm::mat3_cast(body.transform.rotation);
  glm::mat3 scaled = r;
  scaled[0] *= body.invInertiaLocal.x;
  scaled[1] *= body.invInertiaLocal.y;
  scaled[2] *= body.invInertiaLocal.z;
  body.invInertiaWorld = scaled * glm::transpose(r);
}

namespace {

void IntegrateVelocity(Body& body, const glm::vec3& gravity, float h) {
  body.linearVelocity += h * (gravity + body.invMass * body.force);
  // Most bodies carry no applied torque (joint motors act through constraints).
  if (body.torque != glm::vec3(0.0f)) body.angularVelocity += h * (body.invInertiaWorld * body.torque);

  const glm::quat q = body.transform.rotation;
  const glm::vec3 w1 = glm::conjugate(q) * body.angularVelocity;
  const glm::mat3 inertia(glm::vec3(body.inertiaLocal.x, 0.0f, 0.0f), glm::vec3(0.0f, body.inertiaLocal.y, 0.0f),
                          glm::vec3(0.0f, 0.0f, body.inertiaLocal.z));
  const glm::vec3 momentum = body.inertiaLocal * w1;
  const glm::vec3 f = h * glm::cross(w1, momentum);
  // Skew(w1) * inertia with the diagonal inertia: each column of Skew(w1) scaled by its moment.
  glm::mat3 skewTimesInertia = Skew(w1);
  skewTimesInertia[0] *= body.inertiaLocal.x;
  skewTimesInertia[1] *= body.inertiaLocal.y;
  skewTimesInertia[2] *= body.inertiaLocal.z;
  const glm::mat3 jacobian = inertia + h * (skewTimesInertia - Skew(momentum));
  const glm::vec3 w2 = w1 - glm::inverse(jacobian) * f;
  body.angularVelocity = q * w2;

  // Pade approximation of exp(-c h): stable for any damping and step (a factor of exactly 1 without damping).
  if (body.linearDamping != 0.0f) body.linearVelocity *= 1.0f / (1.0f + h * body.linearDamping);
  if (body.angularDamping != 0.0f) body.angularVelocity *= 1.0f / (1.0f + h * body.angularDamping);
}

void IntegratePosition(Body& body, float h) {
  body.transform.position += h * body.linearVelocity;
  body.deltaPosition += h * body.linearVelocity;
  body.deltaRotation += h * body.angularVelocity;
  const glm::vec3 w = body.angularVelocity;
  const glm::quat q = body.transform.rotation;
  const glm::quat dq = glm::quat(0.0f, w.x, w.y, w.z) * q;
  body.transform.rotation = glm::normalize(q + (0.5f * h) * dq);
}

}  // namespace

void IntegrateVelocities(std::vector<Body>& bodies, const glm::vec3& gravity, float h) {
  for (Body& body : bodies) IntegrateVelocity(body, gravity, h);
}

void IntegratePositions(std::vector<Body>& bodies, float h) {
  for (Body& body : bodies) IntegratePosition(body, h);
  // A loop of its own: each body's normalisation and inertia update form one long dependent chain
  // (square root, division, rotation matrix, product), and apart they overlap across bodies.
  for (Body& body : bodies) UpdateWorldInertia(body);
}

}  // namespace rise::physics
