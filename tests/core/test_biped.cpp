// SPDX-License-Identifier: MIT
// The biped in the physics world: masses, bind pose, lying start poses, state read-back, settling.
#include <cmath>
#include <glm/geometric.hpp>

#include "core/biped.h"
#include "core/input_json.h"
#include "test_support.h"

namespace {

constexpr rise::Posture kLying[] = {rise::Posture::kSupine, rise::Posture::kProne, rise::Posture::kSideLeft,
                                    rise::Posture::kSideRight};

rise::StartSpec Start(rise::Posture posture, double headingDeg = 0.0) {
  rise::StartSpec start;
  start.posture = posture;
  start.headingDeg = headingDeg;
  return start;
}

// Angle of the pelvis-to-chest line out of the ground plane, degrees.
float TrunkTiltDeg(const std::vector<rise::physics::Transform>& world, const rise::BipedDef& def,
                   const glm::vec3& normal) {
  const glm::vec3 trunk = glm::normalize(world[def.Find("chest")].position - world[def.Find("pelvis")].position);
  return std::asin(std::fabs(glm::dot(trunk, normal))) * 180.0f / 3.14159265f;
}

}  // namespace

TEST_SUITE("biped") {
  TEST_CASE("the world holds 16 bodies and 15 joints whose masses sum to the body mass") {
    const rise::BipedDef def = rise::MakeBipedDef(1.6f, 55.0f);
    rise::physics::World world;
    const rise::Biped biped(def, world, rise::BindPose(def), 0.8f);
    CHECK(world.BodyCount() == 16);
    CHECK(world.JointCount() == 15);
    float mass = 0.0f;
    for (int j = 0; j < def.skeleton.JointCount(); ++j) {
      CHECK(biped.BodyOf(j).IsValid() == def.skeleton.joints[j].hasBox);
      CHECK(biped.JointOf(j).IsValid() == (def.DofCount(j) > 0));
      if (biped.BodyOf(j).IsValid()) mass += world.GetMass(biped.BodyOf(j));
    }
    CHECK(std::fabs(mass - 55.0f) < 1e-4f * 55.0f);
  }

  TEST_CASE("bind pose: soles exactly on the ground, centre of mass at 0.55-0.57 of the height") {
    for (const float height : {1.5f, 1.75f, 1.95f}) {
      const rise::BipedDef def = rise::MakeBipedDef(height, 75.0f);
      rise::physics::World world;
      const rise::Biped biped(def, world, rise::BindPose(def), 0.8f);
      const rise::physics::PlaneShape ground = rise::GroundPlane(0.0);
      CHECK(std::fabs(biped.LowestCorner(ground)) < 1e-5f);
      for (const char* foot : {"foot_l", "foot_r"}) {
        const rise::physics::Transform& box = world.GetTransform(biped.BodyOf(def.Find(foot)));
        const float halfHeight = def.skeleton.joints[def.Find(foot)].box.halfExtents.y;
        CHECK(std::fabs(box.position.y - halfHeight) < 1e-5f);
      }
      const glm::vec3 com = biped.CenterOfMass();
      CHECK_VEC3_NEAR(com, def.BindCenterOfMass(), 1e-4f);
      CHECK(com.y / height > 0.55f);
      CHECK(com.y / height < 0.57f);
      // Read back, the bind pose is the identity everywhere and the head top is at the height.
      const std::vector<rise::physics::Transform> joints = biped.JointWorldTransforms();
      CHECK(joints[def.Find("head_end")].position.y == doctest::Approx(height).epsilon(1e-5));
      for (int j = 0; j < def.skeleton.JointCount(); ++j) {
        if (biped.JointOf(j).IsValid()) CHECK_QUAT_NEAR(biped.LocalRotation(j), glm::quat(1, 0, 0, 0), 1e-4f);
      }
    }
  }

  TEST_CASE("lying postures: lowest corner 5 mm above flat and sloped ground, trunk parallel to it") {
    const rise::BipedDef def = rise::MakeBipedDef(1.75f, 70.0f);
    for (const double slope : {0.0, 10.0}) {
      const rise::physics::PlaneShape ground = rise::GroundPlane(slope);
      for (const rise::Posture posture : kLying) {
        for (const double heading : {0.0, 45.0, -120.0}) {
          INFO("posture " << std::string(rise::PostureName(posture)) << " slope " << slope << " heading " << heading);
          const rise::BipedPose pose = rise::StartPose(def, Start(posture, heading), slope);
          CHECK(rise::LowestCorner(def, pose, ground) == doctest::Approx(rise::kGroundClearance).epsilon(1e-3));
          const std::vector<rise::physics::Transform> world = rise::JointWorldTransforms(def, pose);
          CHECK(TrunkTiltDeg(world, def, ground.normal) < 10.0f);
          // Which way the chest faces: up when supine, down when prone, along the ground on a side.
          const float facing = glm::dot(world[def.Find("chest")].rotation * glm::vec3(0, 0, 1), ground.normal);
          if (posture == rise::Posture::kSupine) CHECK(facing > 0.98f);
          if (posture == rise::Posture::kProne) CHECK(facing < -0.98f);
          if (posture == rise::Posture::kSideLeft || posture == rise::Posture::kSideRight)
            CHECK(std::fabs(facing) < 0.05f);
          // Lying on the left side puts the body's left (+X) down.
          const float left = glm::dot(world[def.Find("chest")].rotation * glm::vec3(1, 0, 0), ground.normal);
          if (posture == rise::Posture::kSideLeft) CHECK(left < -0.98f);
          if (posture == rise::Posture::kSideRight) CHECK(left > 0.98f);
        }
      }
    }
    // At heading 0 on flat ground, supine lies with the head toward -Z and prone toward +Z.
    const auto headDirection = [&](rise::Posture posture) {
      const auto world = rise::JointWorldTransforms(def, rise::StartPose(def, Start(posture), 0.0));
      return glm::normalize(world[def.Find("head_end")].position - world[def.Find("pelvis")].position);
    };
    CHECK(headDirection(rise::Posture::kSupine).z < -0.99f);
    CHECK(headDirection(rise::Posture::kProne).z > 0.99f);
    CHECK(headDirection(rise::Posture::kSideLeft).x > 0.99f);
  }

  TEST_CASE("custom posture: root Euler angles, joint angles and drop height are applied") {
    const rise::BipedDef def = rise::MakeBipedDef(1.75f, 70.0f);
    rise::StartSpec start;
    start.posture = rise::Posture::kCustom;
    start.rootEulerDeg = {-90.0, 30.0, 0.0};
    start.jointsDeg["shin_l"] = {70.0};
    start.jointsDeg["thigh_r"] = {40.0, 10.0};
    start.dropHeightM = 0.4;
    const rise::BipedPose pose = rise::StartPose(def, start, 0.0);
    CHECK(rise::LowestCorner(def, pose, rise::GroundPlane(0.0)) == doctest::Approx(0.405f).epsilon(1e-4));
    const glm::quat expectedRoot = glm::angleAxis(glm::radians(-90.0f), glm::vec3(1, 0, 0)) *
                                   glm::angleAxis(glm::radians(30.0f), glm::vec3(0, 1, 0));
    CHECK_QUAT_NEAR(pose.root.rotation, expectedRoot, 1e-5f);
    const float knee = 70.0f;
    CHECK_QUAT_NEAR(pose.local[def.Find("shin_l")], def.JointRotation(def.Find("shin_l"), &knee), 1e-6f);
    // Joints not listed stay at the bind pose (custom has no angles of its own).
    CHECK_QUAT_NEAR(pose.local[def.Find("forearm_l")], glm::quat(1, 0, 0, 0), 1e-6f);
  }


  TEST_CASE("self overlap: none standing, shallow in the lying postures, deep with the legs crossed through each other") {
    const rise::BipedDef def = rise::MakeBipedDef(1.75f, 70.0f);
    CHECK_FALSE(rise::DeepestSelfOverlap(def, rise::BindPose(def)).has_value());
    for (const rise::Posture posture : kLying) {
      const std::optional<rise::SelfOverlap> overlap = rise::DeepestSelfOverlap(def, rise::StartPose(def, Start(posture), 0.0));
      CAPTURE(static_cast<int>(posture));
      CHECK((!overlap || overlap->depthM <= rise::kMaxStartOverlapM));
    }
    rise::StartSpec start;
    start.posture = rise::Posture::kCustom;
    start.jointsDeg["thigh_l"] = {-19.0, -18.0};
    start.jointsDeg["shin_l"] = {143.0};
    start.jointsDeg["thigh_r"] = {-25.0, -15.0};
    const std::optional<rise::SelfOverlap> crossed = rise::DeepestSelfOverlap(def, rise::StartPose(def, start, 0.0));
    REQUIRE(crossed.has_value());
    CHECK(crossed->boxA == "thigh_l");
    CHECK(crossed->boxB == "thigh_r");
    CHECK(crossed->depthM == doctest::Approx(0.144f).epsilon(0.05));
    // The trunk's boxes pass through the limbs' by design: an arm folded into the chest is no overlap.
    start.jointsDeg = {{"upper_arm_l", {0.0, -20.0}}};
    const std::optional<rise::SelfOverlap> arm = rise::DeepestSelfOverlap(def, rise::StartPose(def, start, 0.0));
    CHECK((!arm || arm->boxA.rfind("upper_arm", 0) != 0 || arm->boxB == "head"));
  }
  TEST_CASE("the engine's joint angles read back as the skeleton local rotations of the pose") {
    const rise::BipedDef def = rise::MakeBipedDef(1.75f, 70.0f);
    rise::StartSpec start;
    start.posture = rise::Posture::kCustom;
    start.rootEulerDeg = {-70.0, 20.0, 10.0};
    start.jointsDeg = {{"abdomen", {20, -10, 15}}, {"head", {-30, 20, 50}}, {"upper_arm_l", {100, 40}},
                       {"forearm_l", {90}},        {"hand_r", {30, -20}},   {"thigh_r", {60, -20}},
                       {"shin_r", {110}},          {"foot_l", {-40, 20}}};
    const rise::BipedPose pose = rise::StartPose(def, start, 0.0);
    rise::physics::World world;
    const rise::Biped biped(def, world, pose, 0.8f);
    const rise::BipedPose back = biped.Pose();
    CHECK(rise::test::Distance(back.root.position, pose.root.position) < 1e-5f);
    CHECK_QUAT_NEAR(back.root.rotation, pose.root.rotation, 2e-3f);
    for (int j = 1; j < def.skeleton.JointCount(); ++j) {
      INFO(def.skeleton.joints[j].name);
      // 2e-3 rad is the resolution of a float quaternion's angle near zero (acos of a dot near 1).
      CHECK_QUAT_NEAR(back.local[j], pose.local[j], 2e-3f);
      if (biped.JointOf(j).IsValid()) CHECK_QUAT_NEAR(biped.LocalRotation(j), pose.local[j], 2e-3f);
    }
  }

  TEST_CASE("released in each posture, and dropped from 0.3 m, the limp biped comes to rest on the ground") {
    const rise::BipedDef def = rise::MakeBipedDef(1.75f, 70.0f);
    struct Case {
      rise::Posture posture;
      double slope;
      double dropHeight;
      float maxDepth;  // m; a 0.3 m fall lands at 2.4 m/s, so the soft contact may give a little more
    };
    const Case cases[] = {{rise::Posture::kSupine, 0.0, 0.0, 0.01f},   {rise::Posture::kProne, 0.0, 0.0, 0.01f},
                          {rise::Posture::kSideLeft, 0.0, 0.0, 0.01f}, {rise::Posture::kSideRight, 0.0, 0.0, 0.01f},
                          {rise::Posture::kSupine, 10.0, 0.0, 0.01f},  {rise::Posture::kProne, 10.0, 0.0, 0.01f},
                          {rise::Posture::kSideLeft, 0.0, 0.3, 0.02f}, {rise::Posture::kProne, 0.0, 0.3, 0.02f}};
    for (const Case& c : cases) {
      INFO("posture " << std::string(rise::PostureName(c.posture)) << " slope " << c.slope << " drop " << c.dropHeight);
      rise::StartSpec start = Start(c.posture, 30.0);
      start.dropHeightM = c.dropHeight;
      rise::TerrainSpec terrain;
      terrain.slopeDeg = c.slope;
      rise::physics::World world(rise::BipedWorldSettings());
      rise::AddGround(world, terrain);
      const rise::Biped biped(def, world, rise::StartPose(def, start, c.slope), static_cast<float>(terrain.friction));
      const rise::physics::PlaneShape ground = rise::GroundPlane(c.slope);
      float deepest = 1.0f;
      bool healthy = true;
      const int steps = static_cast<int>(3.0f / world.Settings().timeStep);
      for (int step = 0; step < steps && healthy; ++step) {
        healthy = world.Step().Ok();
        deepest = std::min(deepest, biped.LowestCorner(ground));
      }
      CHECK(healthy);
      CHECK(deepest > -c.maxDepth);
      CHECK(std::isfinite(biped.CenterOfMass().y));
      CHECK(biped.MaxBodySpeed() < 0.05f);
      // At rest the body lies on the ground: its lowest corner is within a centimetre of it.
      CHECK(std::fabs(biped.LowestCorner(ground)) < 0.01f);
      // Every joint stays inside its limits (plus the solver's softness, 2 deg); knees and elbows
      // thus still bend one way only.
      for (int j = 0; j < def.skeleton.JointCount(); ++j) {
        if (def.DofCount(j) == 0) continue;
        float angles[3] = {};
        def.JointAngles(j, biped.LocalRotation(j), angles);
        for (int k = 0; k < def.DofCount(j); ++k) {
          INFO(def.skeleton.joints[j].name << " dof " << k << " " << angles[k]);
          CHECK(angles[k] > def.bones[j].dofs[k].minDeg - 2.0f);
          CHECK(angles[k] < def.bones[j].dofs[k].maxDeg + 2.0f);
        }
      }
    }
  }
}
