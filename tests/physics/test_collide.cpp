// SPDX-License-Identifier: MIT
// Narrow-phase manifolds checked against hand-computed contact geometry.
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtx/quaternion.hpp>
#include <glm/vec2.hpp>
#include <initializer_list>
#include <random>
#include <vector>

#include "physics/collide.h"
#include "test_support.h"

namespace {

using rise::physics::BoxShape;
using rise::physics::CollideBoxes;
using rise::physics::CollidePlaneBox;
using rise::physics::Manifold;
using rise::physics::PlaneShape;
using rise::physics::Transform;

constexpr float kSpeculative = 0.02f;
constexpr float kTol = 1e-5f;

glm::quat AxisAngle(float degrees, const glm::vec3& axis) {
  return glm::angleAxis(glm::radians(degrees), glm::normalize(axis));
}

// Area of the polygon through the manifold points in angular order about their
// centroid, seen along the normal: the contact area when the points are convex.
float PolygonArea(const Manifold& m) {
  glm::vec3 centroid{0.0f};
  for (int i = 0; i < m.pointCount; ++i) centroid += m.points[i].point / static_cast<float>(m.pointCount);
  const glm::vec3 u =
      glm::normalize(glm::cross(m.normal, std::fabs(m.normal.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0)));
  const glm::vec3 v = glm::cross(m.normal, u);
  std::vector<glm::vec2> polygon;
  for (int i = 0; i < m.pointCount; ++i) {
    const glm::vec3 d = m.points[i].point - centroid;
    polygon.push_back({glm::dot(d, u), glm::dot(d, v)});
  }
  std::sort(polygon.begin(), polygon.end(),
            [](const glm::vec2& a, const glm::vec2& b) { return std::atan2(a.y, a.x) < std::atan2(b.y, b.x); });
  float twiceArea = 0.0f;
  for (size_t i = 0; i < polygon.size(); ++i) {
    const glm::vec2 a = polygon[i];
    const glm::vec2 b = polygon[(i + 1) % polygon.size()];
    twiceArea += a.x * b.y - a.y * b.x;
  }
  return 0.5f * std::fabs(twiceArea);
}

// True when the manifold has a point within kTol of p.
bool HasPoint(const Manifold& m, const glm::vec3& p) {
  for (int i = 0; i < m.pointCount; ++i) {
    if (rise::test::Distance(m.points[i].point, p) <= kTol) return true;
  }
  return false;
}

std::vector<uint32_t> Ids(const Manifold& m) {
  std::vector<uint32_t> ids;
  for (int i = 0; i < m.pointCount; ++i) ids.push_back(m.points[i].id);
  return ids;
}

bool IdsDistinct(const Manifold& m) {
  std::vector<uint32_t> ids = Ids(m);
  std::sort(ids.begin(), ids.end());
  return std::adjacent_find(ids.begin(), ids.end()) == ids.end();
}

// The world position of box vertex v (bit k set: + half extent on axis k).
glm::vec3 BoxVertex(const BoxShape& box, const Transform& t, int v) {
  glm::vec3 local;
  for (int k = 0; k < 3; ++k) local[k] = (v >> k & 1) ? box.halfExtents[k] : -box.halfExtents[k];
  return t.position + t.rotation * local;
}

// Distance from p to the solid box (0 inside).
float DistanceToBox(const BoxShape& box, const Transform& t, const glm::vec3& p) {
  const glm::vec3 local = glm::inverse(t.rotation) * (p - t.position);
  return glm::length(glm::max(glm::abs(local) - box.halfExtents, glm::vec3(0.0f)));
}

// For an overlapping point, stepping half the separation back along the normal
// must land on A and half forward on B: the point is midway between the surfaces.
float WorstSurfaceError(const BoxShape& boxA, const Transform& tA, const BoxShape& boxB, const Transform& tB,
                        const Manifold& m) {
  float worst = 0.0f;
  for (int i = 0; i < m.pointCount; ++i) {
    const rise::physics::ManifoldPoint& p = m.points[i];
    if (p.separation >= 0.0f) continue;  // a speculative edge pair may be offset sideways too
    const glm::vec3 onA = p.point - m.normal * (0.5f * p.separation);
    const glm::vec3 onB = p.point + m.normal * (0.5f * p.separation);
    worst = std::max({worst, DistanceToBox(boxA, tA, onA), DistanceToBox(boxB, tB, onB)});
  }
  return worst;
}

}  // namespace

