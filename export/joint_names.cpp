// SPDX-License-Identifier: MIT
// Joint naming presets and the reverse lookup to canonical names.
#include "export/joint_names.h"

#include <array>
#include <cctype>

namespace rise {
namespace {

struct NameRow {
  const char* canonical;
  const char* mixamo;  // without the "mixamorig:" prefix
  const char* ue;
};

// Mixamo and the UE mannequin have more spine and finger bones than our
// 15-box body; each of our joints takes the name of the bone at the same place
// (chest -> Spine2/spine_03, the upper spine that carries the arms). The UE
// mannequin has no head-top bone, so head_end keeps a descriptive name.
constexpr std::array<NameRow, 22> kNames = {{
    {"root", "root", "root"},
    {"pelvis", "Hips", "pelvis"},
    {"abdomen", "Spine", "spine_01"},
    {"chest", "Spine2", "spine_03"},
    {"head", "Head", "head"},
    {"head_end", "HeadTop_End", "head_end"},
    {"upper_arm_l", "LeftArm", "upperarm_l"},
    {"forearm_l", "LeftForeArm", "lowerarm_l"},
    {"hand_l", "LeftHand", "hand_l"},
    {"hand_l_end", "LeftHandMiddle4", "middle_01_l"},
    {"upper_arm_r", "RightArm", "upperarm_r"},
    {"forearm_r", "RightForeArm", "lowerarm_r"},
    {"hand_r", "RightHand", "hand_r"},
    {"hand_r_end", "RightHandMiddle4", "middle_01_r"},
    {"thigh_l", "LeftUpLeg", "thigh_l"},
    {"shin_l", "LeftLeg", "calf_l"},
    {"foot_l", "LeftFoot", "foot_l"},
    {"foot_l_end", "LeftToe_End", "ball_l"},
    {"thigh_r", "RightUpLeg", "thigh_r"},
    {"shin_r", "RightLeg", "calf_r"},
    {"foot_r", "RightFoot", "foot_r"},
    {"foot_r_end", "RightToe_End", "ball_r"},
}};

constexpr std::string_view kMixamoPrefix = "mixamorig:";

bool EqualNoCase(std::string_view a, std::string_view b) {
  if (a.size() != b.size()) return false;
  for (size_t i = 0; i < a.size(); ++i) {
    if (std::tolower(static_cast<unsigned char>(a[i])) != std::tolower(static_cast<unsigned char>(b[i]))) return false;
  }
  return true;
}

const NameRow* FindCanonical(std::string_view canonical) {
  for (const NameRow& row : kNames) {
    if (canonical == row.canonical) return &row;
  }
  return nullptr;
}

}  // namespace

std::optional<NamingPreset> ParseNamingPreset(std::string_view name) {
  if (name == "default") return NamingPreset::kDefault;
  if (name == "mixamo") return NamingPreset::kMixamo;
  if (name == "ue") return NamingPreset::kUe;
  return std::nullopt;
}

const char* NamingPresetName(NamingPreset preset) {
  switch (preset) {
    case NamingPreset::kDefault:
      return "default";
    case NamingPreset::kMixamo:
      return "mixamo";
    case NamingPreset::kUe:
      return "ue";
  }
  return "default";
}

std::string PresetJointName(NamingPreset preset, std::string_view canonical) {
  const NameRow* row = FindCanonical(canonical);
  if (row == nullptr || preset == NamingPreset::kDefault) return std::string(canonical);
  if (preset == NamingPreset::kUe) return row->ue;
  // An extracted root keeps its plain name: Mixamo rigs have no such bone.
  if (std::string_view(row->canonical) == "root") return row->mixamo;
  return std::string(kMixamoPrefix) + row->mixamo;
}

Skeleton RenameJoints(const Skeleton& skeleton, NamingPreset preset) {
  Skeleton renamed = skeleton;
  for (SkeletonJoint& joint : renamed.joints) joint.name = PresetJointName(preset, joint.name);
  return renamed;
}

std::optional<std::string> CanonicalJointName(std::string_view anyName) {
  std::string_view name = anyName;
  if (const size_t cut = name.find_last_of(":|"); cut != std::string_view::npos) name.remove_prefix(cut + 1);
  for (const NameRow& row : kNames) {
    if (EqualNoCase(name, row.canonical) || EqualNoCase(name, row.mixamo) || EqualNoCase(name, row.ue)) {
      return std::string(row.canonical);
    }
  }
  return std::nullopt;
}

}  // namespace rise
