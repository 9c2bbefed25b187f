// SPDX-License-Identifier: MIT
// Narrow phase: plane-box and box-box (SAT + clipping) contact manifolds.
//
// Box numbering used for feature ids (all in the box's own frame):
// - vertex v in 0..7: bit k set means +halfExtents[k] on axis k, else -halfExtents[k];
// - face f in 0..5: 2 * axis + (1 if the face normal is -axis);
// - edge e in 0..11: 4 * axis it runs along + two bits for the signs of the
//   other two axes (bit 0: axis (a+1)%3 positive, bit 1: axis (a+2)%3 positive).
// These depend only on which features touch, never on the pose, which is what
// makes ids stable while a box slides or rocks a little.
//
// Everything runs on fixed-size stack arrays: the functions never allocate.
#include "physics/collide.h"

#include <cmath>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <initializer_list>
#include <utility>

#include "base/assert.h"

namespace rise::physics {
namespace {

// A convex quad clipped by four half-planes gains at most one vertex per plane.
constexpr int kMaxClipPoints = 8;

// Squared sine of the angle below which two edges count as parallel: their cross
// product is then too short to give a trustworthy direction, and a face axis of
// either box already separates whatever such an edge pair would.
constexpr float kParallelSinSq = 1.0e-6f;

// Hysteresis of the axis choice (after Gregorius, "Robust Contact Creation",
// GDC 2015): B's face must beat A's, and an edge must beat both faces, by a
// margin; otherwise contacts flip between near-equal axes from step to step and
// lose their ids and warm-start impulses.
constexpr float kFaceRelTolerance = 0.98f;
constexpr float kEdgeRelTolerance = 0.90f;
constexpr float kAbsTolerance = 0.5e-3f;  // metres

// Box-box id layout. Face contact: bits 0-2 and 3-5 the clip labels `out` and
// `in` (see ClipVertex), 6-8 the incident face, 9-11 the reference face, bit 12
// set when the reference face is B's. Edge-edge: bits 0-3 B's edge, 4-7 A's
// edge, bit 13 set. Plane-box ids are plain vertex numbers (0..7).
constexpr uint32_t kIdReferenceIsB = 1u << 12;
constexpr uint32_t kIdEdgeEdge = 1u << 13;

float SignOf(float x) {
  return x < 0.0f ? -1.0f : 1.0f;
}

// A point under construction: where it is and which box features made it.
struct Candidate {
  glm::vec3 point;
  float separation;
  uint32_t id;
};

// Keeps at most four of `count` candidates: the deepest, then the one farthest
// from it, then the one spanning the largest triangle with those two, then the
// one adding the most area outside that triangle (Gregorius's manifold
// reduction). Area is measured in the contact plane. Kept points stay in their
// input order so a clipped polygon keeps its winding. Ties go to the lower
// index, so the choice is deterministic.
void ReduceToManifold(const Candidate* candidates, int count, const glm::vec3& normal, Manifold& manifold) {
  bool keep[kMaxClipPoints] = {};
  RISE_ASSERT(count <= kMaxClipPoints);
  if (count <= kMaxManifoldPoints) {
    for (int i = 0; i < count; ++i) keep[i] = true;
  } else {
    int deepest = 0;
    for (int i = 1; i < count; ++i) {
      if (candidates[i].separation < candidates[deepest].separation) deepest = i;
    }
    const glm::vec3 p0 = candidates[deepest].point;

    int farthest = -1;
    float bestDistSq = -1.0f;
    for (int i = 0; i < count; ++i) {
      if (i == deepest) continue;
      glm::vec3 d = candidates[i].point - p0;
      d -= normal * glm::dot(d, normal);
      const float distSq = glm::dot(d, d);
      if (distSq > bestDistSq) {
        bestDistSq = distSq;
        farthest = i;
      }
    }
    const glm::vec3 p1 = candidates[farthest].point;

    // Twice the signed area of triangle (a, b, c) seen along the normal.
    auto signedArea = [&normal](const glm::vec3& a, const glm::vec3& b, const glm::vec3& c) {
      return glm::dot(glm::cross(b - a, c - a), normal);
    };
    int third = -1;
    float bestArea = -1.0f;
    for (int i = 0; i < count; ++i) {
      if (i == deepest || i == farthest) continue;
      const float area = std::fabs(signedArea(p0, p1, candidates[i].point));
      if (area > bestArea) {
        bestArea = area;
        third = i;
      }
    }
    const glm::vec3 p2 = candidates[third].point;
    // With this sign, a point outside a triangle edge has a negative oriented area.
    const float orientation = SignOf(signedArea(p0, p1, p2));

    int fourth = -1;
    float bestAdded = 0.0f;
    for (int i = 0; i < count; ++i) {
      if (i == deepest || i == farthest || i == third) continue;
      const glm::vec3 q = candidates[i].point;
      // Twice the area q adds when inserted beyond the triangle edge it lies farthest outside.
      const float outside =
          -std::fmin(std::fmin(orientation * signedArea(p0, p1, q), orientation * signedArea(p1, p2, q)),
                     orientation * signedArea(p2, p0, q));
      if (outside > bestAdded) {
        bestAdded = outside;
        fourth = i;
      }
    }
    keep[deepest] = keep[farthest] = keep[third] = true;
    // A point inside the triangle adds no support area; three points are then enough.
    if (fourth >= 0) keep[fourth] = true;
  }

  manifold.pointCount = 0;
  for (int i = 0; i < count; ++i) {
    if (!keep[i]) continue;
    ManifoldPoint& mp = manifold.points[manifold.pointCount++];
    mp.point = candidates[i].point;
    mp.separation = candidates[i].separation;
    mp.id = candidates[i].id;
  }
}

// The four corners of face `face`, counter-clockwise seen from outside the box.
// Corner k and the edge from corner k to corner k+1 keep their numbers whatever
// the pose, which the clip labels below rely on.
void FaceCorners(const OrientedBox& box, int face, glm::vec3 corners[4]) {
  const int axis = face / 2;
  const float sign = (face & 1) ? -1.0f : 1.0f;
  const int u = (axis + 1) % 3;
  const int w = (axis + 2) % 3;
  // (u, w) signs in counter-clockwise order about +axis (u x w = axis); reversed for -axis.
  static constexpr float kU[4] = {-1.0f, 1.0f, 1.0f, -1.0f};
  static constexpr float kW[4] = {-1.0f, -1.0f, 1.0f, 1.0f};
  const glm::vec3 center = box.center + box.axes[axis] * (sign * box.half[axis]);
  for (int k = 0; k < 4; ++k) {
    const int c = sign > 0.0f ? k : (4 - k) % 4;
    corners[k] = center + box.axes[u] * (kU[c] * box.half[u]) + box.axes[w] * (kW[c] * box.half[w]);
  }
}

// A vertex of the incident polygon during clipping. Every vertex is where two
// lines of the incident face plane meet; a line label is 0..3 for an incident
// face edge and 4..7 for a reference face side plane. `in` labels the polygon
// edge arriving at the vertex, `out` the one leaving it. Together they name the
// point by features alone, so they make its id.
struct ClipVertex {
  glm::vec3 point;
  uint8_t in;
  uint8_t out;
};

// Sutherland-Hodgman step: keeps the part of the polygon with dot(normal, x) <= offset.
int ClipPolygon(const ClipVertex* input, int count, const glm::vec3& normal, float offset, uint8_t label,
                ClipVertex* output) {
  int outCount = 0;
  for (int i = 0; i < count; ++i) {
    const ClipVertex& cur = input[i];
    const ClipVertex& next = input[(i + 1) % count];
    const float dCur = glm::dot(normal, cur.point) - offset;
    const float dNext = glm::dot(normal, next.point) - offset;
    if (dCur <= 0.0f) output[outCount++] = cur;
    // Strict signs: a vertex lying on the plane is kept once, never duplicated.
    if ((dCur < 0.0f && dNext > 0.0f) || (dCur > 0.0f && dNext < 0.0f)) {
      RISE_ASSERT(outCount < kMaxClipPoints);
      const float t = dCur / (dCur - dNext);
      ClipVertex& v = output[outCount++];
      v.point = cur.point + t * (next.point - cur.point);
      const bool leaving = dCur < 0.0f;
      v.in = leaving ? cur.out : label;
      v.out = leaving ? label : cur.out;
    }
  }
  return outCount;
}

// Face contact: clips the face of `incident` most anti-parallel to the
// reference face against that face's four side planes and keeps the points
// closer to the reference face plane than the speculative distance.
void CollideFaces(const OrientedBox& reference, int referenceAxis, float referenceSign, const OrientedBox& incident,
                  bool referenceIsB, float speculativeDistance, Manifold& manifold) {
  const glm::vec3 refNormal = reference.axes[referenceAxis] * referenceSign;
  const int referenceFace = 2 * referenceAxis + (referenceSign < 0.0f ? 1 : 0);

  int incidentAxis = 0;
  float bestDot = 0.0f;
  for (int k = 0; k < 3; ++k) {
    const float d = std::fabs(glm::dot(incident.axes[k], refNormal));
    if (d > bestDot) {
      bestDot = d;
      incidentAxis = k;
    }
  }
  // The incident face looks back at the reference face.
  const bool incidentNegative = glm::dot(incident.axes[incidentAxis], refNormal) > 0.0f;
  const int incidentFace = 2 * incidentAxis + (incidentNegative ? 1 : 0);

  glm::vec3 corners[4];
  FaceCorners(incident, incidentFace, corners);
  ClipVertex polygonA[kMaxClipPoints];
  ClipVertex polygonB[kMaxClipPoints];
  for (int k = 0; k < 4; ++k) {
    polygonA[k] = {corners[k], static_cast<uint8_t>((k + 3) % 4), static_cast<uint8_t>(k)};
  }
  int count = 4;

  ClipVertex* current = polygonA;
  ClipVertex* next = polygonB;
  const int u = (referenceAxis + 1) % 3;
  const int w = (referenceAxis + 2) % 3;
  const int sideAxes[2] = {u, w};
  uint8_t label = 4;
  for (int sideAxis : sideAxes) {
    const glm::vec3 axis = reference.axes[sideAxis];
    const float center = glm::dot(axis, reference.center);
    for (float sign : {1.0f, -1.0f}) {
      count = ClipPolygon(current, count, axis * sign, sign * center + reference.half[sideAxis], label++, next);
      std::swap(current, next);
      if (count == 0) return;
    }
  }

  const float faceOffset = glm::dot(refNormal, reference.center) + reference.half[referenceAxis];
  const uint32_t faceBits = (referenceIsB ? kIdReferenceIsB : 0u) | static_cast<uint32_t>(referenceFace) << 9 |
                            static_cast<uint32_t>(incidentFace) << 6;
  Candidate candidates[kMaxClipPoints];
  int candidateCount = 0;
  for (int i = 0; i < count; ++i) {
    const float separation = glm::dot(refNormal, current[i].point) - faceOffset;
    if (separation >= speculativeDistance) continue;
    candidates[candidateCount++] = {current[i].point - refNormal * (0.5f * separation), separation,
                                    faceBits | static_cast<uint32_t>(current[i].in) << 3 | current[i].out};
  }
  manifold.normal = referenceIsB ? -refNormal : refNormal;
  ReduceToManifold(candidates, candidateCount, refNormal, manifold);
}

// Of the four edges of `box` running along `axis`, the one farthest along
// `direction`: writes its centre and returns its edge number.
int SupportEdge(const OrientedBox& box, int axis, const glm::vec3& direction, glm::vec3& center) {
  const int u = (axis + 1) % 3;
  const int w = (axis + 2) % 3;
  const float su = SignOf(glm::dot(direction, box.axes[u]));
  const float sw = SignOf(glm::dot(direction, box.axes[w]));
  center = box.center + box.axes[u] * (su * box.half[u]) + box.axes[w] * (sw * box.half[w]);
  return 4 * axis + (su > 0.0f ? 1 : 0) + (sw > 0.0f ? 2 : 0);
}

// Closest points of two segments given as centre + t * direction, |t| <= half,
// with unit, non-parallel directions (Ericson, Real-Time Collision Detection 5.1.9).
void ClosestPointsOfSegments(const glm::vec3& centerA, const glm::vec3& dirA, float halfA, const glm::vec3& centerB,
                             const glm::vec3& dirB, float halfB, glm::vec3& onA, glm::vec3& onB) {
  const glm::vec3 r = centerA - centerB;
  const float b = glm::dot(dirA, dirB);
  const float c = glm::dot(dirA, r);
  const float f = glm::dot(dirB, r);
  // |dirA x dirB|^2 rather than 1 - b^2, which cancels for nearly parallel edges;
  // exactly parallel ones never get here.
  const glm::vec3 cross = glm::cross(dirA, dirB);
  const float denom = glm::dot(cross, cross);
  float s = glm::clamp((b * f - c) / denom, -halfA, halfA);
  float t = b * s + f;
  if (t < -halfB || t > halfB) {
    t = glm::clamp(t, -halfB, halfB);
    s = glm::clamp(b * t - c, -halfA, halfA);
  }
  onA = centerA + dirA * s;
  onB = centerB + dirB * t;
}

}  // namespace

OrientedBox MakeOrientedBox(const BoxShape& box, const Transform& transform) {
  RISE_ASSERT(box.halfExtents.x > 0.0f && box.halfExtents.y > 0.0f && box.halfExtents.z > 0.0f);
  // A non-unit quaternion would scale the axes and every distance measured along them.
  RISE_ASSERT(std::fabs(glm::dot(transform.rotation, transform.rotation) - 1.0f) < 1e-3f);
  return {transform.position, glm::mat3_cast(transform.rotation), box.halfExtents};
}

Manifold CollidePlaneBox(const PlaneShape& plane, const OrientedBox& b, float speculativeDistance,
                         float reachDistance) {
  RISE_ASSERT(std::fabs(glm::dot(plane.normal, plane.normal) - 1.0f) < 1e-3f);
  Manifold manifold;
  manifold.normal = plane.normal;

  // Vertex v is ((center +- halfAxis[0]) +- halfAxis[1]) +- halfAxis[2], bit k of v choosing the
  // sign; the vertices share their partial sums.
  const glm::vec3 halfAxis[3] = {b.axes[0] * b.half[0], b.axes[1] * b.half[1], b.axes[2] * b.half[2]};
  glm::vec3 vertices[8];
  for (int x = 0; x < 2; ++x) {
    const glm::vec3 px = x ? b.center + halfAxis[0] : b.center - halfAxis[0];
    for (int y = 0; y < 2; ++y) {
      const glm::vec3 pxy = y ? px + halfAxis[1] : px - halfAxis[1];
      vertices[x | y << 1] = pxy - halfAxis[2];
      vertices[x | y << 1 | 4] = pxy + halfAxis[2];
    }
  }
  // Past the speculative distance (a fast box's wider reach) only the face turned most toward the
  // plane counts: its far face's vertices sit over the same area, and the reduction to four
  // points could keep one of them in place of the vertex that touches first.
  int upAxis = 0;
  int farSide = 0;  // bit upAxis of the far face's vertices
  if (reachDistance > speculativeDistance) {
    float upDot = 0.0f;
    for (int i = 0; i < 3; ++i) {
      const float d = glm::dot(plane.normal, b.axes[i]);
      if (std::fabs(d) > std::fabs(upDot)) {
        upAxis = i;
        upDot = d;
      }
    }
    farSide = upDot > 0.0f ? 1 : 0;
  }
  Candidate candidates[8];
  int count = 0;
  for (int v = 0; v < 8; ++v) {
    const glm::vec3& p = vertices[v];
    const float separation = glm::dot(plane.normal, p) - plane.offset;
    if (separation < speculativeDistance || (separation < reachDistance && ((v >> upAxis) & 1) != farSide)) {
      candidates[count++] = {p - plane.normal * (0.5f * separation), separation, static_cast<uint32_t>(v)};
    }
  }
  ReduceToManifold(candidates, count, plane.normal, manifold);
  return manifold;
}

Manifold CollidePlaneBox(const PlaneShape& plane, const BoxShape& box, const Transform& boxTransform,
                         float speculativeDistance, float reachDistance) {
  return CollidePlaneBox(plane, MakeOrientedBox(box, boxTransform), speculativeDistance, reachDistance);
}

Manifold CollideBoxes(const BoxShape& boxA, const Transform& transformA, const BoxShape& boxB,
                      const Transform& transformB, float speculativeDistance) {
  return CollideBoxes(MakeOrientedBox(boxA, transformA), MakeOrientedBox(boxB, transformB), speculativeDistance);
}

Manifold CollideBoxes(const OrientedBox& a, const OrientedBox& b, float speculativeDistance) {
  Manifold manifold;
  const glm::vec3 d = b.center - a.center;

  // Bounding spheres first: most pairs a broad phase hands over are far apart.
  const float reach = glm::length(a.half) + glm::length(b.half) + speculativeDistance;
  if (glm::dot(d, d) > reach * reach) return manifold;

  // absC[i][j] = |dot(A axis i, B axis j)|: how much of B's axis j projects on A's axis i.
  float absC[3][3];
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) absC[i][j] = std::fabs(glm::dot(a.axes[i], b.axes[j]));
  }

  float faceSepA = -INFINITY;
  int faceAxisA = 0;
  for (int i = 0; i < 3; ++i) {
    const float projected = b.half[0] * absC[i][0] + b.half[1] * absC[i][1] + b.half[2] * absC[i][2];
    const float separation = std::fabs(glm::dot(d, a.axes[i])) - a.half[i] - projected;
    if (separation > speculativeDistance) return manifold;
    if (separation > faceSepA) {
      faceSepA = separation;
      faceAxisA = i;
    }
  }

  float faceSepB = -INFINITY;
  int faceAxisB = 0;
  for (int j = 0; j < 3; ++j) {
    const float projected = a.half[0] * absC[0][j] + a.half[1] * absC[1][j] + a.half[2] * absC[2][j];
    const float separation = std::fabs(glm::dot(d, b.axes[j])) - b.half[j] - projected;
    if (separation > speculativeDistance) return manifold;
    if (separation > faceSepB) {
      faceSepB = separation;
      faceAxisB = j;
    }
  }

  float edgeSep = -INFINITY;
  int edgeAxisA = 0;
  int edgeAxisB = 0;
  glm::vec3 edgeNormal{0.0f};
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      // The length comes from the cross product itself: 1 - c^2 cancels
      // catastrophically in float exactly when the edges are nearly parallel.
      const glm::vec3 cross = glm::cross(a.axes[i], b.axes[j]);
      const float sinSq = glm::dot(cross, cross);
      if (sinSq < kParallelSinSq) continue;
      const glm::vec3 axis = cross / std::sqrt(sinSq);
      float radius = 0.0f;
      for (int k = 0; k < 3; ++k) {
        radius += a.half[k] * std::fabs(glm::dot(axis, a.axes[k])) + b.half[k] * std::fabs(glm::dot(axis, b.axes[k]));
      }
      const float distance = glm::dot(d, axis);
      const float separation = std::fabs(distance) - radius;
      if (separation > speculativeDistance) return manifold;
      if (separation > edgeSep) {
        edgeSep = separation;
        edgeAxisA = i;
        edgeAxisB = j;
        edgeNormal = axis * SignOf(distance);
      }
    }
  }

  const bool useFaceB = faceSepB > kFaceRelTolerance * faceSepA + kAbsTolerance;
  const float faceSep = useFaceB ? faceSepB : faceSepA;
  if (edgeSep > kEdgeRelTolerance * faceSep + kAbsTolerance) {
    glm::vec3 centerA;
    glm::vec3 centerB;
    const int edgeA = SupportEdge(a, edgeAxisA, edgeNormal, centerA);
    const int edgeB = SupportEdge(b, edgeAxisB, -edgeNormal, centerB);
    glm::vec3 onA;
    glm::vec3 onB;
    ClosestPointsOfSegments(centerA, a.axes[edgeAxisA], a.half[edgeAxisA], centerB, b.axes[edgeAxisB],
                            b.half[edgeAxisB], onA, onB);
    const float separation = glm::dot(onB - onA, edgeNormal);
    manifold.normal = edgeNormal;
    if (separation < speculativeDistance) {
      manifold.points[0] = {0.5f * (onA + onB), separation,
                            kIdEdgeEdge | static_cast<uint32_t>(edgeA) << 4 | static_cast<uint32_t>(edgeB)};
      manifold.pointCount = 1;
    }
    return manifold;
  }

  if (useFaceB) {
    // B's face looks towards A.
    CollideFaces(b, faceAxisB, -SignOf(glm::dot(d, b.axes[faceAxisB])), a, true, speculativeDistance, manifold);
  } else {
    CollideFaces(a, faceAxisA, SignOf(glm::dot(d, a.axes[faceAxisA])), b, false, speculativeDistance, manifold);
  }
  return manifold;
}

}  // namespace rise::physics
