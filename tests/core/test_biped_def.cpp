// SPDX-License-Identifier: MIT
// BipedDef: proportions, masses, joint limits and the bind-pose skeleton.
#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>

#include "core/biped_def.h"
#include "test_support.h"

namespace {

float TotalMass(const rise::BipedDef& def) {
  float sum = 0.0f;
  for (const rise::BoneDef& bone : def.bones) sum += bone.massKg;
  return sum;
}

// World-space bind-pose box of joint i: min and max corners (joint frames are world aligned).
void BindBox(const rise::BipedDef& def, int i, glm::vec3& lo, glm::vec3& hi) {
  const glm::vec3 p = def.skeleton.BindPositions()[i] + def.skeleton.joints[i].box.center;
  lo = p - def.skeleton.joints[i].box.halfExtents;
  hi = p + def.skeleton.joints[i].box.halfExtents;
}

bool Overlap(const rise::BipedDef& def, int a, int b) {
  glm::vec3 loA, hiA, loB, hiB;
  BindBox(def, a, loA, hiA);
  BindBox(def, b, loB, hiB);
  for (int k = 0; k < 3; ++k) {
    if (hiA[k] <= loB[k] || hiB[k] <= loA[k]) return false;
  }
  return true;
}

}  // namespace

TEST_SUITE("biped_def") {
  TEST_CASE("joint names, order and parents are exactly the shared skeleton contract") {
    const rise::BipedDef def = rise::MakeBipedDef(1.75f, 70.0f);
    const std::pair<const char*, const char*> expected[] = {
        {"pelvis", ""},           {"abdomen", "pelvis"},    {"chest", "abdomen"},         {"head", "chest"},
        {"head_end", "head"},     {"upper_arm_l", "chest"}, {"forearm_l", "upper_arm_l"}, {"hand_l", "forearm_l"},
        {"hand_l_end", "hand_l"}, {"upper_arm_r", "chest"}, {"forearm_r", "upper_arm_r"}, {"hand_r", "forearm_r"},
        {"hand_r_end", "hand_r"}, {"thigh_l", "pelvis"},    {"shin_l", "thigh_l"},        {"foot_l", "shin_l"},
        {"foot_l_end", "foot_l"}, {"thigh_r", "pelvis"},    {"shin_r", "thigh_r"},        {"foot_r", "shin_r"},
        {"foot_r_end", "foot_r"}};
    REQUIRE(def.skeleton.JointCount() == 21);
    REQUIRE(def.bones.size() == 21u);
    CHECK(def.skeleton.Validate().empty());
    int boxes = 0;
    for (int i = 0; i < 21; ++i) {
      const rise::SkeletonJoint& joint = def.skeleton.joints[i];
      CHECK(joint.name == expected[i].first);
      const int parent = joint.parent;
      CHECK(std::string(parent < 0 ? "" : def.skeleton.joints[parent].name.c_str()) == expected[i].second);
      const bool isEnd = joint.name.size() > 4 && joint.name.substr(joint.name.size() - 4) == "_end";
      CHECK(joint.hasBox == !isEnd);
      CHECK((def.bones[i].kind == rise::JointKind::kEnd) == isEnd);
      boxes += joint.hasBox ? 1 : 0;
    }
    CHECK(boxes == 16);
    CHECK(rise::SegmentNames().size() == 16u);
  }

  TEST_CASE("segment masses follow Dempster's fractions and sum to the body mass") {
    for (const float mass : {45.0f, 70.0f, 110.0f}) {
      const rise::BipedDef def = rise::MakeBipedDef(1.75f, mass);
      CHECK(TotalMass(def) == doctest::Approx(mass).epsilon(1e-5));
      CHECK(def.bones[def.Find("thigh_l")].massKg == doctest::Approx(0.100 * mass).epsilon(1e-5));
      CHECK(def.bones[def.Find("shin_r")].massKg == doctest::Approx(0.0465 * mass).epsilon(1e-5));
      CHECK(def.bones[def.Find("foot_l")].massKg == doctest::Approx(0.0145 * mass).epsilon(1e-5));
      CHECK(def.bones[def.Find("upper_arm_r")].massKg == doctest::Approx(0.028 * mass).epsilon(1e-5));
      CHECK(def.bones[def.Find("forearm_l")].massKg == doctest::Approx(0.016 * mass).epsilon(1e-5));
      CHECK(def.bones[def.Find("hand_r")].massKg == doctest::Approx(0.006 * mass).epsilon(1e-5));
      CHECK(def.bones[def.Find("head")].massKg == doctest::Approx(0.081 * mass).epsilon(1e-5));
      const float trunk = def.bones[def.Find("pelvis")].massKg + def.bones[def.Find("abdomen")].massKg +
                          def.bones[def.Find("chest")].massKg;
      CHECK(trunk == doctest::Approx(0.497 * mass).epsilon(1e-5));
    }
  }

  TEST_CASE("bind pose: soles on y = 0, head top at the height, Winter's joint heights") {
    for (const float height : {1.5f, 1.75f, 1.95f}) {
      const rise::BipedDef def = rise::MakeBipedDef(height, 70.0f);
      const std::vector<glm::vec3> p = def.skeleton.BindPositions();
      CHECK(def.BindHeadTop() == doctest::Approx(height).epsilon(1e-5));
      for (const char* foot : {"foot_l", "foot_r"}) {
        glm::vec3 lo, hi;
        BindBox(def, def.Find(foot), lo, hi);
        CHECK(std::fabs(lo.y) < 1e-6f);
        CHECK(p[def.Find(std::string(foot) + "_end")].y == doctest::Approx(0.0f));
      }
      CHECK(p[def.Find("foot_l")].y / height == doctest::Approx(0.039f).epsilon(1e-4));
      CHECK(p[def.Find("shin_l")].y / height == doctest::Approx(0.285f).epsilon(1e-4));
      CHECK(p[def.Find("thigh_r")].y / height == doctest::Approx(0.530f).epsilon(1e-4));
      CHECK(p[def.Find("upper_arm_l")].y / height == doctest::Approx(0.819f).epsilon(1e-3));
      // Arm chain lengths: upper arm 0.186 H, forearm 0.146 H, hand 0.108 H.
      CHECK(glm::length(p[def.Find("forearm_r")] - p[def.Find("upper_arm_r")]) / height ==
            doctest::Approx(0.186f).epsilon(1e-4));
      CHECK(glm::length(p[def.Find("hand_r")] - p[def.Find("forearm_r")]) / height ==
            doctest::Approx(0.146f).epsilon(1e-4));
      CHECK(glm::length(p[def.Find("hand_r_end")] - p[def.Find("hand_r")]) / height ==
            doctest::Approx(0.108f).epsilon(1e-4));
      // Left is +X, and the toes point along +Z.
      CHECK(p[def.Find("thigh_l")].x > 0.0f);
      CHECK(p[def.Find("upper_arm_r")].x < 0.0f);
      CHECK(p[def.Find("foot_l_end")].z > p[def.Find("foot_l")].z + 0.1f * height);
    }
  }

  TEST_CASE("bind-pose centre of mass lies at 0.55-0.57 of the height, on the mid-plane") {
    for (const float height : {1.5f, 1.75f, 1.95f}) {
      const rise::BipedDef def = rise::MakeBipedDef(height, 80.0f);
      const glm::vec3 com = def.BindCenterOfMass();
      CHECK(com.y / height > 0.55f);
      CHECK(com.y / height < 0.57f);
      CHECK(std::fabs(com.x) < 1e-5f);
    }
  }

  TEST_CASE("no two boxes overlap in the bind pose unless they are parent and child") {
    const rise::BipedDef def = rise::MakeBipedDef(1.75f, 70.0f);
    const rise::Skeleton& s = def.skeleton;
    int overlaps = 0;
    for (int a = 0; a < s.JointCount(); ++a) {
      for (int b = a + 1; b < s.JointCount(); ++b) {
        if (!s.joints[a].hasBox || !s.joints[b].hasBox) continue;
        if (s.joints[b].parent == a) continue;
        INFO(s.joints[a].name << " vs " << s.joints[b].name);
        CHECK_FALSE(Overlap(def, a, b));
        overlaps += Overlap(def, a, b) ? 1 : 0;
      }
    }
    CHECK(overlaps == 0);
    // The hands hang beside the thighs with a visible gap (at least 1 cm).
    glm::vec3 handLo, handHi, thighLo, thighHi;
    BindBox(def, def.Find("hand_l"), handLo, handHi);
    BindBox(def, def.Find("thigh_l"), thighLo, thighHi);
    CHECK(handLo.x - thighHi.x > 0.01f);
  }

  TEST_CASE("joint kinds, DOF counts and one-way hinges") {
    const rise::BipedDef def = rise::MakeBipedDef(1.75f, 70.0f);
    CHECK(def.bones[0].kind == rise::JointKind::kFree);
    CHECK(def.DofCount(def.Find("shin_l")) == 1);
    CHECK(def.DofCount(def.Find("forearm_r")) == 1);
    CHECK(def.DofCount(def.Find("thigh_l")) == 2);
    CHECK(def.DofCount(def.Find("upper_arm_r")) == 2);
    CHECK(def.DofCount(def.Find("chest")) == 3);
    CHECK(def.DofCount(def.Find("head_end")) == 0);
    for (const char* hinge : {"shin_l", "shin_r", "forearm_l", "forearm_r"}) {
      const rise::JointDof& dof = def.bones[def.Find(hinge)].dofs[0];
      CHECK(dof.minDeg == 0.0f);
      CHECK(dof.maxDeg >= 140.0f);
    }
    // Knee flexion swings the shin backward (-Z), elbow flexion the forearm forward (+Z).
    const float ninety = 90.0f;
    const glm::vec3 down(0, -1, 0);
    CHECK_VEC3_NEAR(def.JointRotation(def.Find("shin_l"), &ninety) * down, glm::vec3(0, 0, -1), 1e-5f);
    CHECK_VEC3_NEAR(def.JointRotation(def.Find("forearm_r"), &ninety) * down, glm::vec3(0, 0, 1), 1e-5f);
    // Hip flexion lifts the thigh forward; left abduction moves the left leg to +X, right to -X.
    const float hip[2] = {90.0f, 0.0f};
    CHECK_VEC3_NEAR(def.JointRotation(def.Find("thigh_l"), hip) * down, glm::vec3(0, 0, 1), 1e-5f);
    const float abduct[2] = {0.0f, 90.0f};
    CHECK_VEC3_NEAR(def.JointRotation(def.Find("thigh_l"), abduct) * down, glm::vec3(1, 0, 0), 1e-5f);
    CHECK_VEC3_NEAR(def.JointRotation(def.Find("upper_arm_r"), abduct) * down, glm::vec3(-1, 0, 0), 1e-5f);
    // Ankle dorsiflexion lifts the toes; positive trunk flexion bends forward.
    const float dorsi[2] = {90.0f, 0.0f};
    CHECK_VEC3_NEAR(def.JointRotation(def.Find("foot_r"), dorsi) * glm::vec3(0, 0, 1), glm::vec3(0, 1, 0), 1e-5f);
    const float bow[3] = {90.0f, 0.0f, 0.0f};
    CHECK_VEC3_NEAR(def.JointRotation(def.Find("abdomen"), bow) * glm::vec3(0, 1, 0), glm::vec3(0, 0, 1), 1e-5f);
  }

  TEST_CASE("torque caps scale with body mass per joint") {
    const rise::BipedDef def = rise::MakeBipedDef(1.75f, 80.0f);
    CHECK(def.bones[def.Find("thigh_l")].maxTorqueNm == doctest::Approx(3.5 * 80));
    CHECK(def.bones[def.Find("shin_r")].maxTorqueNm == doctest::Approx(3.0 * 80));
    CHECK(def.bones[def.Find("foot_l")].maxTorqueNm == doctest::Approx(2.0 * 80));
    CHECK(def.bones[def.Find("abdomen")].maxTorqueNm == doctest::Approx(3.0 * 80));
    CHECK(def.bones[def.Find("chest")].maxTorqueNm == doctest::Approx(3.0 * 80));
    CHECK(def.bones[def.Find("upper_arm_r")].maxTorqueNm == doctest::Approx(1.2 * 80));
    CHECK(def.bones[def.Find("forearm_l")].maxTorqueNm == doctest::Approx(1.0 * 80));
    CHECK(def.bones[def.Find("head")].maxTorqueNm == doctest::Approx(0.5 * 80));
    CHECK(def.bones[def.Find("hand_r")].maxTorqueNm == doctest::Approx(0.3 * 80));
    CHECK(def.bones[0].maxTorqueNm == 0.0f);
    for (const rise::BoneDef& bone : def.bones) {
      if (bone.maxTorqueNm > 0.0f) {
        CHECK(bone.servoKp > 0.0f);
        CHECK(bone.servoKd > 0.0f);
      }
    }
  }

  TEST_CASE("overrides: long arms, a heavy thigh, and the other masses rescaled to the body mass") {
    rise::SegmentOverrides overrides;
    overrides["upper_arm_l"].lengthM = 0.40f;
    overrides["thigh_r"].massKg = 12.0f;
    overrides["chest"].widthM = 0.40f;
    const rise::BipedDef def = rise::MakeBipedDef(1.75f, 70.0f, overrides);
    CHECK(TotalMass(def) == doctest::Approx(70.0f).epsilon(1e-5));
    CHECK(def.bones[def.Find("thigh_r")].massKg == doctest::Approx(12.0f));
    // The untouched segments share 70 - 12 kg in Dempster's ratios.
    const float scale = (70.0f - 12.0f) / (1.0f - 0.100f);
    CHECK(def.bones[def.Find("thigh_l")].massKg == doctest::Approx(0.100f * scale).epsilon(1e-5));
    const std::vector<glm::vec3> p = def.skeleton.BindPositions();
    CHECK(glm::length(p[def.Find("forearm_l")] - p[def.Find("upper_arm_l")]) == doctest::Approx(0.40f));
    CHECK(def.skeleton.joints[def.Find("chest")].box.halfExtents.x == doctest::Approx(0.20f));
    // A wider chest pushes the shoulders out so the arms still clear it.
    glm::vec3 armLo, armHi, chestLo, chestHi;
    BindBox(def, def.Find("upper_arm_l"), armLo, armHi);
    BindBox(def, def.Find("chest"), chestLo, chestHi);
    CHECK(armLo.x > chestHi.x);
  }
  TEST_CASE("JointAngles inverts JointRotation for every joint at random angles inside the limits") {
    const rise::BipedDef def = rise::MakeBipedDef(1.75f, 70.0f);
    int checked = 0;
    for (int j = 0; j < def.skeleton.JointCount(); ++j) {
      const int n = def.DofCount(j);
      if (n == 0) continue;
      for (int trial = 0; trial < 50; ++trial) {
        float angles[3] = {}, back[3] = {};
        for (int k = 0; k < n; ++k) {
          const rise::JointDof& dof = def.bones[j].dofs[k];
          angles[k] = std::uniform_real_distribution<float>(dof.minDeg, dof.maxDeg)(rise::test::Rng());
        }
        def.JointAngles(j, def.JointRotation(j, angles), back);
        for (int k = 0; k < n; ++k) {
          INFO(def.skeleton.joints[j].name << " dof " << k << ": " << angles[k] << " -> " << back[k]);
          CHECK(std::fabs(back[k] - angles[k]) < 0.01f);
        }
        ++checked;
      }
    }
    CHECK(checked == 15 * 50);
  }

  TEST_CASE("a joint frame puts the DOF axes where the engine's joint types expect them") {
    const rise::BipedDef def = rise::MakeBipedDef(1.75f, 70.0f);
    for (int j = 0; j < def.skeleton.JointCount(); ++j) {
      const std::vector<rise::JointDof>& dofs = def.bones[j].dofs;
      const glm::quat f = def.JointFrame(j);
      INFO(def.skeleton.joints[j].name);
      if (dofs.size() == 1) CHECK_VEC3_NEAR(f * glm::vec3(1, 0, 0), dofs[0].axis, 1e-5f);
      if (dofs.size() >= 2) {
        CHECK_VEC3_NEAR(f * glm::vec3(0, 1, 0), dofs[0].axis, 1e-5f);
        // Universal joints need z = the second axis exactly (the engine's second angle is about B's z).
        const float along = glm::dot(f * glm::vec3(0, 0, 1), dofs[1].axis);
        CHECK(std::fabs(along - 1.0f) < 1e-5f + (dofs.size() == 3 ? 2.0f : 0.0f));
        CHECK(std::fabs(std::fabs(along) - 1.0f) < 1e-5f);
      }
      if (dofs.size() == 3) CHECK_VEC3_NEAR(f * glm::vec3(1, 0, 0), dofs[2].axis, 1e-5f);
    }
  }
}
