// SPDX-License-Identifier: MIT
// Narrow phase: contact manifolds between boxes and static geometry.
//
// Conventions shared by every function here:
// - A manifold's normal is a unit vector pointing from shape A to shape B.
// - A point's separation is the signed distance between the two surfaces along
//   the normal at that point: negative when they overlap, metres.
// - Points are reported while separation < speculativeDistance, so the solver
//   can stop an approaching body before it touches (speculative contacts).
// - Each point carries a feature id built from the features (vertex, edge,
//   face) that made it, so the same physical point keeps its id from step to
//   step and its impulse can warm-start the next step. Ids within one manifold
//   are distinct.
#pragma once

#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include <cstdint>

namespace rise::physics {

struct Transform {
  glm::vec3 position{0.0f};
  glm::quat rotation{1.0f, 0.0f, 0.0f, 0.0f};
};

struct BoxShape {
  glm::vec3 halfExtents{0.5f};  // metres, in the body frame
};

// The set of points x with dot(normal, x) = offset; solid below (against the normal).
struct PlaneShape {
  glm::vec3 normal{0.0f, 1.0f, 0.0f};
  float offset = 0.0f;
};

constexpr int kMaxManifoldPoints = 4;

struct ManifoldPoint {
  glm::vec3 point{0.0f};   // world position, midway between the two surfaces
  float separation = 0.0f; // metres, negative when overlapping
  uint32_t id = 0;         // feature id, stable while the same features touch
};

struct Manifold {
  glm::vec3 normal{0.0f, 1.0f, 0.0f};  // from A to B
  ManifoldPoint points[kMaxManifoldPoints];
  int pointCount = 0;
};

// A box as the narrow phase measures it. The Collide stage builds one per body per step and
// hands it to every test of that body, so the rotation matrix is computed once, not per pair.
struct OrientedBox {
  glm::vec3 center{0.0f};
  glm::mat3 axes{1.0f};  // columns are the box axes in world space
  glm::vec3 half{0.5f};
};

OrientedBox MakeOrientedBox(const BoxShape& box, const Transform& transform);

// A = the static plane, B = the box; the normal is the plane normal. A `reachDistance` above
// speculativeDistance widens the speculative band for a box closing on the plane fast: vertices
// of the box's face turned toward the plane count while closer than it, the far face's vertices
// only while closer than speculativeDistance (the default 0 widens nothing).
Manifold CollidePlaneBox(const PlaneShape& plane, const OrientedBox& box, float speculativeDistance,
                         float reachDistance = 0.0f);
Manifold CollidePlaneBox(const PlaneShape& plane, const BoxShape& box, const Transform& boxTransform,
                         float speculativeDistance, float reachDistance = 0.0f);

// Separating-axis test over the 15 box axes, then clipping of the incident face
// against the reference face's side planes (Sutherland-Hodgman), reduced to at
// most four points that keep the deepest point and the widest area; edge-edge
// contacts give one point.
Manifold CollideBoxes(const OrientedBox& a, const OrientedBox& b, float speculativeDistance);
Manifold CollideBoxes(const BoxShape& boxA, const Transform& transformA, const BoxShape& boxB,
                      const Transform& transformB, float speculativeDistance);

}  // namespace rise::physics
