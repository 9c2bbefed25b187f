// SPDX-License-Identifier: MIT
#include <sstream>

#include "export/biped_fixture.h"
#include "export/bvh_reader.h"
#include "export/bvh_writer.h"
#include "export/gltf_reader.h"
#include "export/gltf_writer.h"
#include "export/root_motion.h"
#include "test_support.h"

namespace {

int Count(const std::string& text, const std::string& what) {
  int n = 0;
  for (size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

// Largest distance over all frames and all joints (End Sites included) between
// the BVH read back and the glTF read back.
float MaxDistance(const rise::BvhMotion& bvh, const rise::Clip& gltf) {
  REQUIRE(bvh.FrameCount() == gltf.FrameCount());
  float worst = 0.0f;
  for (int f = 0; f < gltf.FrameCount(); ++f) {
    const auto positions = gltf.WorldPositions(f);
    for (int j = 0; j < gltf.skeleton.JointCount(); ++j) {
      const int b = bvh.Find(gltf.skeleton.joints[j].name);
      REQUIRE_MESSAGE(b >= 0, gltf.skeleton.joints[j].name);
      worst = std::max(worst, rise::test::Distance(bvh.positions[f][b], positions[j]));
    }
  }
  return worst;
}

}  // namespace

TEST_SUITE("bvh_writer") {
  TEST_CASE("hierarchy: one ROOT with 6 channels, ZXY joints, End Sites for head, hands and feet, frame timing") {
    const rise::Clip clip = rise::test::SwingClip(30.0, 2.0);
    const std::string text = rise::FormatBvh(clip);
    CHECK(text.rfind("HIERARCHY\nROOT pelvis\n", 0) == 0);
    CHECK(Count(text, "ROOT ") == 1);
    CHECK(Count(text, "JOINT ") == 15);
    CHECK(Count(text, "End Site") == 5);
    CHECK(Count(text, "CHANNELS 6 Xposition Yposition Zposition Zrotation Xrotation Yrotation") == 1);
    CHECK(Count(text, "CHANNELS 3 Zrotation Xrotation Yrotation") == 15);
    CHECK(text.find("JOINT head_end") == std::string::npos);
    CHECK(text.find("MOTION\nFrames: 61\nFrame Time: 0.0333333333\n") != std::string::npos);
    // Root OFFSET is the bind-pose pelvis position.
    CHECK(text.find("ROOT pelvis\n{\n  OFFSET 0 0.95 0\n") != std::string::npos);
    // 61 motion lines of 6 + 15 * 3 values.
    std::istringstream motion(text.substr(text.find("Frame Time:")));
    std::string line;
    std::getline(motion, line);
    int lines = 0;
    while (std::getline(motion, line)) {
      std::istringstream values(line);
      int n = 0;
      for (double v; values >> v;) ++n;
      CHECK(n == 51);
      ++lines;
    }
    CHECK(lines == 61);
  }
  TEST_CASE("read back, every joint is within 1 cm of the glTF at every frame, for metres/centimetres and Y/Z up") {
    rise::test::TempFolder folder;
    const rise::Clip clip = rise::test::SwingClip(30.0, 4.0);
    REQUIRE(rise::WriteGltf(clip, folder.File("swing.glb"), {rise::NamingPreset::kDefault, false}) == "");
    rise::Clip gltf;
    REQUIRE(rise::ReadGltf(folder.File("swing.glb"), gltf) == "");
    for (rise::BvhUnits units : {rise::BvhUnits::kMetres, rise::BvhUnits::kCentimetres}) {
      for (rise::BvhUp up : {rise::BvhUp::kY, rise::BvhUp::kZ}) {
        const rise::BvhOptions options{{units, up}, rise::NamingPreset::kDefault, false};
        const std::string path = folder.File("swing.bvh");
        REQUIRE(rise::WriteBvh(clip, path, options) == "");
        rise::BvhMotion bvh;
        REQUIRE(rise::ReadBvh(path, options.format, bvh) == "");
        CHECK(bvh.frameTime == doctest::Approx(1.0 / 30.0).epsilon(1e-9));
        CHECK(bvh.names.size() == 21);
        const float worst = MaxDistance(bvh, gltf);
        CAPTURE(worst);
        CHECK(worst < 0.01f);
        // The text rounding alone is far smaller than the 1 cm promise.
        CHECK(worst < 1e-4f);
      }
    }
  }
  TEST_CASE("the file really is in the chosen units and axes") {
    const rise::Clip clip = rise::test::SwingClip(30.0, 1.0);
    const std::string cmZ = rise::FormatBvh(clip, {{rise::BvhUnits::kCentimetres, rise::BvhUp::kZ}, {}, false});
    // Pelvis bind position (0, 0.95, 0) m Y-up is (0, 0, 95) cm Z-up; the head
    // top 1.75 m up; the character faces -Y, so the left thigh is at +X.
    CHECK(cmZ.find("ROOT pelvis\n{\n  OFFSET 0 0 95\n") != std::string::npos);
    CHECK(cmZ.find("JOINT thigh_l\n  {\n    OFFSET 9 0 -7\n") != std::string::npos);
    rise::BvhMotion asWritten;
    REQUIRE(rise::ParseBvh(cmZ, {}, "cmZ", asWritten) == "");
    // Read as if metres Y-up, the first frame's head top is 100x too far, along +Z.
    rise::BvhMotion right;
    REQUIRE(rise::ParseBvh(cmZ, {rise::BvhUnits::kCentimetres, rise::BvhUp::kZ}, "cmZ", right) == "");
    const int top = right.Find("head_end");
    const glm::vec3 p = right.positions[0][top];
    CHECK_VEC3_NEAR(asWritten.positions[0][top], glm::vec3(100.0f * p.x, -100.0f * p.z, 100.0f * p.y), 1e-3f);
  }
  TEST_CASE("Euler curves never jump by more than the motion between two frames") {
    // The root turns 8 rad over 10 s and tips over by 80 degrees: without
    // unwrapping, the angles would jump by 360 degrees.
    const rise::Clip clip = rise::test::SwingClip(30.0, 10.0);
    std::istringstream text(rise::FormatBvh(clip));
    std::string line;
    while (std::getline(text, line) && line.rfind("Frame Time:", 0) != 0) {
    }
    std::vector<double> previous;
    double worst = 0.0;
    while (std::getline(text, line)) {
      std::istringstream values(line);
      std::vector<double> frame;
      for (double v; values >> v;) frame.push_back(v);
      if (!previous.empty()) {
        for (size_t c = 0; c < frame.size(); ++c) {
          if (c < 3) continue;  // root position
          worst = std::max(worst, std::fabs(frame[c] - previous[c]));
        }
      }
      previous = frame;
    }
    CAPTURE(worst);
    CHECK(worst < 30.0);
  }
  TEST_CASE("an extracted root gives the pelvis 6 channels and still matches the clip") {
    const rise::Clip clip = rise::ApplyRootMotion(rise::test::SwingClip(30.0, 2.0), rise::RootMotion::kExtract);
    const std::string text = rise::FormatBvh(clip);
    CHECK(text.rfind("HIERARCHY\nROOT root\n", 0) == 0);
    CHECK(Count(text, "CHANNELS 6") == 2);
    rise::BvhMotion bvh;
    REQUIRE(rise::ParseBvh(text, {}, "extract", bvh) == "");
    CHECK(MaxDistance(bvh, clip) < 1e-4f);
  }
  TEST_CASE("mixamo names appear in the hierarchy and an unwritable path leaves no file") {
    rise::test::TempFolder folder;
    const rise::Clip clip = rise::test::SwingClip(30.0, 1.0);
    const std::string text = rise::FormatBvh(clip, {{}, rise::NamingPreset::kMixamo, false});
    CHECK(text.rfind("HIERARCHY\nROOT mixamorig:Hips\n", 0) == 0);
    CHECK(text.find("JOINT mixamorig:LeftUpLeg") != std::string::npos);
    CHECK(rise::WriteBvh(clip, folder.File("none/x.bvh")).find("does not exist") != std::string::npos);
    CHECK(folder.Files().empty());
  }
}
