// SPDX-License-Identifier: MIT
#include <filesystem>
#include <glm/trigonometric.hpp>

#include "core/clip_check.h"
#include "core/clip_output.h"
#include "fixture_clips.h"
#include "test_support.h"

namespace {

namespace fs = std::filesystem;

std::string Folder(const std::string& name) {
  const fs::path dir = fs::path(RISE_BINARY_DIR) / "test_clip_check" / name;
  fs::remove_all(dir);
  fs::create_directories(dir);
  return dir.string();
}

}  // namespace

TEST_SUITE("clip_check") {
  TEST_CASE("a rising clip written as glTF and BVH passes, the two files within a millimetre") {
    const std::string dir = Folder("pass");
    rise::ClipOutputOptions options;
    options.naming = rise::NamingPreset::kMixamo;
    options.bvh.units = rise::BvhUnits::kCentimetres;
    REQUIRE(rise::WriteClipFiles(rise::test::RiseClip(), {dir + "/c.glb", dir + "/c.bvh"}, options).empty());
    const rise::ClipCheck check = rise::CheckClipFiles(dir + "/c.glb", dir + "/c.bvh", options.bvh);
    REQUIRE(check.error.empty());
    CHECK(check.quality.passed);
    CHECK(check.hasBvh);
    CHECK(check.bvhJoints >= 16);  // paired by canonical name across the mixamo preset
    CHECK(check.bvhDistance < 0.001);
    CHECK(check.passed);
    CHECK(check.ToJson()["passed"] == true);
    CHECK(rise::MissedBars(check.quality).empty());
  }

  TEST_CASE("BVH units assumed wrong make the distance bar fail") {
    const std::string dir = Folder("units");
    rise::ClipOutputOptions options;
    options.bvh.units = rise::BvhUnits::kCentimetres;
    REQUIRE(rise::WriteClipFiles(rise::test::RiseClip(), {dir + "/c.glb", dir + "/c.bvh"}, options).empty());
    const rise::ClipCheck check = rise::CheckClipFiles(dir + "/c.glb", dir + "/c.bvh", rise::BvhFormat{});
    REQUIRE(check.error.empty());
    CHECK(check.bvhDistance > 1.0);  // read as metres, every offset is 100 times too long
    CHECK_FALSE(check.bvhOk);
    CHECK_FALSE(check.passed);
  }

  TEST_CASE("a clip that never stands names the missed bar") {
    const std::string dir = Folder("fail");
    REQUIRE(rise::WriteClipFiles(rise::test::StandingClip(30), {dir + "/c.glb"}, {}).empty());
    const rise::ClipCheck check = rise::CheckClipFiles(dir + "/c.glb");
    REQUIRE(check.error.empty());
    CHECK_FALSE(check.passed);
    CHECK(rise::MissedBars(check.quality) == "starts lying");
  }

  TEST_CASE("an unreadable file is an error, not a failed bar") {
    const rise::ClipCheck check = rise::CheckClipFiles("no/such/clip.glb");
    CHECK_FALSE(check.error.empty());
    CHECK(check.error.find("no/such/clip.glb") != std::string::npos);
    CHECK_FALSE(check.passed);
  }

  TEST_CASE("the ground of a rise-gen clip comes from its resolved input's slope") {
    rise::Clip clip = rise::test::StandingClip(2);
    clip.metadata.parametersJson = R"({"terrain": {"slope_deg": 10, "friction": 0.8}})";
    const rise::QualityOptions options = rise::QualityOptionsFor(clip);
    const glm::vec3 normal = glm::normalize(options.groundNormal);
    // The plane rises toward +Z: its normal leans back toward -Z by the slope angle.
    CHECK(normal.y == doctest::Approx(std::cos(glm::radians(10.0f))).epsilon(1e-5));
    CHECK(normal.z == doctest::Approx(-std::sin(glm::radians(10.0f))).epsilon(1e-5));
    clip.metadata.parametersJson = "{}";
    CHECK(rise::QualityOptionsFor(clip).groundNormal == glm::vec3(0, 1, 0));
  }
}
