// SPDX-License-Identifier: MIT
#include "export/bvh_reader.h"
#include "test_support.h"

namespace {

// A root at (1, 2, 3) turned 90 degrees about Z, with a child 1 unit along +X
// whose own joint turns 90 degrees about Y, ending 1 unit further along +X.
constexpr const char* kArm = R"(HIERARCHY
ROOT base
{
  OFFSET 0 0 0
  CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation
  JOINT arm
  {
    OFFSET 1 0 0
    CHANNELS 3 Zrotation Xrotation Yrotation
    End Site
    {
      OFFSET 1 0 0
    }
  }
}
MOTION
Frames: 2
Frame Time: 0.5
1 2 3 90 0 0 0 0 0
1 2 3 90 0 0 0 0 90
)";

}  // namespace

TEST_SUITE("bvh_reader") {
  TEST_CASE("forward kinematics of a hand-computed two-bone chain") {
    rise::BvhMotion motion;
    REQUIRE(rise::ParseBvh(kArm, {}, "arm", motion) == "");
    CHECK(motion.names == std::vector<std::string>{"base", "arm", "arm_end"});
    CHECK(motion.parents == std::vector<int>{-1, 0, 1});
    CHECK(motion.frameTime == 0.5);
    REQUIRE(motion.FrameCount() == 2);
    // Frame 0: Z turn maps +X to +Y.
    CHECK_VEC3_NEAR(motion.positions[0][0], glm::vec3(1, 2, 3), 1e-5f);
    CHECK_VEC3_NEAR(motion.positions[0][1], glm::vec3(1, 3, 3), 1e-5f);
    CHECK_VEC3_NEAR(motion.positions[0][2], glm::vec3(1, 4, 3), 1e-5f);
    // Frame 1: the arm's Y turn maps its +X to -Z, which the root's Z turn keeps.
    CHECK_VEC3_NEAR(motion.positions[1][2], glm::vec3(1, 3, 2), 1e-5f);
  }
  TEST_CASE("channels compose in their written order") {
    // R = Rz(90) Rx(90) applied to the End Site offset (0, 1, 0): Rx takes it
    // to (0, 0, 1), Rz keeps it. With the order swapped, Rz first takes it to
    // (-1, 0, 0), which Rx keeps.
    const auto tip = [](const char* channels) {
      const std::string text = std::string("HIERARCHY\nROOT a\n{\n OFFSET 0 0 0\n CHANNELS 2 ") + channels +
                               "\n End Site\n {\n  OFFSET 0 1 0\n }\n}\nMOTION\nFrames: 1\nFrame Time: 1\n90 90\n";
      rise::BvhMotion motion;
      REQUIRE(rise::ParseBvh(text, {}, "order", motion) == "");
      return motion.positions[0][1];
    };
    CHECK_VEC3_NEAR(tip("Zrotation Xrotation"), glm::vec3(0, 0, 1), 1e-5f);
    CHECK_VEC3_NEAR(tip("Xrotation Zrotation"), glm::vec3(-1, 0, 0), 1e-5f);
  }
  TEST_CASE("centimetres and Z-up are converted to metres and Y-up") {
    rise::BvhMotion motion;
    REQUIRE(rise::ParseBvh(kArm, {rise::BvhUnits::kCentimetres, rise::BvhUp::kZ}, "arm", motion) == "");
    // File (1, 2, 3) cm Z-up is (0.01, 0.03, -0.02) m Y-up.
    CHECK_VEC3_NEAR(motion.positions[0][0], glm::vec3(0.01f, 0.03f, -0.02f), 1e-6f);
  }
  TEST_CASE("broken files are refused with a reason") {
    rise::BvhMotion motion;
    CHECK(rise::ParseBvh("ROOT a", {}, "x", motion).find("HIERARCHY") != std::string::npos);
    std::string shortMotion = kArm;
    shortMotion.resize(shortMotion.size() - 3);  // drop the last value
    CHECK(rise::ParseBvh(shortMotion, {}, "x", motion).find("fewer values") != std::string::npos);
    CHECK(rise::ParseBvh(std::string(kArm) + " 7\n", {}, "x", motion).find("more values") != std::string::npos);
    std::string unknown = kArm;
    unknown.replace(unknown.find("Zrotation Xrotation Yrotation\n    End"), 9, "Wrotation");
    CHECK(rise::ParseBvh(unknown, {}, "x", motion).find("unknown channel") != std::string::npos);
    CHECK(rise::ReadBvh("/nonexistent/x.bvh", {}, motion).find("cannot be opened") != std::string::npos);
  }
}
