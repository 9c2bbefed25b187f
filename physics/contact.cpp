// SPDX-License-Identifier: MIT
// The Collide stage and contact persistence.
//
// Broad phase: with ~15 bodies an all-pairs bounding-box test is cheaper than any tree, and its
// fixed loop order (statics x bodies, then bodies i < j) makes the contact list come out sorted
// by key, so matching last step's contacts is one merge walk and the solver order is reproducible.
#include "physics/contact.h"

#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>

#include <algorithm>
#include <cmath>

namespace rise::physics {

namespace {

constexpr uint64_t kBodyPairFlag = uint64_t{1} << 63;

Aabb BoxAabb(const OrientedBox& box, float margin) {
  const glm::mat3& r = box.axes;
  const glm::vec3 h = box.half;
  const glm::vec3 extent = glm::abs(r[0]) * h.x + glm::abs(r[1]) * h.y + glm::abs(r[2]) * h.z + glm::vec3(margin);
  return Aabb{box.center - extent, box.center + extent};
}

bool Overlap(const Aabb& a, const Aabb& b) {
  return a.min.x <= b.max.x && b.min.x <= a.max.x && a.min.y <= b.max.y && b.min.y <= a.max.y &&
         a.min.z <= b.max.z && b.min.z <= a.max.z;
}

bool FiltersPass(uint32_t categoryA, uint32_t maskA, uint32_t categoryB, uint32_t maskB) {
  return (categoryA & maskB) != 0u && (categoryB & maskA) != 0u;
}

// The plane's half space test for the box's deepest corner, before building a manifold.
bool NearPlane(const PlaneShape& plane, const OrientedBox& box, float margin) {
  const glm::mat3& r = box.axes;
  const glm::vec3 h = box.half;
  const float radius = std::fabs(glm::dot(plane.normal, r[0])) * h.x + std::fabs(glm::dot(plane.normal, r[1])) * h.y +
                       std::fabs(glm::dot(plane.normal, r[2])) * h.z;
  return glm::dot(plane.normal, box.center) - plane.offset - radius < margin;
}

struct TangentBasis {
  glm::vec3 t1, t2;
};

// A fixed function of the normal, so a resting contact keeps its friction axes across steps.
TangentBasis MakeTangentBasis(const glm::vec3& n) {
  TangentBasis basis;
  basis.t1 = std::fabs(n.x) >= 0.57735f ? glm::vec3(n.y, -n.x, 0.0f) : glm::vec3(0.0f, n.z, -n.y);
  basis.t1 = glm::normalize(basis.t1);
  basis.t2 = glm::cross(n, basis.t1);
  return basis;
}

// `contact` may hold a contact of an earlier step (Collide reuses the storage), so every field
// the solver reads is set here; the row data is PrepareContacts' to fill.
void InitContact(Contact& contact, uint64_t key, int32_t bodyA, int32_t bodyB, int32_t staticShape, float friction,
                 const Manifold& manifold, const TangentBasis& tangents) {
  contact.key = key;
  contact.bodyA = bodyA;
  contact.bodyB = bodyB;
  contact.staticShape = staticShape;
  contact.friction = friction;
  contact.normal = manifold.normal;
  contact.tangent[0] = tangents.t1;
  contact.tangent[1] = tangents.t2;
  contact.pointCount = manifold.pointCount;
  for (int i = 0; i < manifold.pointCount; ++i) {
    const ManifoldPoint& mp = manifold.points[i];
    ContactPoint& cp = contact.points[i];
    cp.point = mp.point;
    cp.separation = mp.separation;
    cp.id = mp.id;
    cp.normalImpulse = 0.0f;
    cp.tangentImpulse[0] = cp.tangentImpulse[1] = 0.0f;
  }
}

void CopyMatchingImpulses(Contact& fresh, const Contact& old, float maxDistanceSquared) {
  for (int i = 0; i < fresh.pointCount; ++i) {
    ContactPoint& cp = fresh.points[i];
    for (int j = 0; j < old.pointCount; ++j) {
      const ContactPoint& op = old.points[j];
      const glm::vec3 d = cp.point - op.point;
      if (op.id == cp.id && glm::dot(d, d) < maxDistanceSquared) {
        cp.normalImpulse = op.normalImpulse;
        cp.tangentImpulse[0] = op.tangentImpulse[0];
        cp.tangentImpulse[1] = op.tangentImpulse[1];
        break;
      }
    }
  }
}

// How far the box's vertex closing fastest on the plane travels toward it in one step: the
// vertex velocities v + w x r along -n, at most -n.v + sum_i h_i |a_i . (n x w)| (r runs over
// +-h_i a_i), plus what gravity adds within the step; m, >= 0.
float PlaneReach(const PlaneShape& plane, const OrientedBox& box, const Body& body, const glm::vec3& gravity,
                 float timeStep) {
  const glm::vec3& n = plane.normal;
  const glm::vec3 spin = glm::cross(n, body.angularVelocity);
  const float closing = -glm::dot(n, body.linearVelocity) + box.half.x * std::fabs(glm::dot(box.axes[0], spin)) +
                        box.half.y * std::fabs(glm::dot(box.axes[1], spin)) +
                        box.half.z * std::fabs(glm::dot(box.axes[2], spin)) +
                        std::max(-glm::dot(n, gravity), 0.0f) * timeStep;
  return std::max(closing, 0.0f) * timeStep;
}

Manifold CollideStatic(const StaticShape& shape, const OrientedBox& box, float speculativeDistance, float planeReach) {
  switch (shape.type) {
    case StaticShapeType::kPlane:
      return CollidePlaneBox(shape.plane, box, speculativeDistance, planeReach);
    case StaticShapeType::kBox:
      return CollideBoxes(MakeOrientedBox(shape.box, shape.transform), box, speculativeDistance);
  }
  return Manifold{};
}

bool StaticNear(const StaticShape& shape, const OrientedBox& box, const Aabb& bodyBounds, float margin) {
  switch (shape.type) {
    case StaticShapeType::kPlane:
      return NearPlane(shape.plane, box, margin);
    case StaticShapeType::kBox:
      return Overlap(BoxAabb(MakeOrientedBox(shape.box, shape.transform), 0.0f), bodyBounds);
  }
  return false;
}

}  // namespace

float MixFriction(float frictionA, float frictionB) { return std::sqrt(frictionA * frictionB); }

uint64_t BodyPairKey(int32_t bodyA, int32_t bodyB) {
  return kBodyPairFlag | (uint64_t(uint32_t(bodyA)) << 31) | uint64_t(uint32_t(bodyB));
}

void Collide(const std::vector<Body>& bodies, const std::vector<StaticShape>& statics,
             const std::vector<uint64_t>& joinedPairs, const WorldSettings& settings, std::vector<Contact>& contacts,
             CollideScratch& scratch) {
  const float margin = settings.speculativeDistance;
  // Last step's `fresh` storage is overwritten in place: a new Contact is value-initialised, all
  // 800 bytes of it, which cost more than the narrow phase of a resting box.
  std::vector<Contact>& fresh = scratch.contacts;
  size_t freshCount = 0;
  auto addContact = [&fresh, &freshCount]() -> Contact& {
    if (freshCount == fresh.size()) fresh.emplace_back();
    return fresh[freshCount++];
  };

  const int bodyCount = int(bodies.size());
  std::vector<OrientedBox>& boxes = scratch.bodyBoxes;
  std::vector<Aabb>& bounds = scratch.bodyBounds;
  boxes.resize(bodies.size());
  bounds.resize(bodies.size());
  for (int b = 0; b < bodyCount; ++b) {
    boxes[b] = MakeOrientedBox(bodies[b].box, bodies[b].transform);
    bounds[b] = BoxAabb(boxes[b], 0.5f * margin);
  }

  for (int s = 0; s < int(statics.size()); ++s) {
    const StaticShape& shape = statics[s];
    // Every manifold with a plane has the plane's normal, so its friction axes are found once.
    const bool plane = shape.type == StaticShapeType::kPlane;
    const TangentBasis planeTangents = plane ? MakeTangentBasis(shape.plane.normal) : TangentBasis{};
    for (int b = 0; b < bodyCount; ++b) {
      const Body& body = bodies[b];
      if (!FiltersPass(shape.categoryBits, shape.maskBits, body.categoryBits, body.maskBits)) continue;
      // A vertex closing faster than the speculative distance per step could pass the plane
      // between two Collide stages (12 m/s is 5 cm a step at 240 Hz): the band then reaches as
      // far as that vertex travels. Slower boxes see exactly the fixed distance.
      const float reach = plane ? PlaneReach(shape.plane, boxes[b], body, settings.gravity, settings.timeStep) : 0.0f;
      if (!StaticNear(shape, boxes[b], bounds[b], std::max(margin, reach))) continue;
      const Manifold manifold = CollideStatic(shape, boxes[b], margin, reach);
      if (manifold.pointCount == 0) continue;
      InitContact(addContact(), (uint64_t(uint32_t(s)) << 31) | uint64_t(uint32_t(b)), -1, b, s,
                  MixFriction(shape.friction, body.friction), manifold,
                  plane ? planeTangents : MakeTangentBasis(manifold.normal));
    }
  }

  for (int i = 0; i < bodyCount; ++i) {
    for (int j = i + 1; j < bodyCount; ++j) {
      // The bounds reject most pairs on their first axis; the filter passes nearly every pair.
      if (!Overlap(bounds[i], bounds[j])) continue;
      const Body& a = bodies[i];
      const Body& b = bodies[j];
      if (!FiltersPass(a.categoryBits, a.maskBits, b.categoryBits, b.maskBits)) continue;
      const uint64_t key = BodyPairKey(i, j);
      if (std::binary_search(joinedPairs.begin(), joinedPairs.end(), key)) continue;
      const Manifold manifold = CollideBoxes(boxes[i], boxes[j], margin);
      if (manifold.pointCount == 0) continue;
      InitContact(addContact(), key, i, j, -1, MixFriction(a.friction, b.friction), manifold,
                  MakeTangentBasis(manifold.normal));
    }
  }
  fresh.resize(freshCount);

  if (settings.enableWarmStarting) {
    const float maxDistanceSquared = settings.warmStartMatchDistance * settings.warmStartMatchDistance;
    size_t o = 0;
    for (Contact& contact : fresh) {
      while (o < contacts.size() && contacts[o].key < contact.key) ++o;
      if (o < contacts.size() && contacts[o].key == contact.key) CopyMatchingImpulses(contact, contacts[o], maxDistanceSquared);
    }
  }
  contacts.swap(fresh);
}

}  // namespace rise::physics
