// SPDX-License-Identifier: MIT
// Static geometry: immovable shapes the dynamic boxes collide with (ground planes, static boxes).
#pragma once

#include "physics/collide.h"

#include <cstdint>

namespace rise::physics {

// New kinds (a heightfield) add a type here, a narrow-phase function in collide.h and one case in
// contact.cpp's CollideStatic; the solver sees only the resulting manifolds.
enum class StaticShapeType : uint8_t { kPlane, kBox };

struct StaticShape {
  StaticShapeType type = StaticShapeType::kPlane;
  PlaneShape plane;      // kPlane: any normal, so slopes are planes too
  BoxShape box;          // kBox
  Transform transform;   // kBox: world pose
  float friction = 0.6f;
  uint32_t categoryBits = 0x1u;
  uint32_t maskBits = 0xFFFFFFFFu;
};

struct StaticShapeId {
  int32_t index = -1;
  bool IsValid() const { return index >= 0; }
};

}  // namespace rise::physics
