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

Aabb BoxAabb(const BoxShape& box, const Transform& transform, float margin) {
  const glm::mat3 r = glm::mat3_cast(transform.rotation);
  const glm::vec3 h = box.halfExtents;
  const glm::vec3 extent = glm::abs(r[0]) * h.x + glm::abs(r[1]) * h.y + glm::abs(r[2]) * h.z + glm::vec3(margin);
  return Aabb{transform.position - extent, transform.position + extent};
}

bool Overlap(const Aabb& a, const Aabb& b) {
  return a.min.x <= b.max.x && b.min.x <= a.max.x && a.min.y <= b.max.y && b.min.y <= a.max.y &&
         a.min.z <= b.max.z && b.min.z <= a.max.z;
}

bool FiltersPass(uint32_t categoryA, uint32_t maskA, uint32_t categoryB, uint32_t maskB) {
  return (categoryA & maskB) != 0u && (categoryB & maskA) != 0u;
}

// The plane's half space test for the box's deepest corner, before building a manifold.
bool NearPlane(const PlaneShape& plane, const Body& body, float margin) {
  const glm::mat3 r = glm::mat3_cast(body.transform.rotation);
  const glm::vec3 h = body.box.halfExtents;
  const float radius = std::fabs(glm::dot(plane.normal, r[0])) * h.x + std::fabs(glm::dot(plane.normal, r[1])) * h.y +
                       std::fabs(glm::dot(plane.normal, r[2])) * h.z;
  return glm::dot(plane.normal, body.transform.position) - plane.offset - radius < margin;
}

void TangentBasis(const glm::vec3& n, glm::vec3& t1, glm::vec3& t2) {
  // A fixed function of the normal, so a resting contact keeps its friction axes across steps.
  t1 = std::fabs(n.x) >= 0.57735f ? glm::vec3(n.y, -n.x, 0.0f) : glm::vec3(0.0f, n.z, -n.y);
  t1 = glm::normalize(t1);
  t2 = glm::cross(n, t1);
}

// `contact` is freshly value-initialised (emplace_back), so its points' impulses start at zero.
void InitContact(Contact& contact, const Manifold& manifold) {
  contact.normal = manifold.normal;
  TangentBasis(manifold.normal, contact.tangent[0], contact.tangent[1]);
  contact.pointCount = manifold.pointCount;
  for (int i = 0; i < manifold.pointCount; ++i) {
    const ManifoldPoint& mp = manifold.points[i];
    ContactPoint& cp = contact.points[i];
    cp.point = mp.point;
    cp.separation = mp.separation;
    cp.id = mp.id;
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

Manifold CollideStatic(const StaticShape& shape, const Body& body, float speculativeDistance) {
  switch (shape.type) {
    case StaticShapeType::kPlane:
      return CollidePlaneBox(shape.plane, body.box, body.transform, speculativeDistance);
    case StaticShapeType::kBox:
      return CollideBoxes(shape.box, shape.transform, body.box, body.transform, speculativeDistance);
  }
  return Manifold{};
}

bool StaticNear(const StaticShape& shape, const Body& body, const Aabb& bodyBox, float margin) {
  switch (shape.type) {
    case StaticShapeType::kPlane:
      return NearPlane(shape.plane, body, margin);
    case StaticShapeType::kBox:
      return Overlap(BoxAabb(shape.box, shape.transform, 0.0f), bodyBox);
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
  std::vector<Contact>& fresh = scratch.contacts;
  fresh.clear();

  const int bodyCount = int(bodies.size());
  std::vector<Aabb>& bounds = scratch.bodyBounds;
  bounds.resize(bodies.size());
  for (int b = 0; b < bodyCount; ++b) bounds[b] = BoxAabb(bodies[b].box, bodies[b].transform, 0.5f * margin);

  for (int s = 0; s < int(statics.size()); ++s) {
    const StaticShape& shape = statics[s];
    for (int b = 0; b < bodyCount; ++b) {
      const Body& body = bodies[b];
      if (!FiltersPass(shape.categoryBits, shape.maskBits, body.categoryBits, body.maskBits)) continue;
      if (!StaticNear(shape, body, bounds[b], margin)) continue;
      const Manifold manifold = CollideStatic(shape, body, margin);
      if (manifold.pointCount == 0) continue;
      Contact& contact = fresh.emplace_back();
      contact.key = (uint64_t(uint32_t(s)) << 31) | uint64_t(uint32_t(b));
      contact.bodyA = -1;
      contact.bodyB = b;
      contact.staticShape = s;
      contact.friction = MixFriction(shape.friction, body.friction);
      InitContact(contact, manifold);
    }
  }

  for (int i = 0; i < bodyCount; ++i) {
    for (int j = i + 1; j < bodyCount; ++j) {
      const Body& a = bodies[i];
      const Body& b = bodies[j];
      if (!FiltersPass(a.categoryBits, a.maskBits, b.categoryBits, b.maskBits)) continue;
      if (!Overlap(bounds[i], bounds[j])) continue;
      const uint64_t key = BodyPairKey(i, j);
      if (std::binary_search(joinedPairs.begin(), joinedPairs.end(), key)) continue;
      const Manifold manifold = CollideBoxes(a.box, a.transform, b.box, b.transform, margin);
      if (manifold.pointCount == 0) continue;
      Contact& contact = fresh.emplace_back();
      contact.key = key;
      contact.bodyA = i;
      contact.bodyB = j;
      contact.friction = MixFriction(a.friction, b.friction);
      InitContact(contact, manifold);
    }
  }

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
