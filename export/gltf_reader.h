// SPDX-License-Identifier: MIT
// Reads a .glb/.gltf back into a Clip: for the tests and for `rise-gen check`,
// which measures clips through it, including reasonable files of other tools.
//
// What is taken from the file:
// - the first skin's joints, ordered parents-first from its single root joint
//   (files whose skin has several root joints are rejected);
// - joint names, mapped to canonical names (joint_names.h) when every joint
//   maps to a distinct one, otherwise kept as they are;
// - the bind pose from the nodes' rest transforms (including any transform of
//   the nodes above the root joint, such as an armature's axis or unit
//   change). The clip's convention (joint frames aligned with the world in the
//   bind pose) is restored by removing each joint's rest world rotation;
// - bone boxes: for each joint, the axis-aligned bounds of the skinned mesh
//   vertices it owns (largest weight), taken to joint space through the
//   inverse bind matrices;
// - the first animation, sampled at the frame rate estimated from its key
//   times (the median key spacing of the densest track, snapped to a whole
//   fps when within 0.5 %); LINEAR and STEP are honoured, CUBICSPLINE is read
//   through its values only; non-root joints whose translation moves get a
//   translation track;
// - metadata from the animation's `extras` when rise-gen wrote them.
#pragma once

#include <string>

#include "export/clip.h"

namespace rise {

// Reads `path`. Returns an empty string on success, otherwise a message.
std::string ReadGltf(const std::string& path, Clip& clip);

}  // namespace rise
