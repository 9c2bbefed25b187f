// SPDX-License-Identifier: MIT
// Analytic two-link IK (Kulpa et al., as used by Coros et al. 2010 and the rise
// paper): knee or elbow placed on a plane through the root and the target whose
// rotation about the root-target line is the swivel parameter.
#pragma once

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

namespace rise {

struct TwoBoneIk {
  // Inputs, world space.
  glm::vec3 root{0.0f};    // hip or shoulder joint position
  glm::vec3 target{0.0f};  // desired ankle or wrist position
  glm::vec3 pole{0.0f, 0.0f, 1.0f};  // where the mid joint should point (knee forward, elbow back)
  float swivel = 0.0f;     // rotation of the bend plane about root->target, radians
  float upperLength = 0.0f;
  float lowerLength = 0.0f;
  // Largest mid-joint flexion allowed (radians from straight): the knee or
  // elbow limit. Targets closer than it allows are pushed out, never the joint.
  float maxFlexion = 2.6f;
  // Rest pose of the chain (bind pose): bone direction and bend direction.
  glm::vec3 restBoneDirection{0.0f, -1.0f, 0.0f};
  glm::vec3 restPole{0.0f, 0.0f, 1.0f};

  // Outputs.
  glm::vec3 mid{0.0f};          // knee or elbow position
  glm::vec3 end{0.0f};          // reached end position (target clamped to reach)
  glm::quat upperRotation{1.0f, 0.0f, 0.0f, 0.0f};  // world rotation of the upper bone from rest
  glm::quat lowerRotation{1.0f, 0.0f, 0.0f, 0.0f};  // world rotation of the lower bone from rest
  float flexion = 0.0f;         // mid-joint angle from straight, radians
  bool reached = false;         // target within reach (no clamping)

  // True when the inputs describe a solvable chain (positive lengths, finite values).
  bool Validate() const;
  // Computes the outputs; pure function of the inputs.
  void Solve();
};

}  // namespace rise
