// SPDX-License-Identifier: MIT
// Joint naming presets, so clips retarget onto common rigs without a manual
// bone map, and the reverse lookup that finds our joints in anyone's file.
//
// Canonical names are the biped's own (core/ builds them): pelvis, abdomen,
// chest, head, head_end, upper_arm_l, forearm_l, hand_l, hand_l_end, thigh_l,
// shin_l, foot_l, foot_l_end, the same with _r, and `root` for an extracted
// root. _l is the character's left (+X when standing facing +Z).
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "export/skeleton.h"

namespace rise {

enum class NamingPreset {
  kDefault,  // canonical names
  kMixamo,   // mixamorig:Hips, mixamorig:Spine, mixamorig:LeftUpLeg, ...
  kUe,       // Unreal Engine mannequin: pelvis, spine_01, thigh_l, calf_l, ...
};

// "default", "mixamo", "ue" -> preset; anything else -> nullopt.
std::optional<NamingPreset> ParseNamingPreset(std::string_view name);
const char* NamingPresetName(NamingPreset preset);

// The preset's name for canonical joint `canonical`; names the preset does not
// know pass through unchanged.
std::string PresetJointName(NamingPreset preset, std::string_view canonical);

// The skeleton with every joint renamed by PresetJointName.
Skeleton RenameJoints(const Skeleton& skeleton, NamingPreset preset);

// Reverse lookup: the canonical name for a joint name from any preset, matched
// without regard to case and after dropping a namespace prefix ("mixamorig1:",
// "Armature|"), so files of other tools map too. nullopt when unknown.
std::optional<std::string> CanonicalJointName(std::string_view anyName);

}  // namespace rise