TEST_SUITE("collide") {
  TEST_CASE("plane-box: a box resting flat gives its four bottom corners at the exact depth") {
    const BoxShape box{{0.5f, 0.25f, 0.3f}};
    const Transform t{{0.7f, 0.25f - 0.002f, -1.2f}, {1.0f, 0.0f, 0.0f, 0.0f}};
    const Manifold m = CollidePlaneBox(PlaneShape{}, box, t, kSpeculative);
    REQUIRE(m.pointCount == 4);
    CHECK_VEC3_NEAR(m.normal, glm::vec3(0.0f, 1.0f, 0.0f), kTol);
    std::vector<uint32_t> ids = Ids(m);
    std::sort(ids.begin(), ids.end());
    CHECK(ids == std::vector<uint32_t>{0, 1, 4, 5});  // the vertices with -y
    for (int i = 0; i < 4; ++i) {
      CHECK(m.points[i].separation == doctest::Approx(-0.002f).epsilon(1e-4));
      // Midway between the plane and the corner 2 mm below it.
      CHECK(m.points[i].point.y == doctest::Approx(-0.001f).epsilon(1e-3));
      CHECK(std::fabs(std::fabs(m.points[i].point.x - 0.7f) - 0.5f) < kTol);
      CHECK(std::fabs(std::fabs(m.points[i].point.z + 1.2f) - 0.3f) < kTol);
    }
    CHECK(PolygonArea(m) == doctest::Approx(1.0f * 0.6f).epsilon(1e-5));
  }

  TEST_CASE("plane-box: a box tilted about one axis touches along an edge, about two at a corner") {
    const BoxShape box{{0.5f, 0.25f, 0.3f}};
    const float angle = glm::radians(10.0f);
    // Lowest corners after a +10 deg turn about z have x = -0.5, y = -0.25; put them 1 mm deep.
    const float height = 0.5f * std::sin(angle) + 0.25f * std::cos(angle) - 0.001f;
    const Transform edge{{0.0f, height, 0.0f}, AxisAngle(10.0f, {0, 0, 1})};
    const Manifold m2 = CollidePlaneBox(PlaneShape{}, box, edge, kSpeculative);
    REQUIRE(m2.pointCount == 2);
    std::vector<uint32_t> ids = Ids(m2);
    std::sort(ids.begin(), ids.end());
    CHECK(ids == std::vector<uint32_t>{0, 4});
    for (int i = 0; i < 2; ++i) CHECK(m2.points[i].separation == doctest::Approx(-0.001f).epsilon(1e-3));

    const Transform corner{{0.0f, 0.4f, 0.0f}, AxisAngle(10.0f, {0, 0, 1}) * AxisAngle(-15.0f, {1, 0, 0})};
    float lowest = 1e9f;
    int lowestVertex = -1;
    for (int v = 0; v < 8; ++v) {
      const float y = BoxVertex(box, corner, v).y;
      if (y < lowest) {
        lowest = y;
        lowestVertex = v;
      }
    }
    const Manifold m1 = CollidePlaneBox(PlaneShape{}, box, corner, kSpeculative);
    REQUIRE(m1.pointCount == 1);
    CHECK(m1.points[0].id == static_cast<uint32_t>(lowestVertex));
    CHECK(m1.points[0].separation == doctest::Approx(lowest).epsilon(1e-5));
    CHECK_VEC3_NEAR(m1.points[0].point, BoxVertex(box, corner, lowestVertex) - glm::vec3(0, 0.5f * lowest, 0), kTol);
  }

  TEST_CASE("plane-box: a box above the plane is speculative within the distance and absent beyond it") {
    const BoxShape box{{0.2f, 0.2f, 0.2f}};
    const Manifold near = CollidePlaneBox(PlaneShape{}, box, {{0, 0.2f + 0.01f, 0}, {1, 0, 0, 0}}, kSpeculative);
    REQUIRE(near.pointCount == 4);
    for (int i = 0; i < 4; ++i) CHECK(near.points[i].separation == doctest::Approx(0.01f).epsilon(1e-4));
    const Manifold far = CollidePlaneBox(PlaneShape{}, box, {{0, 0.2f + 0.03f, 0}, {1, 0, 0, 0}}, kSpeculative);
    CHECK(far.pointCount == 0);
  }

  TEST_CASE("plane-box: a reach beyond the speculative distance adds the near face's vertices only") {
    // A thin box 3 cm above the plane, tilted 10 deg: the 2 cm band alone finds nothing.
    const BoxShape box{{0.1f, 0.015f, 0.05f}};
    const Transform t{
        {0.0f, 0.03f + 0.1f * std::sin(glm::radians(10.0f)) + 0.015f * std::cos(glm::radians(10.0f)), 0.0f},
        AxisAngle(10.0f, {0, 0, 1})};
    CHECK(CollidePlaneBox(PlaneShape{}, box, t, kSpeculative).pointCount == 0);
    CHECK(CollidePlaneBox(PlaneShape{}, box, t, kSpeculative, kSpeculative).pointCount == 0);
    // A 10 cm reach covers all eight corners (the highest is 9.4 cm up); the four of the bottom
    // face (body -y) are kept and the top face's, over the same area, are not.
    const Manifold m = CollidePlaneBox(PlaneShape{}, box, t, kSpeculative, 0.1f);
    REQUIRE(m.pointCount == 4);
    CHECK(IdsDistinct(m));
    for (int i = 0; i < m.pointCount; ++i) {
      CHECK((m.points[i].id & 2u) == 0u);  // vertex bit 1 is the body's y sign
      CHECK(m.points[i].separation == doctest::Approx(BoxVertex(box, t, int(m.points[i].id)).y).epsilon(1e-4));
    }
  }

  TEST_CASE("plane-box: a turned box resting on a tilted, offset plane") {
    const glm::vec3 normal =
        glm::normalize(glm::vec3(std::sin(glm::radians(20.0f)), std::cos(glm::radians(20.0f)), 0.3f));
    const PlaneShape plane{normal, 0.3f};
    const BoxShape box{{0.4f, 0.1f, 0.25f}};
    // Box +y along the plane normal, then spun 37 deg about it.
    const glm::quat rotation = AxisAngle(37.0f, normal) * glm::rotation(glm::vec3(0, 1, 0), normal);
    const Transform t{normal * (0.3f + 0.1f - 0.003f), rotation};
    const Manifold m = CollidePlaneBox(plane, box, t, kSpeculative);
    REQUIRE(m.pointCount == 4);
    CHECK_VEC3_NEAR(m.normal, normal, kTol);
    for (int i = 0; i < 4; ++i) {
      CHECK(m.points[i].separation == doctest::Approx(-0.003f).epsilon(1e-3));
      CHECK(glm::dot(normal, m.points[i].point) - 0.3f == doctest::Approx(-0.0015f).epsilon(1e-3));
    }
    CHECK(PolygonArea(m) == doctest::Approx(0.8f * 0.5f).epsilon(1e-4));
  }

  TEST_CASE("plane-box: more than four qualifying vertices keep the deepest and the widest spread") {
    // A 2 cm box inside a 10 cm speculative band: all eight corners qualify.
    const BoxShape box{{0.01f, 0.01f, 0.01f}};
    const Transform t{{0.0f, 0.02f, 0.0f}, AxisAngle(20.0f, {1, 0, 0}) * AxisAngle(35.0f, {0, 0, 1})};
    const Manifold m = CollidePlaneBox(PlaneShape{}, box, t, 0.1f);
    REQUIRE(m.pointCount == 4);
    CHECK(IdsDistinct(m));
    int deepest = 0;
    for (int v = 1; v < 8; ++v) {
      if (BoxVertex(box, t, v).y < BoxVertex(box, t, deepest).y) deepest = v;
    }
    int farthest = -1;
    float farthestDistSq = -1.0f;
    for (int v = 0; v < 8; ++v) {
      glm::vec3 d = BoxVertex(box, t, v) - BoxVertex(box, t, deepest);
      d.y = 0.0f;
      if (glm::dot(d, d) > farthestDistSq) {
        farthestDistSq = glm::dot(d, d);
        farthest = v;
      }
    }
    const std::vector<uint32_t> ids = Ids(m);
    CHECK(std::count(ids.begin(), ids.end(), static_cast<uint32_t>(deepest)) == 1);
    CHECK(std::count(ids.begin(), ids.end(), static_cast<uint32_t>(farthest)) == 1);
    // The kept quad covers nearly as much as the best quad through the deepest corner (brute force).
    float bestQuadArea = 0.0f;
    for (int b = 0; b < 8; ++b) {
      for (int c = b + 1; c < 8; ++c) {
        for (int d = c + 1; d < 8; ++d) {
          if (b == deepest || c == deepest || d == deepest) continue;
          Manifold quad;
          quad.pointCount = 4;
          const int corners[4] = {deepest, b, c, d};
          for (int k = 0; k < 4; ++k) quad.points[k].point = BoxVertex(box, t, corners[k]);
          bestQuadArea = std::max(bestQuadArea, PolygonArea(quad));
        }
      }
    }
    CHECK(PolygonArea(m) >= 0.9f * bestQuadArea);
    CHECK(PolygonArea(m) <= bestQuadArea * (1.0f + 1e-4f));
  }

  TEST_CASE("box-box: a box resting on a bigger one gives four points, symmetric when A and B swap") {
    const BoxShape lower{{0.5f, 0.5f, 0.5f}};
    const BoxShape upper{{0.3f, 0.2f, 0.4f}};
    const Transform tLower{{0, 0, 0}, {1, 0, 0, 0}};
    const Transform tUpper{{0, 0.5f + 0.2f - 0.004f, 0}, {1, 0, 0, 0}};
    const Manifold m = CollideBoxes(lower, tLower, upper, tUpper, kSpeculative);
    REQUIRE(m.pointCount == 4);
    CHECK_VEC3_NEAR(m.normal, glm::vec3(0, 1, 0), kTol);
    CHECK(IdsDistinct(m));
    for (float x : {-0.3f, 0.3f}) {
      for (float z : {-0.4f, 0.4f}) CHECK(HasPoint(m, {x, 0.5f - 0.002f, z}));
    }
    for (int i = 0; i < 4; ++i) CHECK(m.points[i].separation == doctest::Approx(-0.004f).epsilon(1e-3));

    const Manifold swapped = CollideBoxes(upper, tUpper, lower, tLower, kSpeculative);
    REQUIRE(swapped.pointCount == 4);
    CHECK_VEC3_NEAR(swapped.normal, -m.normal, kTol);
    for (int i = 0; i < 4; ++i) {
      CHECK(HasPoint(m, swapped.points[i].point));
      CHECK(swapped.points[i].separation == doctest::Approx(-0.004f).epsilon(1e-3));
    }
  }

  TEST_CASE("box-box: an offset box is clipped to the overlap rectangle") {
    const BoxShape lower{{1.0f, 0.5f, 1.0f}};
    const BoxShape upper{{0.5f, 0.1f, 0.5f}};
    const Transform tUpper{{0.8f, 0.6f - 0.002f, -0.7f}, {1, 0, 0, 0}};
    const Manifold m = CollideBoxes(lower, {}, upper, tUpper, kSpeculative);
    REQUIRE(m.pointCount == 4);
    // Overlap: x in [0.3, 1], z in [-1, -0.2].
    CHECK(PolygonArea(m) == doctest::Approx(0.7f * 0.8f).epsilon(1e-4));
    for (float x : {0.3f, 1.0f}) {
      for (float z : {-1.0f, -0.2f}) CHECK(HasPoint(m, {x, 0.5f - 0.001f, z}));
    }
  }

  TEST_CASE("box-box: a turned box keeps its footprint inside, and is cut to a triangle over an edge") {
    const BoxShape lower{{1.0f, 0.5f, 1.0f}};
    const BoxShape inside{{0.3f, 0.1f, 0.2f}};
    const Transform tInside{{0.1f, 0.6f - 0.003f, 0.2f}, AxisAngle(30.0f, {0, 1, 0})};
    const Manifold m = CollideBoxes(lower, {}, inside, tInside, kSpeculative);
    REQUIRE(m.pointCount == 4);
    CHECK(PolygonArea(m) == doctest::Approx(0.6f * 0.4f).epsilon(1e-4));
    for (int v : {0, 1, 4, 5}) {
      CHECK(HasPoint(m, BoxVertex(inside, tInside, v) + glm::vec3(0, 0.0015f, 0)));
    }

    // A 45 deg diamond of half-diagonal r centred 0.1 beyond the x = 1 edge keeps a
    // right isosceles triangle of height r - 0.1.
    const BoxShape diamond{{0.3f, 0.1f, 0.3f}};
    const Transform tDiamond{{1.1f, 0.6f - 0.003f, 0.0f}, AxisAngle(45.0f, {0, 1, 0})};
    const Manifold cut = CollideBoxes(lower, {}, diamond, tDiamond, kSpeculative);
    REQUIRE(cut.pointCount == 3);
    const float h = 0.3f * std::sqrt(2.0f) - 0.1f;
    CHECK(PolygonArea(cut) == doctest::Approx(h * h).epsilon(1e-3));
    CHECK(HasPoint(cut, {1.0f - h, 0.5f - 0.0015f, 0.0f}));
    CHECK(HasPoint(cut, {1.0f, 0.5f - 0.0015f, h}));
    CHECK(HasPoint(cut, {1.0f, 0.5f - 0.0015f, -h}));
    CHECK(IdsDistinct(cut));
  }

  TEST_CASE("box-box: crossing edges give one point at the edges' closest points") {
    // A's top edge runs along z at x = 0; B's bottom edge runs along x at z = -0.15.
    const BoxShape cube{{0.5f, 0.5f, 0.5f}};
    const float r = 0.5f * std::sqrt(2.0f);
    const Transform tA{{0, 0, 0}, AxisAngle(45.0f, {0, 0, 1})};
    const Transform tB{{0.1f, 2.0f * r - 0.01f, -0.15f}, AxisAngle(45.0f, {1, 0, 0})};
    const Manifold m = CollideBoxes(cube, tA, cube, tB, kSpeculative);
    REQUIRE(m.pointCount == 1);
    CHECK_VEC3_NEAR(m.normal, glm::vec3(0, 1, 0), kTol);
    CHECK(m.points[0].separation == doctest::Approx(-0.01f).epsilon(1e-3));
    CHECK_VEC3_NEAR(m.points[0].point, glm::vec3(0.0f, r - 0.005f, -0.15f), kTol);

    const Manifold swapped = CollideBoxes(cube, tB, cube, tA, kSpeculative);
    REQUIRE(swapped.pointCount == 1);
    CHECK_VEC3_NEAR(swapped.normal, glm::vec3(0, -1, 0), kTol);
    CHECK_VEC3_NEAR(swapped.points[0].point, m.points[0].point, kTol);
    CHECK(swapped.points[0].separation == doctest::Approx(-0.01f).epsilon(1e-3));
  }

  TEST_CASE("box-box: separated boxes give no points, including when only an edge axis separates") {
    const BoxShape cube{{0.5f, 0.5f, 0.5f}};
    const Manifold above = CollideBoxes(cube, {}, cube, {{0.2f, 1.0f + 0.03f, 0.1f}, {1, 0, 0, 0}}, kSpeculative);
    CHECK(above.pointCount == 0);
    const Manifold side =
        CollideBoxes(cube, {}, cube, {{-1.5f, 0.0f, 0.0f}, AxisAngle(10.0f, {0, 1, 0})}, kSpeculative);
    CHECK(side.pointCount == 0);

    // Crossed edges 3 cm apart: every face axis overlaps, only the edge cross product separates.
    const float r = 0.5f * std::sqrt(2.0f);
    const Transform tA{{0, 0, 0}, AxisAngle(45.0f, {0, 0, 1})};
    const Transform tB{{0, 2.0f * r + 0.03f, 0}, AxisAngle(45.0f, {1, 0, 0})};
    CHECK(CollideBoxes(cube, tA, cube, tB, kSpeculative).pointCount == 0);
    // Within the speculative distance the same pair gives one speculative point.
    const Transform tNear{{0, 2.0f * r + 0.01f, 0}, AxisAngle(45.0f, {1, 0, 0})};
    const Manifold near = CollideBoxes(cube, tA, cube, tNear, kSpeculative);
    REQUIRE(near.pointCount == 1);
    CHECK(near.points[0].separation == doctest::Approx(0.01f).epsilon(1e-3));
  }

  TEST_CASE("box-box: nearly parallel edges never win over the faces they lie in") {
    // Edge pairs within a fraction of a degree of parallel have a cross product too
    // short to trust; a resting box turned slightly must still get a face contact.
    const BoxShape lower{{0.5f, 0.5f, 0.5f}};
    const BoxShape upper{{0.4f, 0.2f, 0.3f}};
    for (float degrees : {0.02f, 0.06f, 0.1f, 0.2f, 0.5f}) {
      for (const glm::vec3& axis : {glm::vec3(0, 1, 0), glm::vec3(0.2f, 1, -0.1f), glm::vec3(1, 3, 2)}) {
        CAPTURE(degrees);
        const Transform t{{0.05f, 0.5f + 0.2f - 0.003f, -0.02f}, AxisAngle(degrees, axis)};
        const Manifold m = CollideBoxes(lower, {}, upper, t, kSpeculative);
        REQUIRE(m.pointCount == 4);
        CHECK(glm::length(m.normal) == doctest::Approx(1.0f).epsilon(1e-5));
        CHECK(m.normal.y > 0.9999f);
        // The points are midway between the upper box's bottom corners and the top face y = 0.5.
        for (int v : {0, 1, 4, 5}) {
          const glm::vec3 corner = BoxVertex(upper, t, v);
          CHECK(HasPoint(m, {corner.x, 0.5f * (corner.y + 0.5f), corner.z}));
        }
        for (int i = 0; i < 4; ++i) {
          CHECK(m.points[i].point.y - 0.5f * m.points[i].separation == doctest::Approx(0.5f).epsilon(1e-5));
        }
      }
    }
  }

  TEST_CASE("box-box: feature ids stay the same after a sub-millimetre move") {
    const BoxShape lower{{1.0f, 0.5f, 1.0f}};
    const BoxShape upper{{0.3f, 0.1f, 0.3f}};
    const glm::vec3 nudge{0.0007f, -0.0003f, 0.0005f};
    SUBCASE("face contact with clipped points") {
      // Turned, slightly tilted and hanging over the edge: ids come from corners and clip intersections.
      const Transform t0{{0.95f, 0.6f - 0.004f, 0.1f}, AxisAngle(30.0f, {0, 1, 0}) * AxisAngle(0.5f, {1, 0, 0})};
      const Transform t1{t0.position + nudge, t0.rotation};
      const Manifold m0 = CollideBoxes(lower, {}, upper, t0, kSpeculative);
      const Manifold m1 = CollideBoxes(lower, {}, upper, t1, kSpeculative);
      REQUIRE(m0.pointCount >= 3);
      CHECK(IdsDistinct(m0));
      CHECK(Ids(m0) == Ids(m1));
    }
    SUBCASE("tilted box on an edge") {
      const Transform t0{{0.2f, 0.6f + 0.3f * std::sin(glm::radians(5.0f)) - 0.002f, 0.0f}, AxisAngle(5.0f, {0, 0, 1})};
      const Transform t1{t0.position + nudge, t0.rotation};
      const Manifold m0 = CollideBoxes(lower, {}, upper, t0, kSpeculative);
      const Manifold m1 = CollideBoxes(lower, {}, upper, t1, kSpeculative);
      // The lowest edge sits 0.1 (1 - cos 5 deg) above the 2 mm the centre was lowered by.
      REQUIRE(m0.pointCount == 2);
      for (int i = 0; i < 2; ++i) {
        CHECK(m0.points[i].separation ==
              doctest::Approx(0.1f * (1.0f - std::cos(glm::radians(5.0f))) - 0.002f).epsilon(1e-3));
      }
      CHECK(Ids(m0) == Ids(m1));
    }
    SUBCASE("edge-edge") {
      const BoxShape cube{{0.5f, 0.5f, 0.5f}};
      const float r = 0.5f * std::sqrt(2.0f);
      const Transform tA{{0, 0, 0}, AxisAngle(45.0f, {0, 0, 1})};
      const Transform t0{{0.1f, 2.0f * r - 0.01f, -0.15f}, AxisAngle(45.0f, {1, 0, 0})};
      const Transform t1{t0.position + nudge, t0.rotation};
      const Manifold m0 = CollideBoxes(cube, tA, cube, t0, kSpeculative);
      const Manifold m1 = CollideBoxes(cube, tA, cube, t1, kSpeculative);
      REQUIRE(m0.pointCount == 1);
      REQUIRE(m1.pointCount == 1);
      CHECK(m0.points[0].id == m1.points[0].id);
    }
  }

  TEST_CASE("box-box: deep overlap is resolved along the axis of least penetration") {
    const BoxShape big{{1.0f, 1.0f, 1.0f}};
    const BoxShape small{{0.5f, 0.5f, 0.5f}};
    // Penetration along x 1.5 - 0.95 = 0.55, along y 1.5 - 0.3 = 1.2, along z 1.5 - 0.2 = 1.3.
    const Manifold m = CollideBoxes(big, {}, small, {{-0.95f, 0.3f, 0.2f}, {1, 0, 0, 0}}, kSpeculative);
    REQUIRE(m.pointCount == 4);
    CHECK_VEC3_NEAR(m.normal, glm::vec3(-1, 0, 0), kTol);
    for (int i = 0; i < 4; ++i) CHECK(m.points[i].separation == doctest::Approx(-0.55f).epsilon(1e-4));

    // Turned by 20 deg about y the small box's x extent on A's x axis grows to
    // 0.5 (cos 20 + sin 20) = 0.6408, so x penetration is 1.6408 - 1.1 = 0.5408 < y's 1.2.
    const Transform turned{{1.1f, 0.3f, 0.2f}, AxisAngle(20.0f, {0, 1, 0})};
    const Manifold mt = CollideBoxes(big, {}, small, turned, kSpeculative);
    REQUIRE(mt.pointCount >= 1);
    CHECK_VEC3_NEAR(mt.normal, glm::vec3(1, 0, 0), kTol);
    float deepest = 0.0f;
    for (int i = 0; i < mt.pointCount; ++i) deepest = std::min(deepest, mt.points[i].separation);
    const float c = std::cos(glm::radians(20.0f));
    const float s = std::sin(glm::radians(20.0f));
    CHECK(deepest == doctest::Approx(1.1f - 1.0f - 0.5f * (c + s)).epsilon(1e-4));
  }

  TEST_CASE("box-box: random poses give unit normals and points midway between the surfaces") {
    std::uniform_real_distribution<float> coordinate(-1.0f, 1.0f);
    std::uniform_real_distribution<float> half(0.05f, 0.6f);
    auto randomRotation = [&] {
      return glm::normalize(glm::quat(coordinate(rise::test::Rng()), coordinate(rise::test::Rng()),
                                      coordinate(rise::test::Rng()), coordinate(rise::test::Rng())));
    };
    float worstError = 0.0f;
    float worstNormal = 0.0f;
    int touching = 0;
    for (int i = 0; i < 20000; ++i) {
      const BoxShape boxA{{half(rise::test::Rng()), half(rise::test::Rng()), half(rise::test::Rng())}};
      const BoxShape boxB{{half(rise::test::Rng()), half(rise::test::Rng()), half(rise::test::Rng())}};
      const Transform tA{{coordinate(rise::test::Rng()), coordinate(rise::test::Rng()), coordinate(rise::test::Rng())},
                         randomRotation()};
      Transform tB{{coordinate(rise::test::Rng()), coordinate(rise::test::Rng()), coordinate(rise::test::Rng())},
                   randomRotation()};
      // Every other pair nearly aligned, where edge cross products degenerate: this
      // once let a near-parallel edge pair win with a normal of length 0.1, because
      // 1 - cos^2 cancels in float.
      if (i % 2 == 0) tB.rotation = tA.rotation * AxisAngle(0.06f * coordinate(rise::test::Rng()), {1, 2, 3});
      const Manifold m = CollideBoxes(boxA, tA, boxB, tB, kSpeculative);
      if (m.pointCount == 0) continue;
      ++touching;
      worstNormal = std::max(worstNormal, std::fabs(glm::length(m.normal) - 1.0f));
      worstError = std::max(worstError, WorstSurfaceError(boxA, tA, boxB, tB, m));
    }
    CHECK(touching > 2000);
    CHECK(worstNormal < 1e-5f);
    CHECK(worstError < 1e-4f);
  }

}  // TEST_SUITE
