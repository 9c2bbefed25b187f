// SPDX-License-Identifier: MIT
#include "core/generate.h"
#include "core/clip_quality.h"
#include "core/input_json.h"
#include "test_support.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cstring>
#include <string>

namespace {

rise::RiseSpec ProneSpec(double seconds) {
  rise::RiseSpec spec;
  spec.start.posture = rise::Posture::kProne;
  spec.maxDurationS = seconds;
  return spec;
}

bool SameClip(const rise::Clip& a, const rise::Clip& b) {
  if (a.FrameCount() != b.FrameCount() || a.rotations.size() != b.rotations.size()) return false;
  if (std::memcmp(a.rootTranslation.data(), b.rootTranslation.data(), a.rootTranslation.size() * sizeof(glm::vec3))) {
    return false;
  }
  for (size_t j = 0; j < a.rotations.size(); ++j) {
    if (std::memcmp(a.rotations[j].data(), b.rotations[j].data(), a.rotations[j].size() * sizeof(glm::quat))) return false;
  }
  return true;
}

}  // namespace

TEST_SUITE("generate") {
TEST_CASE("two runs of the same spec give bit-identical clips") {
  const rise::GeneratedClip a = rise::GenerateClip(ProneSpec(3.0));
  const rise::GeneratedClip b = rise::GenerateClip(ProneSpec(3.0));
  CHECK(a.health.ok);
  CHECK(SameClip(a.clip, b.clip));
  CHECK(a.clip.metadata.parametersJson == b.clip.metadata.parametersJson);
}

TEST_CASE("a prone body settles, places its hands and feet and pushes up onto them") {
  rise::GenerateSettings settings;
  settings.keepTrace = true;
  const rise::GeneratedClip result = rise::GenerateClip(ProneSpec(4.0), settings);
  REQUIRE(result.health.ok);
  CHECK(result.clip.Validate().empty());
  // 4 s at 30 fps: frames 0..120, the last one at the end of the run.
  CHECK(result.clip.FrameCount() == 121);
  std::vector<std::string> phases;
  for (const rise::PhaseSpan& phase : result.clip.metadata.phases) phases.push_back(phase.name);
  REQUIRE(phases.size() >= 3);
  CHECK(phases[0] == "settle");
  CHECK(phases[1] == "place");
  CHECK(phases[2] == "push");
  // Pushed up: the CoM rose from lying (~0.1 m) most of the way to the crawl height (half the
  // standing CoM height; the push hands over to the crawl once the pelvis is within the tracking
  // tolerance of its goal, so a few cm short of it).
  const auto pushEnd = std::find_if(result.trace.begin(), result.trace.end(),
                                    [](const rise::TraceSample& s) { return s.phase == rise::RisePhase::kCrawl; });
  REQUIRE(pushEnd != result.trace.end());
  const float crawlHeight = 0.5f * rise::MakeBipedDef(rise::RiseSpec{}.character).BindCenterOfMass().y;
  CHECK(result.trace.front().com.y < 0.2f);
  CHECK(pushEnd->com.y > 0.75f * crawlHeight);
  // All four limbs bear weight in the bear stance the crawl starts from.
  for (bool touching : pushEnd->touching) CHECK(touching);
}

TEST_CASE("phase 2: from a deep squat on flat feet the body rises and stands still, upright, feet down") {
  // Knees 100 deg, ankles at 25 of their 30 deg of dorsiflexion, hips 115 of
  // 120 deg: a straight-line rise would need more ankle than there is, so
  // this holds the rise to its leg-angle path and the trunk lean.
  rise::RiseSpec spec;
  spec.start.posture = rise::Posture::kCustom;
  spec.start.rootEulerDeg = {40.0, 0.0, 0.0};
  spec.start.jointsDeg = {{"thigh_l", {115, 5}}, {"thigh_r", {115, 5}}, {"shin_l", {100}}, {"shin_r", {100}},
                          {"foot_l", {25, 0}},   {"foot_r", {25, 0}},   {"upper_arm_l", {40, 0}},
                          {"upper_arm_r", {40, 0}}};
  spec.maxDurationS = 8.0;
  const rise::GeneratedClip result = rise::GenerateClip(spec);
  REQUIRE(result.health.ok);
  CHECK(result.stood);
  CHECK(result.retries == 0);
  CHECK(result.timeToStand < 4.0);
  std::vector<std::string> phases;
  for (const rise::PhaseSpan& phase : result.clip.metadata.phases) phases.push_back(phase.name);
  CHECK(phases == std::vector<std::string>{"settle", "rise", "stand"});
  const rise::QualityReport quality = rise::MeasureClip(result.clip);
  CHECK(quality.endsStanding);
  CHECK(quality.penetrationOk);
  CHECK(quality.slipOk);
  CHECK(quality.jumpOk);
}

TEST_CASE("a body that keeps falling is let come to rest after its last retry, and the clip ends there") {
  // Steep, slippery ground: the crawl slides and falls again and again.
  rise::RiseSpec spec = ProneSpec(60.0);
  spec.terrain.friction = 0.5;
  spec.terrain.slopeDeg = 15.0;
  const rise::GeneratedClip result = rise::GenerateClip(spec);
  REQUIRE(result.health.ok);
  CHECK_FALSE(result.stood);
  CHECK(result.retries == 4);
  CHECK(result.clip.Duration() < 50.0);
  CHECK(result.outcome.find("fell 5 times") != std::string::npos);
  CHECK(result.clip.metadata.phases.back().name == "settle");
  // At rest: the last two frames hold the same pose.
  const size_t last = static_cast<size_t>(result.clip.FrameCount() - 1);
  CHECK(glm::length(result.clip.rootTranslation[last] - result.clip.rootTranslation[last - 1]) < 1e-3f);
}

TEST_CASE("metadata: phases tile the clip, contacts name effectors, peak torques stay under the caps") {
  const rise::RiseSpec spec = ProneSpec(3.0);
  const rise::GeneratedClip result = rise::GenerateClip(spec);
  const rise::ClipMetadata& meta = result.clip.metadata;
  REQUIRE(!meta.phases.empty());
  CHECK(meta.phases.front().start == 0.0);
  CHECK(meta.phases.back().end == doctest::Approx(result.clip.Duration()).epsilon(1e-9));
  for (size_t i = 1; i < meta.phases.size(); ++i) CHECK(meta.phases[i].start == meta.phases[i - 1].end);
  for (const rise::ContactSpan& contact : meta.contacts) {
    CHECK((contact.effector == "hand_l" || contact.effector == "hand_r" || contact.effector == "foot_l" ||
           contact.effector == "foot_r"));
    CHECK(contact.end >= contact.start);
  }
  const rise::BipedDef def = rise::MakeBipedDef(spec.character);
  CHECK(meta.peakTorques.size() == 15u);
  for (const auto& [joint, torque] : meta.peakTorques) {
    INFO(joint);
    CHECK(torque <= def.bones[def.Find(joint)].maxTorqueNm * 1.001);
  }
  CHECK(meta.seed == spec.seed);
  CHECK(rise::ParseRiseSpec(meta.parametersJson, "metadata").IsOk());
}

TEST_CASE("the trace has one sample per control step") {
  rise::GenerateSettings settings;
  settings.keepTrace = true;
  const rise::GeneratedClip result = rise::GenerateClip(ProneSpec(1.0), settings);
  CHECK(result.trace.size() == 241u);  // steps 0..240 at 240 Hz
  const std::string lines = rise::TraceToJsonLines(result.trace);
  CHECK(std::count(lines.begin(), lines.end(), '\n') == 241);
}
}
