// SPDX-License-Identifier: MIT
#include <cmath>
#include <glm/trigonometric.hpp>

#include "core/clip_quality.h"
#include "fixture_clips.h"
#include "test_support.h"

namespace {

using rise::test::RiseClip;
using rise::test::StandingClip;

const glm::vec3 kX(1, 0, 0);

const rise::EffectorSlip& SlipOf(const rise::QualityReport& report, const std::string& effector) {
  for (const auto& slip : report.slips) {
    if (slip.effector == effector) return slip;
  }
  FAIL("no slip entry for " << effector);
  return report.slips.front();
}

}  // namespace

TEST_SUITE("clip_quality") {
  TEST_CASE("a body turning from lying to standing about its heels passes every bar") {
    const rise::Clip clip = RiseClip(2.0, 1.0, 30.0);
    const rise::QualityReport report = rise::MeasureClip(clip);
    REQUIRE(report.error.empty());
    CHECK(report.standingHeadHeight == doctest::Approx(1.50).epsilon(1e-5));
    // Straight body 85 deg from vertical: head at 1.5 cos 85 + 0.06 sin 85 (the heel edge is 6 cm behind the joints).
    const double lying = glm::radians(85.0);
    CHECK(report.startHeadRatio ==
          doctest::Approx((1.5 * std::cos(lying) + 0.06 * std::sin(lying)) / 1.5).epsilon(1e-4));
    CHECK(report.startTrunkDeg == doctest::Approx(5.0).epsilon(1e-3));
    CHECK(report.startsLying);
    // The tilt bar (15 deg) is the last to hold: angle 85 (1 - t/2) <= 15 first at frame ceil(60 * 70/85) = 50.
    CHECK(report.timeToStand == doctest::Approx(50.0 / 30.0));
    CHECK(report.endsStanding);
    CHECK(report.headHeightRatio == doctest::Approx(1.0).epsilon(1e-5));
    CHECK(report.trunkTiltEnd == doctest::Approx(0.0).epsilon(1e-3));
    CHECK(std::fabs(report.footHeightEndL) < 1e-5);
    CHECK(std::fabs(report.footHeightEndR) < 1e-5);
    CHECK(report.maxPenetration < 1e-5);
    CHECK(report.penetrationOk);
    // The heels touch from the first frame to the last and turn about their own edge: no slide.
    CHECK(SlipOf(report, "foot_l").contacts == 1);
    CHECK(report.maxSlip < 1e-4);
    CHECK(SlipOf(report, "hand_l").contacts == 0);
    // Fastest joint: head_end, 1.751 m from the heel edge, at 85 deg per 2 s.
    CHECK(report.jumpJoint == "head_end");
    const double radius = std::sqrt(1.75 * 1.75 + 0.06 * 0.06);
    CHECK(report.maxJointJump ==
          doctest::Approx(2.0 * radius * std::sin(glm::radians(85.0 / 60.0) / 2.0) * 30.0).epsilon(1e-3));
    CHECK(report.jumpOk);
    CHECK(report.passed);
  }

  TEST_CASE("a rise shorter than the standing window does not end standing") {
    const rise::QualityReport report = rise::MeasureClip(RiseClip(2.0, 0.1, 30.0));
    // Stands from 1.67 s to 2.1 s: 0.43 s, short of the 0.5 s window.
    CHECK(report.timeToStand == doctest::Approx(50.0 / 30.0));
    CHECK_FALSE(report.endsStanding);
    CHECK_FALSE(report.passed);
  }

  TEST_CASE("a body that never stands starts lying and does not end standing") {
    rise::Clip clip = StandingClip(91);
    for (int f = 0; f < clip.FrameCount(); ++f) {
      rise::test::SetPlankPose(clip, f, glm::angleAxis(glm::radians(rise::test::kLyingDeg), kX));
    }
    const rise::QualityReport report = rise::MeasureClip(clip);
    CHECK(report.startsLying);
    CHECK_FALSE(report.endsStanding);
    CHECK(report.timeToStand < 0.0);
    CHECK(report.headHeightRatio < 0.4);
    CHECK(report.trunkTiltEnd == doctest::Approx(85.0).epsilon(1e-3));
    CHECK(report.penetrationOk);
    CHECK_FALSE(report.passed);
    CHECK(report.ToJson()["ends_standing"]["time_to_stand"].is_null());
  }

  TEST_CASE("a standing body does not start lying") {
    const rise::QualityReport report = rise::MeasureClip(StandingClip(31));
    CHECK_FALSE(report.startsLying);
    CHECK(report.startHeadRatio == doctest::Approx(1.0).epsilon(1e-5));
    CHECK(report.startTrunkDeg == doctest::Approx(90.0).epsilon(1e-4));
    CHECK(report.timeToStand == 0.0);
    CHECK(report.endsStanding);
    CHECK_FALSE(report.passed);
  }

  TEST_CASE("feet sliding 10 cm while planted fail the slip bar") {
    rise::Clip clip = StandingClip(31);
    for (int f = 0; f < 31; ++f) clip.rootTranslation[f].x += 0.10f * f / 30.0f;
    const rise::QualityReport report = rise::MeasureClip(clip);
    CHECK(SlipOf(report, "foot_l").slip == doctest::Approx(0.10).epsilon(1e-3));
    CHECK(SlipOf(report, "foot_r").slip == doctest::Approx(0.10).epsilon(1e-3));
    CHECK(SlipOf(report, "foot_l").contactStart == 0.0);
    CHECK(SlipOf(report, "foot_l").contactEnd == doctest::Approx(1.0));
    REQUIRE(SlipOf(report, "foot_l").overBar.size() == 1);
    CHECK(SlipOf(report, "foot_l").overBar[0].slip == doctest::Approx(0.10).epsilon(1e-3));
    CHECK(SlipOf(report, "foot_l").overBar[0].end == doctest::Approx(1.0));
    const nlohmann::json overBar = report.ToJson()["slip"]["effectors"]["foot_l"]["over_bar"];
    REQUIRE(overBar.size() == 1u);
    CHECK(overBar[0]["start"].get<double>() == 0.0);
    CHECK(overBar[0]["slip"].get<double>() == doctest::Approx(0.10).epsilon(1e-3));
    CHECK(report.maxSlip == doctest::Approx(0.10).epsilon(1e-3));
    CHECK_FALSE(report.slipOk);
    CHECK(report.jumpOk);
    const std::string summary = report.Summary();
    CHECK(summary.find("FAIL contact slip    worst 0.100 m (foot_") != std::string::npos);
    CHECK(summary.find(", contact 0.00-1.00 s)") != std::string::npos);
  }

  TEST_CASE("slip starts again from zero after the foot lifts") {
    // 3 cm slide, a 5 cm hop over frames 10-14 that also moves 3 cm, land, 3 cm slide.
    rise::Clip clip = StandingClip(30);
    for (int f = 0; f < 30; ++f) {
      clip.rootTranslation[f].x += 0.03f * (f < 10   ? f / 9.0f
                                            : f < 15 ? 1.0f + (f - 9) / 6.0f
                                                     : 2.0f + (f - 15) / 14.0f);
      if (f >= 10 && f < 15) clip.rootTranslation[f].y += 0.05f;
    }
    const rise::QualityReport report = rise::MeasureClip(clip);
    const rise::EffectorSlip& foot = SlipOf(report, "foot_l");
    CHECK(foot.contacts == 2);
    CHECK(foot.slip == doctest::Approx(0.03).epsilon(1e-3));
    CHECK(foot.overBar.empty());
    CHECK(report.slipOk);
  }

  TEST_CASE("a foot rolling over its toe edge is not sliding") {
    // Heel rises 30 deg about the toes' bottom front edge, which stays put.
    rise::Clip clip = StandingClip(31);
    const int foot = clip.skeleton.Find("foot_l");
    const glm::vec3 ankle = clip.skeleton.BindPositions()[foot];
    const glm::vec3 toeEdge(ankle.x, 0.0f, 0.18f);
    for (int f = 0; f < 31; ++f) {
      const glm::quat roll = glm::angleAxis(glm::radians(30.0f * f / 30.0f), kX);
      // Turn the whole body about the toe edge so the foot's box rolls on it.
      clip.rotations[0][f] = roll;
      clip.rootTranslation[f] = toeEdge + roll * (clip.skeleton.joints[0].restOffset - toeEdge);
    }
    const rise::QualityReport report = rise::MeasureClip(clip);
    CHECK(SlipOf(report, "foot_l").slip < 1e-4);
    CHECK(SlipOf(report, "foot_l").contacts == 1);
  }

  TEST_CASE("a body sinking 5 cm fails the penetration bar at its lowest box") {
    rise::Clip clip = StandingClip(31);
    for (int f = 0; f < 31; ++f) clip.rootTranslation[f].y -= 0.05f * f / 30.0f;
    const rise::QualityReport report = rise::MeasureClip(clip);
    CHECK(report.maxPenetration == doctest::Approx(0.05).epsilon(1e-3));
    CHECK(report.penetrationFrame == 30);
    CHECK(report.penetrationJoint == "foot_l");
    CHECK_FALSE(report.penetrationOk);
    CHECK(report.footHeightEndL == doctest::Approx(-0.05).epsilon(1e-3));
    // Sinking 5 cm leaves the feet 5 cm under: the standing bar's foot test fails too.
    CHECK_FALSE(report.endsStanding);
  }

  TEST_CASE("a forearm flipping in one frame is a teleport of the hand tip") {
    rise::Clip clip = StandingClip(31);
    const int forearm = clip.skeleton.Find("forearm_l");
    for (int f = 15; f < 31; ++f) clip.rotations[forearm][f] = glm::angleAxis(glm::radians(180.0f), kX);
    const rise::QualityReport report = rise::MeasureClip(clip);
    // hand_l_end is 0.26 + 0.17 m from the elbow: a half turn moves it 0.86 m.
    CHECK(report.jumpJoint == "hand_l_end");
    CHECK(report.jumpFrame == 15);
    CHECK(report.maxJointJumpMeters == doctest::Approx(0.86).epsilon(1e-4));
    CHECK(report.maxJointJump == doctest::Approx(0.86 * 30.0).epsilon(1e-4));
    CHECK_FALSE(report.jumpOk);
  }

  TEST_CASE("a jump just inside the bound of 10 m/s x frame time + 1 cm is no teleport") {
    rise::Clip clip = StandingClip(2);
    clip.rootTranslation[1].x += 10.0f / 30.0f + 0.0099f;
    CHECK(rise::MeasureClip(clip).jumpOk);
    clip.rootTranslation[1].x += 0.0002f;
    CHECK_FALSE(rise::MeasureClip(clip).jumpOk);
  }

  TEST_CASE("the fastest box: a forearm flipping in one frame swings the hand's box fastest") {
    rise::Clip clip = StandingClip(31);
    CHECK(rise::MeasureFastestBox(clip).speed == 0.0);
    CHECK(rise::MeasureFastestBox(clip).body == -1);
    const int forearm = clip.skeleton.Find("forearm_l");
    for (int f = 15; f < 31; ++f) clip.rotations[forearm][f] = glm::angleAxis(glm::radians(180.0f), kX);
    const rise::FastestBox fastest = rise::MeasureFastestBox(clip);
    CHECK(clip.skeleton.joints[fastest.body].name == "hand_l");
    CHECK(fastest.frame == 15);
    // The hand box's centre is 0.26 + 0.08 m from the elbow: a half turn moves it 0.68 m.
    CHECK(fastest.speed == doctest::Approx(0.68 * 30.0).epsilon(1e-4));
  }

  TEST_CASE("on a 10 deg slope the bars are measured against the slope plane") {
    rise::Clip clip = RiseClip();
    const glm::quat slope = glm::angleAxis(glm::radians(10.0f), kX);
    for (int f = 0; f < clip.FrameCount(); ++f) {
      clip.rotations[0][f] = slope * clip.rotations[0][f];
      clip.rootTranslation[f] = slope * clip.rootTranslation[f];
    }
    rise::QualityOptions options;
    options.groundNormal = slope * glm::vec3(0, 1, 0);
    const rise::QualityReport onSlope = rise::MeasureClip(clip, options);
    CHECK(onSlope.maxPenetration < 1e-5);
    CHECK(onSlope.maxSlip < 1e-4);
    CHECK(onSlope.headHeightRatio == doctest::Approx(1.0).epsilon(1e-5));
    // Upright to the slope is 10 deg from gravity's vertical.
    CHECK(onSlope.trunkTiltEnd == doctest::Approx(10.0).epsilon(1e-3));
    CHECK(onSlope.passed);
    // Against flat ground the toes, 24 cm ahead of the heel edge, dip 0.24 sin 10 deg below y = 0.
    const rise::QualityReport onFlat = rise::MeasureClip(clip);
    CHECK(onFlat.maxPenetration == doctest::Approx(0.24 * std::sin(glm::radians(10.0))).epsilon(1e-3));
    CHECK_FALSE(onFlat.penetrationOk);
  }

  TEST_CASE("a skeleton without boxes is measured on its joints") {
    rise::Clip clip = RiseClip();
    for (auto& joint : clip.skeleton.joints) joint.hasBox = false;
    const rise::QualityReport report = rise::MeasureClip(clip);
    REQUIRE(report.error.empty());
    // Head joint above the lowest foot joint (foot_l_end at 1 cm).
    CHECK(report.standingHeadHeight == doctest::Approx(1.49).epsilon(1e-5));
    CHECK(report.startsLying);
    CHECK(report.endsStanding);
  }

  TEST_CASE("a clip without a head joint cannot be measured") {
    rise::Clip clip = RiseClip();
    clip.skeleton.joints[clip.skeleton.Find("head")].name = "skull";
    const rise::QualityReport report = rise::MeasureClip(clip);
    CHECK(report.error.find("'head'") != std::string::npos);
    CHECK_FALSE(report.passed);
    CHECK(report.Summary().find("cannot measure") != std::string::npos);
    CHECK(report.ToJson()["error"] == report.error);
  }

  TEST_CASE("the JSON report and the summary carry the figures") {
    rise::Clip clip = RiseClip();
    const rise::QualityReport report = rise::MeasureClip(clip);
    const nlohmann::json json = report.ToJson();
    CHECK(json["passed"] == true);
    CHECK(json["ends_standing"]["time_to_stand"].get<double>() == doctest::Approx(report.timeToStand));
    CHECK(json["joint_jump"]["joint"] == "head_end");
    CHECK(json["slip"]["effectors"]["foot_r"]["contacts"] == 1);
    CHECK(json["penetration"]["max"].get<double>() == doctest::Approx(report.maxPenetration));
    // Figures are rounded to 1e-6: 50 / 30 s reads as 1.666667.
    CHECK(json["ends_standing"]["time_to_stand"].get<double>() == 1.666667);
    const std::string summary = report.Summary();
    CHECK(summary.find("PASS ends standing   stands from 1.67 s") != std::string::npos);
    CHECK(summary.find("PASS overall") != std::string::npos);
  }

  TEST_CASE("max position distance between two sequences") {
    const std::vector<std::vector<glm::vec3>> a{{{0, 0, 0}, {1, 1, 1}}, {{0, 1, 0}, {2, 2, 2}}};
    auto b = a;
    b[1][0] += glm::vec3(0.03f, 0.04f, 0.0f);
    b[0][1] += glm::vec3(0.0f, 0.01f, 0.0f);
    CHECK(rise::MaxPositionDistance(a, b).value() == doctest::Approx(0.05).epsilon(1e-4));
    CHECK(rise::MaxPositionDistance(a, a).value() == 0.0);
    b[1].pop_back();
    CHECK_FALSE(rise::MaxPositionDistance(a, b).has_value());
    const rise::Clip clip = RiseClip();
    const auto sequence = rise::JointPositionSequence(clip);
    REQUIRE(sequence.size() == static_cast<size_t>(clip.FrameCount()));
    CHECK_VEC3_NEAR(sequence[7][3], clip.WorldPositions(7)[3], 1e-6f);
  }
}
