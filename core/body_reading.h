// SPDX-License-Identifier: MIT
// What the rise controller reads from the simulated body each step (the sensor
// side of the feedback loop) and what it writes back (servo targets). Kept
// free of physics types so the controller can be tested on a kinematic body.
#pragma once

#include "core/body_pose_ik.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <vector>

namespace rise {

struct BodyReading {
  double time = 0.0;                       // s since the simulation started
  std::vector<glm::vec3> jointPositions;   // world, per skeleton joint
  std::vector<glm::quat> jointRotations;   // world, per skeleton joint
  glm::vec3 com{0.0f};                     // whole-body centre of mass, world
  glm::vec3 comVelocity{0.0f};             // m/s
  float maxBodySpeed = 0.0f;               // fastest body centre, m/s (rest detection)
  float maxAngularSpeed = 0.0f;            // fastest body spin, rad/s (rest detection)
  std::array<bool, kLimbCount> touching{}; // hand/foot box pressing on the ground
};

// Per skeleton joint: the local rotation its servo tracks, a gain scale
// (1 = the BipedDef's gains) and a feed-forward torque (world, N*m, applied
// to the joint's child body, its parent gets the opposite) that the servo adds
// inside its torque cap. Joints without a body are ignored.
struct ServoTargets {
  std::vector<glm::quat> local;
  std::vector<float> gainScale;
  std::vector<glm::vec3> feedForward;
};

}  // namespace rise
