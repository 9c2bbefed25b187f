// SPDX-License-Identifier: MIT
#include <set>

#include "export/biped_fixture.h"
#include "export/joint_names.h"
#include "test_support.h"

TEST_SUITE("joint_names") {
  TEST_CASE("presets give the rig names artists expect") {
    using rise::NamingPreset;
    CHECK(rise::PresetJointName(NamingPreset::kMixamo, "pelvis") == "mixamorig:Hips");
    CHECK(rise::PresetJointName(NamingPreset::kMixamo, "chest") == "mixamorig:Spine2");
    CHECK(rise::PresetJointName(NamingPreset::kMixamo, "head_end") == "mixamorig:HeadTop_End");
    CHECK(rise::PresetJointName(NamingPreset::kMixamo, "forearm_l") == "mixamorig:LeftForeArm");
    CHECK(rise::PresetJointName(NamingPreset::kMixamo, "thigh_r") == "mixamorig:RightUpLeg");
    CHECK(rise::PresetJointName(NamingPreset::kMixamo, "foot_l_end") == "mixamorig:LeftToe_End");
    CHECK(rise::PresetJointName(NamingPreset::kUe, "abdomen") == "spine_01");
    CHECK(rise::PresetJointName(NamingPreset::kUe, "upper_arm_l") == "upperarm_l");
    CHECK(rise::PresetJointName(NamingPreset::kUe, "shin_r") == "calf_r");
    CHECK(rise::PresetJointName(NamingPreset::kUe, "foot_r_end") == "ball_r");
    CHECK(rise::PresetJointName(NamingPreset::kDefault, "shin_r") == "shin_r");
    CHECK(rise::PresetJointName(NamingPreset::kUe, "tail") == "tail");
  }
  TEST_CASE("every preset name of every biped joint maps back to its canonical name, and names are distinct") {
    const rise::Skeleton skeleton = rise::test::MakeBipedSkeleton();
    for (rise::NamingPreset preset :
         {rise::NamingPreset::kDefault, rise::NamingPreset::kMixamo, rise::NamingPreset::kUe}) {
      CAPTURE(rise::NamingPresetName(preset));
      CHECK(rise::ParseNamingPreset(rise::NamingPresetName(preset)) == preset);
      const rise::Skeleton renamed = rise::RenameJoints(skeleton, preset);
      CHECK(renamed.Validate().empty());
      std::set<std::string> names;
      for (int j = 0; j < skeleton.JointCount(); ++j) {
        names.insert(renamed.joints[j].name);
        CHECK(rise::CanonicalJointName(renamed.joints[j].name) == skeleton.joints[j].name);
        CHECK(renamed.joints[j].parent == skeleton.joints[j].parent);
      }
      CHECK(static_cast<int>(names.size()) == skeleton.JointCount());
    }
    CHECK(rise::CanonicalJointName("root") == std::string("root"));
  }
  TEST_CASE("the reverse lookup reads other tools' spellings and rejects unknown names") {
    CHECK(rise::CanonicalJointName("mixamorig1:LeftUpLeg") == std::string("thigh_l"));
    CHECK(rise::CanonicalJointName("Armature|Hips") == std::string("pelvis"));
    CHECK(rise::CanonicalJointName("HEAD") == std::string("head"));
    CHECK(rise::CanonicalJointName("calf_l") == std::string("shin_l"));
    CHECK_FALSE(rise::CanonicalJointName("LeftHandThumb1").has_value());
    CHECK_FALSE(rise::CanonicalJointName("").has_value());
    CHECK_FALSE(rise::ParseNamingPreset("unreal").has_value());
  }
}
