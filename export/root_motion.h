// SPDX-License-Identifier: MIT
// Where a clip's travel over the ground lives: the three `--root-motion` modes.
//
// The ground frame of a frame is the root's position dropped to y = 0 and its
// heading: the twist of the root rotation about +Y (swing-twist decomposition).
// The twist stays defined for a body lying on its back, front or side; it is
// undefined only for a root turned upside down (a headstand), where the
// previous frame's heading is kept.
#pragma once

#include <optional>
#include <string_view>

#include "export/clip.h"

namespace rise {

enum class RootMotion {
  kBake,     // the root (pelvis) moves through the world; the clip as simulated
  kInPlace,  // horizontal travel and heading change removed relative to frame 0;
             // their totals go to metadata.removedTravel / removedHeading
  kExtract,  // a new ground-level joint `root` (parent of the pelvis) carries
             // the horizontal travel and heading, as Unreal/Unity root motion expects
};

// "bake", "in-place", "extract" -> mode; anything else -> nullopt.
std::optional<RootMotion> ParseRootMotion(std::string_view name);
const char* RootMotionName(RootMotion mode);

// Name of the joint that kExtract adds.
inline constexpr const char* kExtractedRootName = "root";

// The clip rewritten for `mode` (kBake returns it unchanged apart from the
// metadata tag). Every joint's world motion except the removed part is kept.
// `clip` must be valid and must not already hold an extracted root.
Clip ApplyRootMotion(const Clip& clip, RootMotion mode);

// Heading of a world rotation: the angle of its twist about +Y, radians.
double HeadingOf(const glm::quat& rotation, double fallback);

}  // namespace rise
