// SPDX-License-Identifier: MIT
#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <string>
#include <vector>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <nlohmann/json.hpp>

#include "core/clip_check.h"
#include "core/clip_quality.h"
#include "core/generate.h"
#include "core/input_json.h"
#include "test_support.h"

namespace {

rise::RiseSpec ProneSpec(double seconds) {
  rise::RiseSpec spec;
  spec.start.posture = rise::Posture::kProne;
  spec.maxDurationS = seconds;
  return spec;
}

// The clip of an input file's text (which must load), its debug trace kept when asked.
rise::GeneratedClip Generate(const char* text, bool keepTrace = false) {
  const auto spec = rise::ParseRiseSpec(text, "start.json");
  REQUIRE(spec.IsOk());
  rise::GenerateSettings settings;
  settings.keepTrace = keepTrace;
  return rise::GenerateClip(spec.Value(), settings);
}

rise::GeneratedClip GenerateTraced(const char* text) { return Generate(text, true); }

// Checks that the clip of an input file's text (which must load) stands without a retry.
void CheckStandsAtFirstTry(const char* text) {
  INFO(std::string(text));
  const auto spec = rise::ParseRiseSpec(text, "start.json");
  REQUIRE(spec.IsOk());
  const rise::GeneratedClip result = rise::GenerateClip(spec.Value());
  INFO(result.outcome);
  CHECK(result.stood);
  CHECK(result.retries == 0);
}

// Checks that every push of a traced clip starts with both hands on the
// ground; returns how many pushes there were.
int PushesOnBothHands(const rise::GeneratedClip& result) {
  int pushes = 0;
  std::string previous;
  for (const rise::TraceSample& sample : result.trace) {
    if (sample.move == "push" && previous != "push") {
      ++pushes;
      INFO("push at " << sample.time << " s");
      CHECK(sample.touching[0]);
      CHECK(sample.touching[1]);
    }
    previous = sample.move;
  }
  return pushes;
}

// How many spans of the named phase the clip's timeline follows with a
// settle: tries that ended there in a fall.
// How many hands and feet touch the ground in a trace sample.
int Bearing(const rise::TraceSample& sample) {
  return static_cast<int>(std::count(sample.touching.begin(), sample.touching.end(), true));
}

int FallsIn(const rise::GeneratedClip& result, const std::string& phase) {
  const std::vector<rise::PhaseSpan>& phases = result.clip.metadata.phases;
  int falls = 0;
  for (size_t k = 1; k < phases.size(); ++k) falls += phases[k - 1].name == phase && phases[k].name == "settle";
  return falls;
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

// How a roll onto the front went, measured on the clip up to the first step of
// the place phase (the prone path from there on is not the roll's).
struct RollOutcome {
  double placeTime = -1.0;   // s; < 0 when the roll never handed over
  bool pushed = false;       // the push phase followed
  double penetration = 0.0;  // m, deepest box vertex below the ground
  double limbSpeed = 0.0;    // m/s, fastest hand or foot joint (or its end) between two steps
  double plantedSlip = 0.0;  // m, farthest a foot slid along the ground while planted and touching it
  double contactSlip = 0.0;  // m, farthest any hand or foot slid during one contact (rise::MeasureClip's slip bar)
  bool armTurned = false;    // an arm brought out from overhead was turned at the side
  double armOutClearance = -1.0;  // m, lowest the hand brought out came to the ground (the higher hand's lowest)
};

// The roll's cells: one start per posture that rolls, each on another body.
struct RollStart {
  rise::Posture posture;
  double heightM, massKg;
};
constexpr RollStart kRollStarts[] = {{rise::Posture::kSupine, 1.75, 70.0},
                                     {rise::Posture::kSideLeft, 1.5, 45.0},
                                     {rise::Posture::kSideRight, 1.95, 95.0}};

RollOutcome Roll(rise::Posture posture, double heightM, double massKg, const rise::StyleSpec& style = {}) {
  rise::RiseSpec spec;
  spec.character.heightM = heightM;
  spec.character.massKg = massKg;
  spec.start.posture = posture;
  spec.style = style;
  spec.fps = 240.0;  // the engine's rate: one frame per trace sample, so no fast step is missed
  spec.maxDurationS = 9.0;
  rise::GenerateSettings settings;
  settings.keepTrace = true;
  const rise::GeneratedClip result = rise::GenerateClip(spec, settings);
  REQUIRE(result.health.ok);
  REQUIRE(result.trace.size() == static_cast<size_t>(result.clip.FrameCount()));
  RollOutcome outcome;
  size_t place = result.trace.size();
  for (size_t i = 0; i < result.trace.size(); ++i) {
    if (result.trace[i].phase == rise::RisePhase::kPlace && place == result.trace.size()) place = i;
    if (result.trace[i].phase == rise::RisePhase::kPush) outcome.pushed = true;
  }
  if (place < result.trace.size()) outcome.placeTime = result.trace[place].time;
  std::array<float, 2> lowest{1e9f, 1e9f};
  for (const rise::TraceSample& sample : result.trace) {
    if (sample.move != "arm out" && sample.move != "arm turn") continue;
    outcome.armTurned = outcome.armTurned || sample.move == "arm turn";
    for (int h = 0; h < 2; ++h) lowest[h] = std::min(lowest[h], sample.clearance[h]);
  }
  if (outcome.armTurned) outcome.armOutClearance = std::max(lowest[0], lowest[1]);

  rise::Clip roll = result.clip;
  const size_t frames = std::min(place + 1, result.trace.size());
  roll.rootTranslation.resize(frames);
  for (auto& track : roll.rotations) track.resize(frames);
  for (auto& track : roll.translations) track.resize(std::min(track.size(), frames));
  roll.metadata = {};
  const rise::QualityReport quality = rise::MeasureClip(roll);
  outcome.penetration = quality.maxPenetration;
  outcome.contactSlip = quality.maxSlip;

  const rise::Skeleton& sk = roll.skeleton;
  const char* names[] = {"hand_l", "hand_r", "foot_l", "foot_r"};
  std::vector<glm::vec3> previous = roll.WorldPositions(0);
  // A planted foot's slide is followed on the point that touched when it was
  // planted (its lowest box corner then), as rise::MeasureClip follows contacts;
  // a foot that leaves the ground starts a new contact when it lands.
  std::array<int, 2> corner{-1, -1};
  std::array<glm::vec3, 2> plantedAt{};
  auto cornerOf = [&](int joint, int c, const std::vector<glm::vec3>& p, const std::vector<glm::quat>& q) {
    const rise::BoneBox& box = sk.joints[joint].box;
    const glm::vec3 sign((c & 1) ? 1.0f : -1.0f, (c & 2) ? 1.0f : -1.0f, (c & 4) ? 1.0f : -1.0f);
    return p[joint] + q[joint] * (box.center + sign * box.halfExtents);
  };
  for (size_t f = 1; f < frames; ++f) {
    const std::vector<glm::vec3> positions = roll.WorldPositions(static_cast<int>(f));
    const std::vector<glm::quat> rotations = roll.WorldRotations(static_cast<int>(f));
    for (const char* name : names) {
      for (const std::string& joint : {std::string(name), std::string(name) + "_end"}) {
        const int j = sk.Find(joint);
        outcome.limbSpeed =
            std::max(outcome.limbSpeed, static_cast<double>(glm::length(positions[j] - previous[j])) * roll.fps);
      }
    }
    for (int foot = 0; foot < 2; ++foot) {
      const int j = sk.Find(names[2 + foot]);
      if (!result.trace[f].planted[2 + foot] || !result.trace[f].touching[2 + foot]) {
        corner[foot] = -1;
        continue;
      }
      if (corner[foot] < 0) {
        for (int c = 0; c < 8; ++c) {
          if (corner[foot] < 0 ||
              cornerOf(j, c, positions, rotations).y < cornerOf(j, corner[foot], positions, rotations).y) {
            corner[foot] = c;
          }
        }
        plantedAt[foot] = cornerOf(j, corner[foot], positions, rotations);
      }
      glm::vec3 slide = cornerOf(j, corner[foot], positions, rotations) - plantedAt[foot];
      slide.y = 0.0f;
      outcome.plantedSlip = std::max(outcome.plantedSlip, static_cast<double>(glm::length(slide)));
    }
    previous = positions;
  }
  return outcome;
}

// A start run until the place phase takes over from the roll: when that was
// (< 0 if never), and whether a try went back to settle once the roll had begun.
struct RollOver {
  double placeTime = -1.0;
  bool retried = false;
};

RollOver RollOverFrom(rise::RiseSpec spec, double maxDurationS) {
  spec.maxDurationS = maxDurationS;
  rise::GenerateSettings settings;
  settings.keepTrace = true;
  const rise::GeneratedClip result = rise::GenerateClip(spec, settings);
  REQUIRE(result.health.ok);
  RollOver roll;
  bool rolling = false;
  for (const auto& sample : result.trace) {
    if (sample.phase == rise::RisePhase::kPlace) {
      roll.placeTime = sample.time;
      break;
    }
    rolling = rolling || sample.phase == rise::RisePhase::kRoll;
    roll.retried = roll.retried || (rolling && sample.phase == rise::RisePhase::kSettle);
  }
  return roll;
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

TEST_CASE("asking for the debug trace does not change the clip") {
  // The controller fills its trace only when asked (an IK solve and two support
  // hulls a step); what it plans must not depend on it.
  rise::GenerateSettings traced;
  traced.keepTrace = true;
  const rise::GeneratedClip a = rise::GenerateClip(ProneSpec(5.0), traced);
  const rise::GeneratedClip b = rise::GenerateClip(ProneSpec(5.0));
  CHECK(a.trace.size() > 1000u);
  CHECK(b.trace.empty());
  CHECK(SameClip(a.clip, b.clip));
}

TEST_CASE("a laid-down start begins at rest: the body lies still from the first frame until it moves to rise") {
  // Laid on the ground by its lowest corner, a body on its side touched down on
  // its top foot, dropped 5-7 cm onto its hip and crept 3-4 cm while the settle
  // held it, all recorded (the top foot's slide was 4 cm of the 5 cm bar before
  // the roll began). It now comes to rest before the clip's first frame, and the
  // settle in the clip is only the rest hold.
  for (const char* posture : {"supine", "prone", "side_left", "side_right"}) {
    INFO(posture);
    const std::string text = std::string(R"({"start":{"posture":")") + posture + R"("},"max_duration_s":2})";
    const rise::GeneratedClip result = GenerateTraced(text.c_str());
    REQUIRE(result.trace.size() > 1);
    const rise::TraceSample& first = result.trace.front();
    double settleEnd = -1.0;
    float fastest = 0.0f, furthest = 0.0f;  // the CoM's speed (m/s) and distance from where it lay (m)
    for (const rise::TraceSample& sample : result.trace) {
      if (sample.phase != rise::RisePhase::kSettle) {
        settleEnd = sample.time;
        break;
      }
      fastest = std::max(fastest, glm::length(sample.comVelocity));
      furthest = std::max(furthest, glm::distance(sample.com, first.com));
    }
    CHECK(fastest < 0.02f);
    CHECK(furthest < 0.003f);
    CHECK(settleEnd >= rise::RiseController::kRestHold);
    CHECK(settleEnd < rise::RiseController::kRestHold + 0.02);
  }
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
  // Knees 100 deg, ankles at 25 of the 35 deg of dorsiflexion the plan uses, hips 115 of
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

// Prone starts the whole controller brings to a stand (phase 0 place, hands
// down and push, phase 1 feet in, heels down and sit back, phase 2 rise),
// through the loader as the command line runs them. bench/prone_variants
// measures the rate over more starts (13 of 36 at 20 s). Which starts stand is
// chaotic: when the place learned to put the hands down at rest, the stands
// moved from the tallest bodies to these.
constexpr std::array<const char*, 4> kStandingStarts = {
    R"({"character":{"height_m":1.65,"mass_kg":62},"start":{"posture":"prone","heading_deg":37},"seed":2})",
    R"({"character":{"height_m":1.65,"mass_kg":55},"start":{"posture":"prone","heading_deg":259},"seed":8})",
    R"({"character":{"height_m":1.65,"mass_kg":97},"start":{"posture":"prone","heading_deg":121},"seed":14})",
    R"({"character":{"height_m":1.60,"mass_kg":76},"start":{"posture":"prone","heading_deg":168},"seed":25})"};

namespace {
// How many of the starts stand, through the loader as the command line runs
// them. The controller is chaotic (a millimetre early on changes which step
// follows), so the cases ask for three of four; each that stands must start
// lying, end standing still, keep every box above the ground and every joint
// within a body's speed, and (rolled) have rolled onto its front first.
int CountStanding(const std::array<const char*, 4>& starts, bool rolled) {
  int stood = 0;
  for (const char* text : starts) {
    INFO(std::string(text));
    const auto spec = rise::ParseRiseSpec(text, "start.json");
    REQUIRE(spec.IsOk());
    const rise::GeneratedClip result = rise::GenerateClip(spec.Value());
    REQUIRE(result.health.ok);
    if (!result.stood) continue;
    ++stood;
    if (rolled) {
      const std::vector<rise::PhaseSpan>& phases = result.clip.metadata.phases;
      CHECK(std::any_of(phases.begin(), phases.end(), [](const rise::PhaseSpan& phase) { return phase.name == "roll"; }));
    } else {
      CHECK(result.timeToStand < 18.0);
    }
    const rise::QualityReport quality = rise::MeasureClip(result.clip);
    CHECK(quality.startsLying);
    CHECK(quality.endsStanding);
    CHECK(quality.penetrationOk);
    CHECK(quality.jumpOk);
  }
  return stood;
}
}  // namespace

TEST_CASE("phases 0 to 2: lying prone, the body gets up on its hands and feet, brings its feet in and stands") {
  CHECK(CountStanding(kStandingStarts, false) >= 3);
}

TEST_CASE("a body standing at the end has stood, even one the time limit cuts off before it stands still") {
  // A clip ends early once the body has stood still for 1.2 s; one the time
  // limit cuts off sooner, standing, has stood once it has stood for the 0.5 s
  // the quality check measures. (It was reported as "did not stand", exit 1,
  // while the clip passed every bar: samples/prone.json cut 1.1 s into its
  // stand, and a heavy body swaying on a 10 deg slope that never came to rest.)
  const char* const text = R"({"start":{"posture":"prone"},"seed":2})";
  const auto spec = rise::ParseRiseSpec(text, "start.json");
  REQUIRE(spec.IsOk());
  const rise::GeneratedClip full = rise::GenerateClip(spec.Value());
  REQUIRE(full.stood);
  rise::RiseSpec cut = spec.Value();
  cut.maxDurationS = full.timeToStand + 0.85;  // 0.85 s into the stand: past the check's window, short of 1.2 s
  const rise::GeneratedClip result = rise::GenerateClip(cut);
  const rise::QualityReport quality = rise::MeasureClip(result.clip, rise::QualityOptionsFor(result.clip));
  INFO(result.outcome << ", clip " << result.clip.Duration() << " s");
  REQUIRE(quality.endsStanding);
  CHECK(result.clip.Duration() == doctest::Approx(cut.maxDurationS).epsilon(0.01));
  CHECK(result.stood);
  CHECK(result.timeToStand == doctest::Approx(full.timeToStand));
  // Before the window has passed it has not.
  cut.maxDurationS = full.timeToStand + 0.3;
  CHECK_FALSE(rise::GenerateClip(cut).stood);
}

TEST_CASE("a clip that stands ends on a still, neutral stand an engine can blend into its idle") {
  // Issue 5: the last frame is a still neutral stand. Still: over the last
  // 0.5 s no joint moves more than a standing body's sway (2.4 cm measured,
  // at the head's tip). Neutral: upright, every joint near its standing (bind)
  // rotation, arms at the sides.
  const auto spec = rise::ParseRiseSpec(kStandingStarts[0], "start.json");
  REQUIRE(spec.IsOk());
  const rise::GeneratedClip result = rise::GenerateClip(spec.Value());
  REQUIRE(result.stood);
  const rise::Clip& clip = result.clip;
  const int last = clip.FrameCount() - 1;
  const int window = static_cast<int>(0.5 * clip.fps);
  const std::vector<glm::vec3> end = clip.WorldPositions(last);
  float moved = 0.0f;
  std::string movedJoint;
  for (int f = last - window; f < last; ++f) {
    const std::vector<glm::vec3> at = clip.WorldPositions(f);
    for (size_t j = 0; j < end.size(); ++j) {
      const float distance = glm::length(at[j] - end[j]);
      if (distance > moved) moved = distance, movedJoint = clip.skeleton.joints[j].name;
    }
  }
  INFO("most moved joint " << movedJoint);
  CHECK(moved < 0.03f);
  float worst = 0.0f;
  std::string worstJoint;
  for (size_t j = 1; j < clip.rotations.size(); ++j) {
    const float angle = glm::degrees(2.0f * std::acos(std::min(1.0f, std::fabs(clip.rotations[j][static_cast<size_t>(last)].w))));
    if (angle > worst) worst = angle, worstJoint = clip.skeleton.joints[j].name;
  }
  INFO("most turned joint " << worstJoint << " " << worst << " deg from its standing rotation");
  CHECK(worst < 20.0f);
  const glm::vec3 up = clip.WorldRotations(last)[0] * glm::vec3(0, 1, 0);
  CHECK(glm::degrees(std::acos(std::min(1.0f, up.y))) < 10.0f);
  // The trunk upright too: with the pelvis over the ankles rather than the
  // balance point, the CoM stayed behind it and the hips held the trunk leaning
  // forward, pelvis to head 9.5 deg from vertical (16.7 deg, over the 15 deg
  // bar, in one of bench/prone_variants' 144 prone starts).
  const rise::QualityReport quality = rise::MeasureClip(clip, rise::QualityOptionsFor(clip));
  CHECK(quality.trunkTiltEnd < 2.0);
}

TEST_CASE("phase 2: hands let go in the rise swing down to the sides in their joints, not round over the head") {
  // The prone sample (samples/prone.json) rises from a chest folded down over
  // the knees, the arms overhead of it. Sent to the sides along a straight line
  // in the chest's frame, which passed through the shoulder, the IK's left arm
  // flipped from in front to behind half way, and the servos swung the hand up
  // over the head and down again at 9 m/s.
  const rise::GeneratedClip result = Generate(R"({"start":{"posture":"prone","heading_deg":0},"seed":2})");
  INFO(result.outcome);
  REQUIRE(result.stood);
  CHECK(rise::MeasureFastestBox(result.clip).speed < 4.0);
}

// Starts on the back and on either side: the roll turns the body prone (the
// arm it rolled over then comes out from overhead), then the same place, push, crawl
// and rise as the prone starts. (Their bear stance is longer than a prone
// start's, so the foot steps hold the CoM where it is when FootLiftCom would
// take the held foot out of reach.) The roll and the arm brought out add about
// 5 s, so these get 30 s. bench/prone_variants 36 at 30 s: 35 supine, 36
// side_left, 35 side_right stand (was 17, 13 and 19 when these were picked;
// 3 of the 4 stand).
// (Re-picked from the notes harness when the crawl began holding the shoulders
// back (session 10): the two supine starts then fell in the rise, while of 108
// rolled starts as many stood as before, 85 and 84.)
constexpr std::array<const char*, 4> kRolledStandingStarts = {
    R"({"character":{"height_m":1.60,"mass_kg":55},"start":{"posture":"supine","heading_deg":0},"seed":1,"max_duration_s":30})",
    R"({"character":{"height_m":1.60,"mass_kg":90},"start":{"posture":"supine","heading_deg":84},"seed":13,"max_duration_s":30})",
    R"({"character":{"height_m":1.75,"mass_kg":62},"start":{"posture":"side_left","heading_deg":195},"seed":16,"max_duration_s":30})",
    R"({"character":{"height_m":1.60,"mass_kg":90},"start":{"posture":"side_right","heading_deg":84},"seed":13,"max_duration_s":30})"};

TEST_CASE("phases 0 to 2: lying on the back or a side, the body rolls prone, gets up on its hands and feet and stands") {
  CHECK(CountStanding(kRolledStandingStarts, true) >= 3);
}

TEST_CASE("on a slope facing uphill the body stands upright, balanced along gravity, with every quality bar") {
  // Balance is over the feet along gravity, not the ground's normal: measured
  // along the normal, the CoM of a body standing on a 10 deg slope sat 16 cm
  // downhill of its feet and every rise fell down the slope.
  for (const char* text : {R"({"start":{"posture":"prone"},"terrain":{"slope_deg":8,"friction":0.9}})",
                           R"({"start":{"posture":"prone"},"terrain":{"slope_deg":10,"friction":0.9}})"}) {
    INFO(std::string(text));
    const rise::GeneratedClip result = GenerateTraced(text);
    REQUIRE(result.stood);
    const rise::QualityReport quality = rise::MeasureClip(result.clip, rise::QualityOptionsFor(result.clip));
    INFO("lying " << quality.startsLying << " standing " << quality.endsStanding << " ground " << quality.penetrationOk
                  << " slip " << quality.slipOk << " " << quality.maxSlip << " jump " << quality.jumpOk);
    CHECK(quality.passed);
    // At the end the CoM is straight above the soles (its vertical projection at
    // least 3 cm inside them), not merely above them along the ground's normal.
    REQUIRE_FALSE(result.trace.empty());
    CHECK(result.trace.back().feetDistance < -0.03f);
  }
}

TEST_CASE("standing across a slope, the body comes to rest and the clip ends") {
  // One foot uphill of the other: the stand's 1 s moves, each re-planned from
  // the measured (sagging) trunk with its balance integral reset, swung the CoM
  // 2 cm sideways at 1 Hz, so the still stand that ends a clip never came and
  // the clip ran on to max_duration_s, 15 s after the body stood.
  const auto spec = rise::ParseRiseSpec(
      R"({"start":{"posture":"prone","heading_deg":90},"terrain":{"slope_deg":10},"max_duration_s":30})", "start.json");
  REQUIRE(spec.IsOk());
  const rise::GeneratedClip result = rise::GenerateClip(spec.Value());
  INFO(result.outcome << ", clip " << result.clip.Duration() << " s");
  REQUIRE(result.stood);
  CHECK(result.clip.Duration() < result.timeToStand + 3.0);
}

TEST_CASE("on a slope, a squat short of its soles keeps its hands down until the rise has the CoM over them") {
  // Prone starts on 10 deg (bench/prone_variants 48, SLOPE=10, starts 13 and
  // 41): the rise began from the squat with the CoM 2-3 cm short of the soles
  // and let go of the ground at once; the body tipped forward on its face, and
  // its retries ran out of time. Held down until the rise's balance has the CoM
  // over the soles, the hands let go and it stands without a retry. (Start 13
  // replaced start 37 when a shorter body's lengths began to scale with it,
  // and start 23 replaced 13 when laid-down starts began at rest: 13 then fell
  // in its crawl and did not stand within 30 s. Starts 23 and 41 stand at the
  // first try; with the hands let go at once, neither does.)
  for (const char* text :
       {R"({"character":{"height_m":1.85,"mass_kg":69},"start":{"posture":"prone","heading_deg":131},"seed":24,"max_duration_s":30,"terrain":{"slope_deg":10}})",
        R"({"character":{"height_m":1.85,"mass_kg":97},"start":{"posture":"prone","heading_deg":77},"seed":42,"max_duration_s":30,"terrain":{"slope_deg":10}})"}) {
    CheckStandsAtFirstTry(text);
  }
}

TEST_CASE("a body under 1.45 m rises out of its squat at the first try: its margins and stance scale with it") {
  // Stress seeds 5283 and 9005 (1.43 and 1.41 m, slopes under 5 deg): planned with a 1.75 m
  // body's lengths, their rises out of the squat fell, backward (5283, the CoM going back at
  // 0.4 m/s as the rise began) or forward past the toes (9005), and neither stood. With the
  // lengths scaled to the body, both stand without a retry. (5283 is now the stress runner's
  // draw of today, whose pose differs in a few joints: the draw kept in this test since that
  // work stood at the first try until the roll's skid let-go (kSkidLimit) changed its path,
  // then toppled forward from standing, swaying, and stood at the second try.)
  for (const char* text :
       {R"({"character":{"height_m":1.425,"mass_kg":78.335},"fps":240.0,"seed":5283,"start":{"drop_height_m":0.453,"joints_deg":{"abdomen":[29.976,-0.745,-8.846],"chest":[7.252,12.338,-14.104],"foot_l":[17.273,7.738],"foot_r":[20.646,1.534],"forearm_l":[57.09],"forearm_r":[60.936],"hand_l":[-45.068,1.177],"hand_r":[70.453,4.706],"head":[32.805,-14.137,-31.245],"shin_l":[127.562],"shin_r":[114.846],"thigh_l":[58.699,20.515],"thigh_r":[-17.48,-23.577],"upper_arm_l":[142.969,33.914],"upper_arm_r":[162.75,24.873]},"posture":"custom","root_euler_deg":[-24.422,-142.891,-163.484]},"style":{"look_around":0.005,"speed":2.648,"stance_width_m":0.194,"step_height_m":0.269,"sway":0.812,"tiredness":0.027},"terrain":{"friction":0.824,"slope_deg":1.653}})",
        R"({"character":{"height_m":1.407,"mass_kg":61.895},"fps":240.0,"seed":9005,"start":{"drop_height_m":0.284,"joints_deg":{"abdomen":[0.556,-4.671,-7.284],"chest":[39.022,16.657,6.842],"foot_l":[7.943,-16.181],"foot_r":[6.684,8.349],"forearm_l":[41.449],"forearm_r":[91.714],"hand_l":[-35.438,15.325],"hand_r":[-4.577,-16.097],"head":[-27.238,0.08,1.164],"shin_l":[67.209],"shin_r":[37.549],"thigh_l":[-17.321,0.816],"thigh_r":[13.152,14.386],"upper_arm_l":[48.383,-5.246],"upper_arm_r":[-14.076,83.125]},"posture":"custom","root_euler_deg":[84.165,51.713,177.508]},"style":{"look_around":0.579,"speed":1.58,"stance_width_m":0.283,"step_height_m":0.079,"sway":0.346,"tiredness":0.839},"terrain":{"friction":0.358,"slope_deg":3.184}})"}) {
    CheckStandsAtFirstTry(text);
  }
}

TEST_CASE("the fastest style stands with every bar: the balancing phases keep a quasi-static pace") {
  // At speed 3 with every move 3x faster, 43 of 72 prone starts fell (crawl and
  // rise); these four among them. Push, crawl and rise go at most 1.5x.
  for (const char* text :
       {R"({"character":{"height_m":1.6,"mass_kg":55},"start":{"posture":"prone","heading_deg":0},"style":{"speed":3},"seed":1})",
        R"({"character":{"height_m":1.65,"mass_kg":62},"start":{"posture":"prone","heading_deg":37},"style":{"speed":3},"seed":2})",
        R"({"character":{"height_m":1.7,"mass_kg":69},"start":{"posture":"prone","heading_deg":74},"style":{"speed":3},"seed":3})",
        R"({"character":{"height_m":1.85,"mass_kg":90},"start":{"posture":"prone","heading_deg":185},"style":{"speed":3},"seed":6})"}) {
    INFO(std::string(text));
    const auto spec = rise::ParseRiseSpec(text, "start.json");
    REQUIRE(spec.IsOk());
    const rise::GeneratedClip result = rise::GenerateClip(spec.Value());
    REQUIRE(result.stood);
    // Still faster than the default pace, which stands at about 13 s.
    CHECK(result.timeToStand < 11.5);
    CHECK(rise::MeasureClip(result.clip, rise::QualityOptionsFor(result.clip)).passed);
  }
}

TEST_CASE("the slowest style crawls at pace 1: its other moves slow down, the crawl does not") {
  // Slower, a crawl stood longer on three limbs and slid (kMinCrawlPace): at
  // speed 0.5 the crawl took twice as long as at 1 and 35 of 60 prone starts
  // passed every bar; at pace 1, 45.
  auto secondsIn = [](const rise::Clip& clip, const std::string& phase) {
    double seconds = 0.0;
    for (const rise::PhaseSpan& span : clip.metadata.phases) {
      if (span.name == phase) seconds += span.end - span.start;
    }
    return seconds;
  };
  std::array<rise::Clip, 2> clips;
  const std::array<const char*, 2> speeds = {"1", "0.5"};
  for (int i = 0; i < 2; ++i) {
    const std::string text = std::string(R"({"character":{"height_m":1.6,"mass_kg":55},"start":{"posture":"prone"},"style":{"speed":)") +
                             speeds[i] + R"(},"seed":1,"max_duration_s":40})";
    INFO(text);
    const auto spec = rise::ParseRiseSpec(text, "start.json");
    REQUIRE(spec.IsOk());
    const rise::GeneratedClip result = rise::GenerateClip(spec.Value());
    REQUIRE(result.stood);
    clips[i] = result.clip;
  }
  const double crawl = secondsIn(clips[0], "crawl"), slowCrawl = secondsIn(clips[1], "crawl");
  const double push = secondsIn(clips[0], "push"), slowPush = secondsIn(clips[1], "push");
  INFO("crawl " << crawl << " s -> " << slowCrawl << " s, push " << push << " s -> " << slowPush << " s");
  REQUIRE(crawl > 1.0);
  CHECK(slowCrawl < 1.2 * crawl);
  CHECK(slowPush > 1.8 * push);
}

TEST_CASE("a hand let go of as the body sits back or rises, and a foot turned onto its toes at a slow pace, leave the ground without sliding") {
  // bench/prone_variants starts that slid 5.0-5.6 cm: the first two at the
  // tired style's pace as the place turned their feet (the toe edge came back
  // within 1 cm of the ground), the last two as the sit back lifted a hand the
  // arm then pulled back to where it was planted. Since the crawl goes at
  // least at pace 1 (kMinCrawlPace), the first two's right hand slid 5.1 cm
  // as the heels came down and the rise let go of it: unloaded but still
  // planted, it rolled onto its fingers and dragged them. Now the heels-down
  // hands over to the rise once the CoM is near the soles, and a hand let go
  // lifts straight up before it swings to the side.
  for (const char* text :
       {R"({"character":{"height_m":1.75,"mass_kg":76},"start":{"posture":"prone","heading_deg":111},"style":{"speed":0.8,"tiredness":0.6},"seed":4,"max_duration_s":40})",
        R"({"character":{"height_m":1.75,"mass_kg":69},"start":{"posture":"prone","heading_deg":333},"style":{"speed":0.8,"tiredness":0.6},"seed":10,"max_duration_s":40})",
        R"({"character":{"height_m":1.8,"mass_kg":97},"start":{"posture":"prone","heading_deg":178},"seed":35})",
        R"({"character":{"height_m":1.75,"mass_kg":90},"start":{"posture":"prone","heading_deg":9},"seed":118})"}) {
    INFO(std::string(text));
    const auto spec = rise::ParseRiseSpec(text, "start.json");
    REQUIRE(spec.IsOk());
    const rise::GeneratedClip result = rise::GenerateClip(spec.Value());
    REQUIRE(result.stood);
    const rise::QualityReport quality = rise::MeasureClip(result.clip, rise::QualityOptionsFor(result.clip));
    INFO("worst slide " << quality.maxSlip << " m (" << quality.maxSlipEffector << ")");
    CHECK(quality.passed);
  }
}

TEST_CASE("phase 2: a rise that stalls in its squat is planned again from there, not launched to the stand") {
  // Stress seed 5760 (issue 8): a tall, light, tired body on a 11.7 deg slope
  // stalled in a deep squat (pelvis 0.28 m short of its goal); the stand was
  // planned next, its goal the full height, and the servos threw the body
  // off its feet (CoM up at 2.4 m/s, a hand at 11.6 m/s), and it fell. Since
  // a push on one limb is a fall, that start no longer gets to its rise; seed
  // 5618 (1.71 m, 56 kg, as tired as can be, 11.9 deg) stalls so now: planned
  // on to the stand, its CoM went up at 1.4 m/s and it did not stand in 30 s.
  const rise::GeneratedClip result = GenerateTraced(
      R"({"character":{"height_m":1.714,"mass_kg":56.151},"fps":240,"seed":5618,"start":{"drop_height_m":0.758,"joints_deg":{"abdomen":[36.041,14.576,-17.288],"chest":[10.58,-15.919,21.967],"foot_l":[8.828,9.268],"foot_r":[-7.213,-12.786],"forearm_l":[28.833],"forearm_r":[87.454],"hand_l":[13.036,-33.427],"hand_r":[-57.449,-28.615],"head":[53.329,24.413,9.499],"shin_l":[99.926],"shin_r":[103.697],"thigh_l":[-19.011,-4.86],"thigh_r":[79.584,6.455],"upper_arm_l":[30.9,36.162],"upper_arm_r":[110.236,-6.449]},"posture":"custom","root_euler_deg":[-155.667,139.473,-138.148]},"style":{"look_around":0.224,"speed":1.779,"stance_width_m":0.455,"step_height_m":0.182,"sway":0.736,"tiredness":0.997},"terrain":{"friction":0.345,"slope_deg":11.877}})");
  REQUIRE_FALSE(result.trace.empty());
  float fastestRise = 0.0f;
  for (const rise::TraceSample& sample : result.trace) {
    if (sample.phase == rise::RisePhase::kRise || sample.phase == rise::RisePhase::kStand) {
      fastestRise = std::max(fastestRise, sample.comVelocity.y);
    }
  }
  const rise::FastestBox fastest = rise::MeasureFastestBox(result.clip);
  INFO(result.outcome << "; CoM up at " << fastestRise << " m/s; " << fastest.body << " at " << fastest.speed << " m/s");
  CHECK(fastestRise < 1.0f);
  CHECK(fastest.speed < 10.0);
  CHECK(result.stood);
}

TEST_CASE("phase 2: a rise leans against the CoM drifting off its heels and does not sit back down") {
  // Stress seed 9188 (issue 8), on an 8.7 deg slope: as the legs straightened
  // the CoM drifted backward off the heels and the body sat down (a retry;
  // it never stood within its 51 s).
  // Nearly every failed rise of the stress runs fell so; the balance goal now
  // moves against the capture point twice as far (kCaptureGain). (As the roll
  // was retuned, 9188 and its successor 5113 went otherwise. Stress seed 5741,
  // 1.62 m and 93 kg on 9.3 deg, rises at 17 s and stands at 19.5 s; with the
  // old gain its rise falls at 19.0 s, the CoM moving at 1.1 m/s, and it has
  // not stood by 40 s.)
  const auto spec = rise::ParseRiseSpec(
      R"({"character":{"height_m":1.615,"mass_kg":93.419},"fps":240.0,"seed":5741,"start":{"drop_height_m":0.662,"joints_deg":{"abdomen":[26.361,19.375,20.17],"chest":[25.095,11.694,-34.292],"foot_l":[-29.225,22.364],"foot_r":[-33.137,-15.605],"forearm_l":[37.913],"forearm_r":[145.084],"hand_l":[48.838,10.861],"hand_r":[68.113,-28.89],"head":[20.422,1.327,-49.869],"shin_l":[134.704],"shin_r":[47.183],"thigh_l":[58.733,32.933],"thigh_r":[15.363,5.005],"upper_arm_l":[72.814,63.699],"upper_arm_r":[157.436,2.957]},"posture":"custom","root_euler_deg":[38.896,-84.96,15.322]},"style":{"look_around":0.301,"speed":1.677,"stance_width_m":0.391,"step_height_m":0.055,"sway":0.332,"tiredness":0.359},"terrain":{"friction":0.856,"slope_deg":9.279},"max_duration_s":22})",
      "start.json");
  REQUIRE(spec.IsOk());
  const rise::GeneratedClip result = rise::GenerateClip(spec.Value());
  // The first rise goes on to the stand.
  const std::vector<rise::PhaseSpan>& phases = result.clip.metadata.phases;
  const auto firstRise = std::find_if(phases.begin(), phases.end(), [](const rise::PhaseSpan& span) { return span.name == "rise"; });
  REQUIRE(firstRise != phases.end());
  REQUIRE(firstRise + 1 != phases.end());
  const std::string afterRise = (firstRise + 1)->name;
  INFO(result.outcome);
  CHECK(afterRise == "stand");
  CHECK(result.retries == 0);
  CHECK(result.stood);
}

TEST_CASE("phase 1: a hand or foot its hip or shoulder cannot put down ends the try; it does not hang for the rest of the clip") {
  // Stress seed 105 (issue 8): a foot lifted 0.3 m and was put down again and
  // again toward a spot its hip could not take it to, for 25 s, until the
  // time ran out. Now a second put-down goes straight down with the CoM held,
  // and a fifth in a row counts as a failed try, which is retried.
  const rise::GeneratedClip result = GenerateTraced(
      R"({"character":{"height_m":1.801,"mass_kg":95.133},"seed":105,"start":{"drop_height_m":0.737,"joints_deg":{"abdomen":[-20.733,-10.335,6.318],"chest":[28.437,5.031,-30.249],"foot_l":[-11.708,-5.892],"foot_r":[3.016,-17.164],"forearm_l":[63.657],"forearm_r":[34.87],"hand_l":[40.449,14.523],"hand_r":[-36.618,-22.575],"head":[-10.158,-13.085,-23.862],"shin_l":[33.147],"shin_r":[10.756],"thigh_l":[20.112,40.414],"thigh_r":[37.841,40.737],"upper_arm_l":[91.821,84.709],"upper_arm_r":[74.613,-16.903]},"posture":"custom","root_euler_deg":[-145.394,152.449,-17.719]},"style":{"look_around":0.575,"speed":1.134,"stance_width_m":0.372,"step_height_m":0.182,"sway":0.389,"tiredness":0.37},"terrain":{"friction":0.922,"slope_deg":6.48}})");
  REQUIRE_FALSE(result.trace.empty());
  double longest = 0.0;
  for (int limb = 0; limb < rise::kLimbCount; ++limb) {
    double liftedSince = -1.0;
    for (const rise::TraceSample& sample : result.trace) {
      const bool aloft = sample.phase == rise::RisePhase::kCrawl && !sample.touching[limb];
      if (!aloft) liftedSince = -1.0;
      else if (liftedSince < 0.0) liftedSince = sample.time;
      else longest = std::max(longest, sample.time - liftedSince);
    }
  }
  INFO(result.outcome);
  CHECK(longest < 6.0);
}

TEST_CASE("phase 1: a body left on one hand or foot is falling: it goes limp as it settles, no limb whipped round") {
  // Stress seed 5189 (issue 8): on a 13.5 deg slope the body tipped over its
  // left hand in the crawl; its servos kept tracking the crawl, the right foot
  // swung up to 1.4 m, and the move planned from there brought it down at
  // 12.7 m/s, past the stress runner's 10 m/s bound. Now a crawl that rests on
  // one hand or foot, or none, is a fall: the settle holds the joints softly.
  // (Since a lifted swing keeps its own turn of the arm at the shoulder's 90 deg,
  // seed 5189 no longer tips so; then stress seed 5027's crawl did, and since
  // the place's skim clearance (kSkimClearance) stress seed 5108's, 1.72 m and
  // 61 kg on 11.3 deg, left on one limb at 9.4 s. Not re-checked with the rule
  // off.)
  const rise::GeneratedClip result = GenerateTraced(
      R"({"character":{"height_m":1.719,"mass_kg":61.067},"fps":240.0,"seed":5108,"start":{"drop_height_m":0.434,"joints_deg":{"abdomen":[2.45,-7.312,26.84],"chest":[-6.995,-9.657,-15.882],"foot_l":[34.842,-18.497],"foot_r":[21.233,12.529],"forearm_l":[91.408],"forearm_r":[30.153],"hand_l":[-30.96,-10.273],"hand_r":[42.702,1.631],"head":[-39.011,-33.909,66.889],"shin_l":[28.53],"shin_r":[133.138],"thigh_l":[94.928,44.766],"thigh_r":[36.412,22.429],"upper_arm_l":[9.195,95.494],"upper_arm_r":[0.076,35.082]},"posture":"custom","root_euler_deg":[-4.371,-106.696,-178.623]},"style":{"look_around":0.35,"speed":2.177,"stance_width_m":0.256,"step_height_m":0.025,"sway":0.589,"tiredness":0.338},"terrain":{"friction":0.823,"slope_deg":11.335},"max_duration_s":11.5})");
  REQUIRE(result.health.ok);
  REQUIRE(result.trace.size() == static_cast<size_t>(result.clip.FrameCount()));
  int fallsOffSupport = 0;
  for (size_t s = 1; s < result.trace.size(); ++s) {
    const rise::TraceSample& sample = result.trace[s];
    const int bearing = Bearing(sample);
    if (result.trace[s - 1].phase == rise::RisePhase::kCrawl && sample.phase == rise::RisePhase::kSettle && bearing <= 1) {
      ++fallsOffSupport;
    }
  }
  INFO(result.outcome);
  CHECK(fallsOffSupport >= 1);
  CHECK(rise::MeasureFastestBox(result.clip).speed < 8.0);
}

TEST_CASE("phase 0: a push left on one hand or foot is a fall: the body goes limp, no hand whipped round") {
  // Stress seed 5821 (issue 8): pushing up again after a caught rise, on a
  // 10 deg slope, the body slid away downhill on one hand at 1.6-1.9 m/s for
  // half a second while the push went on; the hand whipped to 11.2 m/s, past
  // the stress runner's 10 m/s bound. Now a push resting on one limb or none
  // is a fall. (As the roll was retuned, that start and its successors 5037
  // went otherwise, and then 5230 (pushed on without the rule, it had not stood
  // by 40 s). Since the place's skim clearance (kSkimClearance), stress seed
  // 5237, 1.76 m and 107 kg on 5.9 deg, falls in a push at 8.4 s and stands at
  // 27.5 s. Not re-checked with the rule off.)
  const rise::GeneratedClip result = Generate(
      R"({"character":{"height_m":1.761,"mass_kg":107.141},"fps":240.0,"seed":5237,"start":{"drop_height_m":0.957,"joints_deg":{"abdomen":[-19.004,2.966,-21.208],"chest":[30.514,-8.906,26.518],"foot_l":[-14.012,27.452],"foot_r":[-3.718,34.947],"forearm_l":[80.389],"forearm_r":[45.702],"hand_l":[31.359,-22.09],"hand_r":[79.047,-2.703],"head":[40.794,28.217,62.692],"shin_l":[48.282],"shin_r":[62.234],"thigh_l":[30.909,-19.109],"thigh_r":[100.39,34.361],"upper_arm_l":[-14.144,56.481],"upper_arm_r":[21.673,99.352]},"posture":"custom","root_euler_deg":[88.902,37.561,111.038]},"style":{"look_around":0.022,"speed":1.429,"stance_width_m":0.526,"step_height_m":0.296,"sway":0.65,"tiredness":0.935},"terrain":{"friction":0.32,"slope_deg":5.934},"max_duration_s":29})");
  REQUIRE(result.health.ok);
  const int pushesFallen = FallsIn(result, "push");
  const rise::FastestBox fastest = rise::MeasureFastestBox(result.clip);
  INFO(result.outcome << "; fastest " << fastest.speed << " m/s");
  CHECK(pushesFallen >= 1);
  CHECK(fastest.speed < 10.0);
  CHECK(result.stood);
}

TEST_CASE("phase 0: a push that starts on its hands alone, one of them dropping out of contact for a few steps, goes on") {
  // Stress seed 5556 (issue 8): on a 7.6 deg slope the push began on the two
  // hands with the feet still landing, and a hand at rest left contact for
  // 9 steps (37 ms). Called a fall at the first of them, the body lay down,
  // placed again and fell so five times, and never stood. A push is a fall
  // only after 0.1 s on one limb or none (kUnsupportedHold). (That start, then
  // 5086, have since gone otherwise; since the ankle's closest-turn clamp and
  // its 40 deg range, stress seed 5199's push; since the roll's skid let-go
  // (kSkidLimit), that of stress seed 5662, 1.60 m on 2 deg, which rests on
  // one limb or none for 6 steps and goes on. Not re-checked with the rule off.)
  const rise::GeneratedClip result = GenerateTraced(
      R"({"character":{"height_m":1.604,"mass_kg":93.317},"fps":240.0,"seed":5662,"start":{"drop_height_m":0.163,"joints_deg":{"abdomen":[44.49,16.483,29.553],"chest":[27.944,3.991,32.671],"foot_l":[-0.926,18.981],"foot_r":[-26.271,-6.416],"forearm_l":[149.659],"forearm_r":[87.605],"hand_l":[-17.252,6.027],"hand_r":[68.103,-31.346],"head":[19.356,-5.056,20.461],"shin_l":[21.498],"shin_r":[89.096],"thigh_l":[-12.994,13.991],"thigh_r":[106.22,9.68],"upper_arm_l":[-28.499,17.681],"upper_arm_r":[136.583,44.655]},"posture":"custom","root_euler_deg":[-8.723,123.13,-86.966]},"style":{"look_around":0.936,"speed":1.122,"stance_width_m":0.594,"step_height_m":0.107,"sway":0.375,"tiredness":0.417},"terrain":{"friction":1.2,"slope_deg":2.027},"max_duration_s":24})");
  REQUIRE(result.health.ok);
  int unsupported = 0;
  for (const rise::TraceSample& sample : result.trace) {
    const int bearing = Bearing(sample);
    if (sample.phase == rise::RisePhase::kPush && bearing <= 1) ++unsupported;
  }
  INFO(result.outcome);
  CHECK(unsupported > 0);
  CHECK(FallsIn(result, "push") == 0);
  CHECK(result.retries == 0);
  CHECK(result.stood);
}

TEST_CASE("phase 0: a place of a body tumbling down a slope is a fall: no limb whipped round with it") {
  // Stress seed 5789 (issue 8): in a late try on a 13.5 deg slope the body
  // rolled downhill at 2 m/s while it placed its hands and feet; the place
  // went on, its tracking error grew past 1 m, and a foot was whipped round
  // at 10.2 m/s, past the stress runner's 10 m/s bound. Now a place whose
  // CoM moves faster than 1.5 m/s with its pelvis 0.25 m or more from its
  // goal is a fall: the body goes limp and settles. (That start, then 5072,
  // have since gone otherwise, and then 9277; since the place's skim clearance
  // (kSkimClearance), stress seed 5019, 2.0 m and 77 kg on 8.9 deg, falls in a
  // place at 2.6 s. Not re-checked with the rule off.)
  const rise::GeneratedClip result = Generate(
      R"({"character":{"height_m":1.995,"mass_kg":76.708},"fps":240.0,"seed":5019,"start":{"drop_height_m":0.574,"joints_deg":{"abdomen":[40.164,21.704,18.502],"chest":[12.818,-10.253,-29.082],"foot_l":[-48.691,28.309],"foot_r":[22.0,-19.196],"forearm_l":[136.194],"forearm_r":[38.914],"hand_l":[-57.037,-18.677],"hand_r":[-52.679,-32.22],"head":[20.57,1.824,27.272],"shin_l":[74.268],"shin_r":[6.706],"thigh_l":[65.227,35.363],"thigh_r":[-1.68,-13.675],"upper_arm_l":[-29.159,24.807],"upper_arm_r":[-42.598,23.805]},"posture":"custom","root_euler_deg":[-1.822,67.348,3.92]},"style":{"look_around":0.272,"speed":2.27,"stance_width_m":0.366,"step_height_m":0.236,"sway":0.486,"tiredness":0.681},"terrain":{"friction":0.548,"slope_deg":8.865},"max_duration_s":5})");
  REQUIRE(result.health.ok);
  const int placesFallen = FallsIn(result, "place");
  const rise::FastestBox fastest = rise::MeasureFastestBox(result.clip);
  INFO(result.outcome << "; fastest " << fastest.body << " at " << fastest.speed << " m/s");
  CHECK(placesFallen >= 1);
  CHECK(fastest.speed < 10.0);
}

TEST_CASE("phase 0: a foot the place sends far swings there in its joints, not snapped round by the hip") {
  // Stress seed 5132 (issue 8): on an 11.2 deg slope a place sent the right
  // foot 1.27 m to its spot; along the ankle's path the hip's two angles
  // passed into another branch of their solution and the servos snapped the
  // leg round, the foot at 10.67 m/s (41.3 s), over the stress runner's
  // 10 m/s bound. A foot more than 0.8 m from its spot now swings there in
  // its joints, as an arm brought out from overhead does.
  const rise::GeneratedClip result = Generate(
      R"({"character":{"height_m":1.805,"mass_kg":121.668},"fps":240,"seed":5132,"max_duration_s":43,"start":{"drop_height_m":0.492,"joints_deg":{"abdomen":[-24.678,-13.669,-19.041],"chest":[17.088,-11.566,-5.239],"foot_l":[19.951,25.321],"foot_r":[-40.657,6.528],"forearm_l":[109.008],"forearm_r":[75.514],"hand_l":[25.322,10.759],"hand_r":[-3.911,10.942],"head":[-2.611,19.1,32.492],"shin_l":[63.773],"shin_r":[147.536],"thigh_l":[19.466,39.611],"thigh_r":[79.34,6.315],"upper_arm_l":[-28.529,25.687],"upper_arm_r":[23.431,50.657]},"posture":"custom","root_euler_deg":[-91.482,25.468,120.747]},"style":{"look_around":0.7,"speed":1.466,"stance_width_m":0.202,"step_height_m":0.189,"sway":0.757,"tiredness":0.977},"terrain":{"friction":0.38,"slope_deg":11.23}})");
  REQUIRE(result.health.ok);
  INFO(result.outcome);
  CHECK(rise::MeasureFastestBox(result.clip).speed < 9.5);
}

TEST_CASE("phase 2: a rise that tips forward off its toes is caught on the hands and goes on from all fours") {
  // Stress seed 80 (issue 8): a short, heavy, tired body rose from a squat
  // with its CoM at its toes, tipped forward and was counted as fallen while
  // its hands came down; the settle began a new rise at once, the CoM rocking
  // back at 0.3 m/s, and that one fell backward. Now the hands catch the tip
  // (both down before the push that follows) and the same try stands. The
  // start whose rise tips has moved as the controller changed (seed 80, then
  // 30 once landings were solved with exact joints, then 414 once the crawl
  // went at least at pace 1); since a lifted swing keeps its own turn of the
  // arm at the shoulder's 90 deg seed 5071's, and since the ankle's
  // closest-turn clamp and its 40 deg range stress seed 5047's, and since the
  // place's skim clearance (kSkimClearance) stress seed 5695's (1.50 m and
  // 93 kg on 8.1 deg, caught at 16.4 s, standing at 21.9 s; not re-checked
  // with the catch switched off).
  const rise::GeneratedClip result = GenerateTraced(
      R"({"character":{"height_m":1.496,"mass_kg":93.461},"fps":240.0,"seed":5695,"start":{"drop_height_m":0.801,"joints_deg":{"abdomen":[-17.216,3.74,11.279],"chest":[3.962,-13.947,-25.124],"foot_l":[-5.876,24.128],"foot_r":[-35.288,23.97],"forearm_l":[96.212],"forearm_r":[46.279],"hand_l":[-6.998,-7.237],"hand_r":[70.015,-30.186],"head":[20.433,-18.057,21.888],"shin_l":[133.84],"shin_r":[71.417],"thigh_l":[113.089,41.105],"thigh_r":[22.664,-5.526],"upper_arm_l":[-57.811,-1.097],"upper_arm_r":[160.896,28.418]},"posture":"custom","root_euler_deg":[-17.574,-13.241,171.637]},"style":{"look_around":0.867,"speed":2.001,"stance_width_m":0.188,"step_height_m":0.021,"sway":0.159,"tiredness":0.338},"terrain":{"friction":0.348,"slope_deg":8.087},"max_duration_s":23.5})");
  REQUIRE_FALSE(result.trace.empty());
  int catches = 0;
  std::string previous;
  for (const rise::TraceSample& sample : result.trace) {
    if (sample.move == "catch" && previous == "rise") ++catches;
    previous = sample.move;
  }
  const int pushes = PushesOnBothHands(result);
  INFO(result.outcome);
  CHECK(catches >= 1);
  CHECK(pushes >= 2);
  CHECK(result.retries == 0);
  CHECK(result.stood);
}

TEST_CASE("phase 2: a rise that topples off its feet is a fall while the pelvis is still up: no arm whipped round with it") {
  // Stress seed 9370 (issue 8): on a 9.2 deg slope a 2.04 m body toppled
  // sideways out of its rise. The rise went on toward its goal until the
  // pelvis came down, by then the CoM 1.1 m past the feet, and the servos
  // swung a hand round at 12.65 m/s, over the stress runner's 10 m/s bound.
  // A CoM 0.3 m past the feet and moving at 0.8 m/s or more is now a fall.
  // (That start, and then seeds 5043 and 5075, have since gone otherwise; since
  // a lifted swing keeps its own turn of the arm at the shoulder's 90 deg,
  // stress seed 5138's rise, and since the place's skim clearance
  // (kSkimClearance) stress seed 5334's, 1.46 m and 55 kg on 7.2 deg, topples
  // so at 16.3 s. Not re-checked with the rule off.)
  const rise::GeneratedClip result = GenerateTraced(
      R"({"character":{"height_m":1.458,"mass_kg":55.069},"fps":240.0,"seed":5334,"start":{"drop_height_m":0.538,"joints_deg":{"abdomen":[-13.815,6.522,-14.289],"chest":[37.254,-14.398,32.117],"foot_l":[-39.875,-16.469],"foot_r":[-40.964,-12.701],"forearm_l":[11.728],"forearm_r":[45.972],"hand_l":[-51.729,-0.535],"hand_r":[6.517,-2.01],"head":[-49.964,12.95,-55.818],"shin_l":[50.727],"shin_r":[103.234],"thigh_l":[82.858,16.425],"thigh_r":[26.112,48.749],"upper_arm_l":[69.641,99.133],"upper_arm_r":[114.838,36.359]},"posture":"custom","root_euler_deg":[-149.348,26.733,80.823]},"style":{"look_around":0.894,"speed":1.996,"stance_width_m":0.391,"step_height_m":0.057,"sway":0.533,"tiredness":0.773},"terrain":{"friction":0.996,"slope_deg":7.25},"max_duration_s":18})");
  REQUIRE(result.health.ok);
  REQUIRE_FALSE(result.trace.empty());
  // The rise that topples ends with the CoM just past the 0.3 m.
  float offFeetAtEnd = -1.0f;
  for (size_t s = 1; s < result.trace.size(); ++s) {
    const rise::TraceSample& sample = result.trace[s];
    if (sample.time > 16.0 && result.trace[s - 1].move == "rise" && sample.move != "rise") {
      offFeetAtEnd = sample.feetDistance;
      break;
    }
  }
  INFO(result.outcome);
  CHECK(offFeetAtEnd >= 0.3f);
  CHECK(offFeetAtEnd < 0.4f);
  CHECK(rise::MeasureFastestBox(result.clip).speed < 9.0);
}

TEST_CASE("phase 2: upright on staggered feet, the balance bends the knees to slide the pelvis and keeps the CoM over the feet") {
  // Stress seed 21 (issue 8): a heavy body stood up with its feet 24 cm apart
  // along a diagonal. Upright, the legs were straight, so the balance's pelvis
  // slide put the feet out of reach and shrank to 2-3 mm; the CoM crept off
  // the feet at 3-5 cm/s and the body fell from the stand at 26.7 s. With the
  // knees giving as the slide needs, the stand holds with the CoM inside.
  // Since landings are solved with exact joints, seed 21 lands otherwise;
  // seed 853 stands with its feet 22 cm apart along its heading.
  const rise::GeneratedClip result = GenerateTraced(
      R"({"character":{"height_m":1.956,"mass_kg":77.716},"seed":853,"start":{"drop_height_m":0.317,"joints_deg":{"abdomen":[18.182,0.684,-24.726],"chest":[18.358,-1.065,17.506],"foot_l":[25.501,3.62],"foot_r":[-49.966,24.813],"forearm_l":[54.406],"forearm_r":[15.446],"hand_l":[-48.361,-12.65],"hand_r":[49.926,-31.595],"head":[1.028,10.346,-57.792],"shin_l":[145.516],"shin_r":[23.788],"thigh_l":[9.606,15.186],"thigh_r":[20.829,10.47],"upper_arm_l":[96.76,63.226],"upper_arm_r":[-54.943,63.234]},"posture":"custom","root_euler_deg":[-35.766,24.391,-98.366]},"style":{"look_around":0.42,"speed":2.237,"stance_width_m":0.318,"step_height_m":0.029,"sway":0.912,"tiredness":0.941},"terrain":{"friction":0.457,"slope_deg":4.177}})");
  INFO(result.outcome);
  CHECK(result.stood);
  CHECK(result.retries == 0);
  float worst = -1.0f;  // the CoM's ground projection to the feet's soles, m (negative inside)
  int standing = 0;
  for (const rise::TraceSample& sample : result.trace) {
    if (sample.phase != rise::RisePhase::kStand) continue;
    worst = std::max(worst, sample.feetDistance);
    ++standing;
  }
  CHECK(standing > 240);
  CHECK(worst < -0.02f);
}

TEST_CASE("phase 0: a face-down start with an arm overhead brings it out round the side before the hands are placed") {
  // Stress seed 107 (issue 8): lying face down with the right arm overhead,
  // the place swung that hand toward its spot under the shoulder, the bent
  // elbow pressed into the ground, and the push started with the hand 12 cm
  // up; pushed up on one hand the body tipped over and had no time left to
  // stand. Now the arm comes out round the side first, as at a roll's end.
  const rise::GeneratedClip result = GenerateTraced(
      R"({"character":{"height_m":1.536,"mass_kg":55.924},"seed":107,"start":{"drop_height_m":0.193,"joints_deg":{"abdomen":[42.333,-24.59,9.616],"chest":[-2.702,12.603,16.489],"foot_l":[-28.72,6.128],"foot_r":[10.296,-13.004],"forearm_l":[1.197],"forearm_r":[43.895],"hand_l":[36.129,6.953],"hand_r":[-48.626,-5.284],"head":[-42.725,-22.921,10.337],"shin_l":[31.55],"shin_r":[122.428],"thigh_l":[-13.884,29.559],"thigh_r":[103.0,-25.474],"upper_arm_l":[75.004,5.585],"upper_arm_r":[86.365,46.634]},"posture":"custom","root_euler_deg":[-158.61,172.344,160.586]},"style":{"look_around":0.693,"speed":2.211,"stance_width_m":0.43,"step_height_m":0.221,"sway":0.901,"tiredness":0.768},"terrain":{"friction":1.082,"slope_deg":4.175}})");
  REQUIRE_FALSE(result.trace.empty());
  bool armOut = false;
  for (const rise::TraceSample& sample : result.trace) {
    armOut = armOut || (sample.move == "arm out" && sample.phase == rise::RisePhase::kRoll);
  }
  const int pushes = PushesOnBothHands(result);
  INFO(result.outcome);
  CHECK(armOut);
  CHECK(pushes >= 1);
  CHECK(result.stood);
}

TEST_CASE("phase 0: a place that ends with a hand astray of its spot places again before the push") {
  // Stress seed 5084 (issue 8): face down after a drop, the place's trunk
  // goal was out of reach (the pelvis lagged it by 0.3 m) and the place ended
  // on its stall with the left hand 22 cm out beside the shoulder; the hands
  // went down where they were, and the push tipped the body over that side
  // onto its seat, twice (it stood at 35 s, after two tries, past the 30 s
  // limit). Now a place that leaves a hand astray is tried again.
  const rise::GeneratedClip result = GenerateTraced(
      R"({"character":{"height_m":1.503,"mass_kg":49.548},"seed":5084,"start":{"drop_height_m":0.424,"joints_deg":{"abdomen":[-14.306,-12.218,-4.242],"chest":[25.499,-14.221,0.374],"foot_l":[12.836,23.134],"foot_r":[-16.791,19.6],"forearm_l":[117.922],"forearm_r":[25.437],"hand_l":[48.278,-14.19],"hand_r":[41.905,-4.344],"head":[-2.001,-13.185,55.912],"shin_l":[75.687],"shin_r":[34.111],"thigh_l":[84.463,42.54],"thigh_r":[95.841,-17.076],"upper_arm_l":[36.419,-0.735],"upper_arm_r":[40.217,31.073]},"posture":"custom","root_euler_deg":[91.806,35.143,91.908]},"style":{"look_around":0.179,"speed":2.884,"stance_width_m":0.579,"step_height_m":0.045,"sway":0.386,"tiredness":0.564},"terrain":{"friction":0.567,"slope_deg":1.391}})");
  REQUIRE_FALSE(result.trace.empty());
  int placedAgain = 0;
  float firstAstray = 0.0f;  // the first place's end: its hand farthest from its spot, along the ground, m
  std::string previous;
  for (size_t s = 0; s < result.trace.size(); ++s) {
    const rise::TraceSample& sample = result.trace[s];
    if (sample.move == "push") break;
    if (sample.move == "place again" && previous != "place again") ++placedAgain;
    const bool placeEnds = sample.move == "place" && (s + 1 == result.trace.size() || result.trace[s + 1].move != "place");
    if (placeEnds && placedAgain == 0) {
      for (int hand = 0; hand < 2; ++hand) {
        glm::vec3 off = sample.limbPositions[hand] - sample.limbTargets[hand];
        off.y = 0.0f;
        firstAstray = std::max(firstAstray, glm::length(off));
      }
    }
    previous = sample.move;
  }
  const int pushes = PushesOnBothHands(result);
  INFO(result.outcome);
  CHECK(firstAstray > 0.15f);
  CHECK(placedAgain >= 1);
  CHECK(pushes >= 1);
  CHECK(result.retries == 0);
  CHECK(result.stood);
}

TEST_CASE("phase 0: a hand the place left up comes out round the side before it is placed again") {
  // Stress seed 74 (issue 8): face down with the left arm folded in front of
  // the face, elbow on the ground and hand 19 cm up; placed again from there
  // it stayed folded through every place, the push went ahead on one hand
  // and the body fell. Now the raised arm comes out round the side first.
  // Since landings are solved with exact joints, seed 74 lands otherwise, and
  // since a lifted swing keeps its own turn of the arm at the shoulder's 90
  // deg, seed 41 does; stress seed 5015's place leaves a hand up the same way
  // (not re-checked with the arm out switched off).
  const rise::GeneratedClip result = GenerateTraced(
      R"({"character":{"height_m":1.757,"mass_kg":103.378},"fps":240.0,"seed":5015,"start":{"drop_height_m":0.839,"joints_deg":{"abdomen":[30.487,23.506,17.997],"chest":[-4.398,10.433,29.757],"foot_l":[-42.133,14.892],"foot_r":[-2.227,-17.951],"forearm_l":[93.928],"forearm_r":[48.591],"hand_l":[6.103,-27.824],"hand_r":[-57.032,-1.466],"head":[-25.035,-29.1,-49.817],"shin_l":[12.144],"shin_r":[82.8],"thigh_l":[73.384,-5.155],"thigh_r":[53.763,-0.436],"upper_arm_l":[159.583,54.286],"upper_arm_r":[151.599,-0.17]},"posture":"custom","root_euler_deg":[-74.397,-61.996,-109.444]},"style":{"look_around":0.752,"speed":2.605,"stance_width_m":0.361,"step_height_m":0.236,"sway":0.938,"tiredness":0.54},"terrain":{"friction":0.747,"slope_deg":2.84}})");
  REQUIRE_FALSE(result.trace.empty());
  bool outAfterHandsDown = false;
  std::string previous;
  for (const rise::TraceSample& sample : result.trace) {
    if (sample.move == "arm out" && previous == "hands down") {
      outAfterHandsDown = true;
      const bool leftUp = !sample.touching[0], rightUp = !sample.touching[1];
      CHECK((leftUp || rightUp));
    }
    previous = sample.move;
  }
  const int pushes = PushesOnBothHands(result);
  INFO(result.outcome);
  CHECK(outAfterHandsDown);
  CHECK(pushes >= 1);
  CHECK(result.stood);
}

TEST_CASE("phase 1: a hand or foot comes down from above its spot, not while still travelling along the ground") {
  // Prone starts of the notes harness (heading k*37 deg, seed k+1) in which a
  // swing lagging its path touched down at 1.4-2.8 m/s and slid; a swing is now
  // held aloft until it is over its spot (RiseController::HoldAloftUntilOver).
  constexpr std::array<const char*, 4> kStarts = {
      R"({"character":{"height_m":1.80,"mass_kg":83},"start":{"posture":"prone","heading_deg":148},"seed":5})",
      R"({"character":{"height_m":1.80,"mass_kg":62},"start":{"posture":"prone","heading_deg":94},"seed":23})",
      R"({"character":{"height_m":1.85,"mass_kg":69},"start":{"posture":"prone","heading_deg":131},"seed":24})",
      R"({"character":{"height_m":1.75,"mass_kg":97},"start":{"posture":"prone","heading_deg":279},"seed":28})"};
  for (const char* text : kStarts) {
    INFO(std::string(text));
    const auto spec = rise::ParseRiseSpec(text, "start.json");
    REQUIRE(spec.IsOk());
    const rise::Clip clip = rise::GenerateClip(spec.Value()).clip;
    int touchdowns = 0;
    for (const rise::ContactSpan& contact : clip.metadata.contacts) {
      const int frame = static_cast<int>(std::lround(contact.start * clip.fps));
      if (frame < 1 || frame >= clip.FrameCount()) continue;  // lying there from the start
      const int end = clip.skeleton.Find(contact.effector);
      REQUIRE(end >= 0);
      glm::vec3 step = clip.WorldPositions(frame)[end] - clip.WorldPositions(frame - 1)[end];
      step.y = 0.0f;
      INFO(contact.effector << " at " << contact.start << " s");
      CHECK(glm::length(step) * clip.fps < 1.2);
      ++touchdowns;
    }
    CHECK(touchdowns >= 8);
  }
}

TEST_CASE("phases 0 to 2: no hand or foot slides along the ground on the way up") {
  for (const char* text : kStandingStarts) {
    INFO(std::string(text));
    const auto spec = rise::ParseRiseSpec(text, "start.json");
    REQUIRE(spec.IsOk());
    const rise::QualityReport quality = rise::MeasureClip(rise::GenerateClip(spec.Value()).clip);
    INFO(quality.maxSlipEffector << " slid " << quality.maxSlip << " m");
    CHECK(quality.slipOk);
  }
}

TEST_CASE("every bundled sample starts lying, as the clip's first frame is measured") {
  // A sample dropped from too high starts in the air with its head over the
  // 40 % bar (custom.json from 0.3 m: 60 %), a clip that fails "starts lying".
  for (const char* name : rise::test::kSampleInputs) {
    INFO(name);
    const auto spec = rise::LoadRiseSpec(std::string(RISE_SOURCE_DIR) + "/samples/" + name + ".json");
    REQUIRE(spec.IsOk());
    rise::RiseSpec first = spec.Value();
    first.maxDurationS = 1.0;
    const rise::QualityReport quality = rise::MeasureClip(rise::GenerateClip(first).clip);
    INFO("head at " << quality.startHeadRatio << " of its standing height");
    CHECK(quality.startsLying);
  }
}

TEST_CASE("a drop lands with every box within 2 cm of the ground in the clip, joints closed by the exact solve") {
  // Stress starts (issue 8) dropped from 0.7-1 m whose landing showed a box 2.5-3.6 cm below the
  // ground in the clip while the engine had it under 1 cm: the impact opened the joints above
  // the limb, and the clip's bones carried each gap on. The settle now solves the joints exactly
  // (core/generate.cpp). Recorded at the step rate and cut off after the landing.
  for (const char* text : {
           R"({"character":{"height_m":1.72,"mass_kg":47.046},"seed":409,"fps":240,"max_duration_s":1.5,"start":{"drop_height_m":0.689,"joints_deg":{"abdomen":[39.312,-2.939,-6.997],"chest":[17.985,-9.556,-2.18],"foot_l":[17.789,14.126],"foot_r":[-43.07,26.634],"forearm_l":[99.848],"forearm_r":[58.64],"hand_l":[-66.666,-12.571],"hand_r":[50.425,-25.458],"head":[-10.839,-37.954,53.402],"shin_l":[41.381],"shin_r":[97.737],"thigh_l":[104.758,-7.528],"thigh_r":[11.681,5.765],"upper_arm_l":[154.875,77.374],"upper_arm_r":[169.24,86.61]},"posture":"custom","root_euler_deg":[-146.302,92.563,-117.509]},"style":{"look_around":0.423,"speed":0.787,"stance_width_m":0.386,"step_height_m":0.298,"sway":0.36,"tiredness":0.744},"terrain":{"friction":0.709,"slope_deg":12.117}})",
           R"({"character":{"height_m":2.006,"mass_kg":95.186},"seed":5101,"fps":240,"max_duration_s":1.5,"start":{"drop_height_m":0.957,"joints_deg":{"abdomen":[-22.733,24.254,-10.239],"chest":[11.885,-6.711,-13.693],"foot_l":[-9.036,-1.925],"foot_r":[-17.26,30.021],"forearm_l":[61.098],"forearm_r":[18.105],"hand_l":[-7.143,-9.743],"hand_r":[63.619,-25.097],"head":[45.2,5.393,-55.304],"shin_l":[1.274],"shin_r":[78.241],"thigh_l":[25.655,23.625],"thigh_r":[33.71,-27.488],"upper_arm_l":[-47.061,-12.283],"upper_arm_r":[126.876,52.724]},"posture":"custom","root_euler_deg":[25.96,-36.226,-10.001]},"style":{"look_around":0.714,"speed":2.459,"stance_width_m":0.299,"step_height_m":0.029,"sway":0.125,"tiredness":0.818},"terrain":{"friction":0.56,"slope_deg":10.456}})",
           R"({"character":{"height_m":1.706,"mass_kg":58.13},"seed":5860,"fps":240,"max_duration_s":1.5,"start":{"drop_height_m":0.836,"joints_deg":{"abdomen":[-0.688,-19.389,0.416],"chest":[-2.471,18.726,-34.711],"foot_l":[-23.606,-3.4],"foot_r":[-10.444,-18.633],"forearm_l":[149.933],"forearm_r":[31.411],"hand_l":[-39.908,16.369],"hand_r":[54.897,-8.826],"head":[0.624,-31.053,57.262],"shin_l":[78.089],"shin_r":[97.105],"thigh_l":[61.785,13.189],"thigh_r":[47.497,31.021],"upper_arm_l":[113.904,18.449],"upper_arm_r":[30.732,38.787]},"posture":"custom","root_euler_deg":[-21.04,154.755,-107.386]},"style":{"look_around":0.745,"speed":0.253,"stance_width_m":0.485,"step_height_m":0.15,"sway":0.015,"tiredness":0.998},"terrain":{"friction":1.009,"slope_deg":3.034}})"}) {
    const auto spec = rise::ParseRiseSpec(text, "start.json");
    REQUIRE(spec.IsOk());
    const rise::GeneratedClip result = rise::GenerateClip(spec.Value());
    const rise::QualityReport quality = rise::MeasureClip(result.clip, rise::QualityOptionsFor(result.clip));
    INFO("seed " << spec.Value().seed << ": " << quality.penetrationJoint << " " << quality.maxPenetration * 100.0
                 << " cm below the ground at frame " << quality.penetrationFrame);
    CHECK(result.health.ok);
    CHECK(quality.maxPenetration <= 0.02);
  }
}

TEST_CASE("a body that keeps falling is let come to rest after its last retry, and the clip ends there") {
  // Steep, slippery ground (20 deg, friction 0.4: just enough for a body lying
  // on it to come to rest): the crawl slides and falls again and again. (A try
  // can crawl for ~15 s before it falls: five fit in 120 s.)
  rise::RiseSpec spec = ProneSpec(120.0);
  spec.terrain.friction = 0.4;
  spec.terrain.slopeDeg = 20.0;
  const rise::GeneratedClip result = rise::GenerateClip(spec);
  REQUIRE(result.health.ok);
  CHECK_FALSE(result.stood);
  CHECK(result.retries == 4);
  CHECK(result.clip.Duration() < 110.0);
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

TEST_CASE("roll: from the back or a side the body rolls onto its front and the prone path places and pushes") {
  // The roll's bars: on the front, an arm left overhead drawn out and turned
  // at the side, and into place within 7 s of the start (settling
  // included; 6.1-6.7 s since the arm's turn and the near arm's swing
  // overhead in the tuck; a retry would cost seconds more), nothing sunk into
  // the ground, no hand or foot whipped round (stress runs once found them at
  // 10-16 m/s mid-roll; the far arm's swing up over the head in the push off
  // puts its fingertips at 6.1 m/s on the supine start), and a foot planted
  // to push the body over not skating on the ground. (That foot slid 6.2 cm
  // on the supine start while the back
  // rolled over a near arm kept alongside, a log roll since dropped: the bar
  // is 7 cm, over the clip's 5 cm slip bar.)
  for (const RollStart& start : kRollStarts) {
    INFO(std::string(rise::PostureName(start.posture)) << ", " << start.heightM << " m, " << start.massKg << " kg");
    const RollOutcome roll = Roll(start.posture, start.heightM, start.massKg);
    CHECK(roll.placeTime > 0.0);
    CHECK(roll.placeTime < 7.0);
    CHECK(roll.pushed);
    CHECK(roll.penetration <= 0.02);
    CHECK(roll.limbSpeed <= 6.5);
    CHECK(roll.plantedSlip <= 0.07);
  }
}

TEST_CASE("roll: a far leg left straight or in the air is tucked before it pushes, so the roll gets over") {
  // Stress-runner starts (issue 8; seeds 11, 102, 173) whose rolls fell back
  // with the pushing leg straight or its foot off the ground: the push off was
  // repeated until the roll's moves ran out, a retry, and the place phase came
  // at 17.1, 25.4 and 17.6 s. Tucked again first, each is placed without a
  // retry: by 9.1 s while the back rolled over an arm kept alongside, by
  // 12.0 s over the arm put overhead (which is brought out first, 1-1.6 s).
  // (Seed 173 is no longer asked: since the near leg under a body rolling from
  // its side keeps its foot square, its over falls back twice more and it is
  // placed at 15.0 s, the tuck still coming before each push.)
  // (Seed 11's left knee is 120 deg, not the drawn 129: drawn, its foot lay
  // 6.3 cm inside the right shin, a start the loader now rejects.)
  const char* starts[] = {
      R"({"character":{"height_m":1.516,"mass_kg":109.608},"seed":11,"start":{"drop_height_m":0.241,"joints_deg":{"abdomen":[1.462,9.931,-26.477],"chest":[-2.961,15.765,11.927],"foot_l":[-23.057,7.182],"foot_r":[-1.333,2.281],"forearm_l":[59.152],"forearm_r":[126.975],"hand_l":[-31.384,-17.624],"hand_r":[71.354,-18.479],"head":[8.309,29.754,-31.969],"shin_l":[120],"shin_r":[13.179],"thigh_l":[110.192,30.857],"thigh_r":[34.83,-29.3],"upper_arm_l":[-37.321,67.338],"upper_arm_r":[26.173,-29.63]},"posture":"custom","root_euler_deg":[112.479,140.071,149.28]},"style":{"look_around":0.412,"speed":1.607,"stance_width_m":0.124,"step_height_m":0.3,"sway":0.973,"tiredness":0.66},"terrain":{"friction":0.517,"slope_deg":3.049}})",
      R"({"character":{"height_m":1.836,"mass_kg":129.932},"seed":102,"start":{"drop_height_m":0.403,"joints_deg":{"abdomen":[35.904,6.48,-18.487],"chest":[19.766,-17.016,7.172],"foot_l":[-10.63,20.4],"foot_r":[-48.668,-17.686],"forearm_l":[88.151],"forearm_r":[130.777],"hand_l":[69.972,13.293],"hand_r":[-60.761,5.907],"head":[-47.826,-2.911,52.93],"shin_l":[102.456],"shin_r":[127.07],"thigh_l":[-17.188,-29.746],"thigh_r":[72.915,41.842],"upper_arm_l":[-23.837,51.029],"upper_arm_r":[-0.542,74.568]},"posture":"custom","root_euler_deg":[-41.617,-40.508,122.689]},"style":{"look_around":0.594,"speed":2.029,"stance_width_m":0.234,"step_height_m":0.291,"sway":0.017,"tiredness":0.719},"terrain":{"friction":1.186,"slope_deg":1.972}})"};
  for (const char* text : starts) {
    const auto spec = rise::RiseSpecFromJson(nlohmann::json::parse(text), "stress.json");
    REQUIRE(spec.IsOk());
    INFO("seed " << spec.Value().seed);
    const RollOver roll = RollOverFrom(spec.Value(), 14.0);
    CHECK_FALSE(roll.retried);
    CHECK(roll.placeTime > 0.0);
    CHECK(roll.placeTime < 12.5);
  }
}

TEST_CASE("roll: a push off from a pelvis lying on the far side turns the trunk the short way, not whipping an arm") {
  // Stress-runner starts (issue 8; seeds 382, 502): the chest lay on its back
  // and picked the roll side while the pelvis lay 85 and 47 deg onto the other
  // side. The push off's goal, 140 deg on, was then past a half turn; slerp
  // turned the trunk back the short way and the arm overhead whipped round at
  // 10.7 and 10.2 m/s, over the stress runner's 10 m/s bound. Turned by at most
  // 150 deg, no box moves faster than 8.2 m/s in either.
  const char* starts[] = {
      R"({"character":{"height_m":1.752,"mass_kg":66.015},"fps":240.0,"seed":382,"start":{"drop_height_m":0.48,"joints_deg":{"abdomen":[-16.345,-16.783,29.552],"chest":[17.584,-7.807,16.783],"foot_l":[28.656,4.6],"foot_r":[-10.135,4.961],"forearm_l":[102.799],"forearm_r":[79.437],"hand_l":[-59.047,-0.934],"hand_r":[10.832,-18.939],"head":[12.385,24.566,-42.114],"shin_l":[80.682],"shin_r":[84.556],"thigh_l":[79.482,17.937],"thigh_r":[9.046,38.265],"upper_arm_l":[-13.466,28.752],"upper_arm_r":[59.222,14.177]},"posture":"custom","root_euler_deg":[44.493,-39.711,135.363]},"style":{"look_around":0.579,"speed":2.037,"stance_width_m":0.216,"step_height_m":0.09,"sway":0.524,"tiredness":0.401},"terrain":{"friction":0.626,"slope_deg":9.068}})",
      R"({"character":{"height_m":2.081,"mass_kg":47.259},"fps":240.0,"seed":502,"start":{"drop_height_m":0.746,"joints_deg":{"abdomen":[20.85,4.402,-10.727],"chest":[23.897,16.196,-4.737],"foot_l":[-29.126,27.597],"foot_r":[21.767,34.88],"forearm_l":[146.402],"forearm_r":[39.967],"hand_l":[-55.217,10.029],"hand_r":[39.317,-31.476],"head":[47.963,-6.729,-26.168],"shin_l":[4.826],"shin_r":[126.285],"thigh_l":[44.473,2.1],"thigh_r":[64.231,47.609],"upper_arm_l":[118.266,45.732],"upper_arm_r":[65.153,-28.112]},"posture":"custom","root_euler_deg":[-176.224,-40.353,4.839]},"style":{"look_around":0.865,"speed":2.044,"stance_width_m":0.186,"step_height_m":0.273,"sway":0.116,"tiredness":0.436},"terrain":{"friction":0.549,"slope_deg":8.377}})"};
  for (const char* text : starts) {
    const auto spec = rise::RiseSpecFromJson(nlohmann::json::parse(text), "stress.json");
    REQUIRE(spec.IsOk());
    rise::RiseSpec s = spec.Value();
    INFO("seed " << s.seed);
    s.maxDurationS = 6.0;  // past the push off (3.9 and 4.0 s)
    const rise::GeneratedClip result = rise::GenerateClip(s);
    REQUIRE(result.health.ok);
    CHECK(rise::MeasureFastestBox(result.clip).speed < 9.0);
  }
}

TEST_CASE("roll: an arm left at the side is brought overhead in a tuck before the push off turns the trunk") {
  // Stress seed 5600 (issue 8): after a fall from its rise the body lay
  // turned onto its back with its far foot set, and its arm turn had left the
  // near arm out at the side. The push off came next, swinging that arm 220
  // deg in its joints to overhead while the trunk turned, and the hand
  // whipped round at 12.3 m/s, over the stress runner's 10 m/s bound (51 s).
  // Now a push off follows a tuck or a push off, or an arm already overhead,
  // and never the arm out or arm turn that leaves the arm at the side.
  // Which runs fall into that state moves with every change to the roll, so
  // two stress starts that do today are checked (seed 5600 no longer does; nor
  // do 9055 and 5104, which a scratch build without the rule showed going on
  // over or pushing off at once, since the ankle's closest-turn clamp and its
  // 40 deg range). Seeds 5025 (1.90 m on 7.7 deg) and 5201 (2.07 m on 4.7 deg)
  // tuck after their arm moves and stand; not re-checked with the rule off.
  struct Start {
    const char* text;
    bool stands;
  };
  const Start starts[] = {
      {R"({"character":{"height_m":1.904,"mass_kg":58.526},"fps":240.0,"max_duration_s":30,"seed":5025,"start":{"drop_height_m":0.079,"joints_deg":{"abdomen":[32.046,-1.659,11.541],"chest":[20.917,2.822,-9.265],"foot_l":[-47.742,-18.608],"foot_r":[-40.891,-5.257],"forearm_l":[84.255],"forearm_r":[142.614],"hand_l":[-44.75,-14.176],"hand_r":[2.141,-21.835],"head":[9.782,-39.997,-39.46],"shin_l":[73.051],"shin_r":[52.318],"thigh_l":[97.807,14.054],"thigh_r":[112.811,28.84],"upper_arm_l":[65.928,36.229],"upper_arm_r":[28.445,57.708]},"posture":"custom","root_euler_deg":[26.168,147.677,25.406]},"style":{"look_around":0.683,"speed":2.357,"stance_width_m":0.358,"step_height_m":0.176,"sway":0.74,"tiredness":0.456},"terrain":{"friction":0.536,"slope_deg":7.737}})",
       true},
      {R"({"character":{"height_m":2.074,"mass_kg":47.814},"fps":240.0,"max_duration_s":33,"seed":5201,"start":{"drop_height_m":0.987,"joints_deg":{"abdomen":[5.617,10.784,-22.902],"chest":[-8.819,-18.708,-22.981],"foot_l":[-38.473,1.068],"foot_r":[-33.285,9.971],"forearm_l":[133.918],"forearm_r":[18.259],"hand_l":[-15.764,-34.786],"hand_r":[-46.063,-7.695],"head":[21.48,5.933,-57.342],"shin_l":[34.284],"shin_r":[23.76],"thigh_l":[0.68,13.099],"thigh_r":[70.109,39.358],"upper_arm_l":[120.975,52.294],"upper_arm_r":[98.749,72.782]},"posture":"custom","root_euler_deg":[-43.177,103.064,49.572]},"style":{"look_around":0.309,"speed":1.722,"stance_width_m":0.251,"step_height_m":0.105,"sway":0.426,"tiredness":0.265},"terrain":{"friction":0.568,"slope_deg":4.698}})",
       true}};
  for (const Start& start : starts) {
    const rise::GeneratedClip result = GenerateTraced(start.text);
    INFO(result.outcome);
    REQUIRE(result.health.ok);
    REQUIRE_FALSE(result.trace.empty());
    int tucksAfterArmMoves = 0;
    for (size_t s = 1; s < result.trace.size(); ++s) {
      const std::string& before = result.trace[s - 1].move;
      const std::string& move = result.trace[s].move;
      if (move == before || (before != "arm out" && before != "arm turn")) continue;
      INFO(move << " at " << result.trace[s].time << " s, after " << before);
      CHECK(move != "push off");
      tucksAfterArmMoves += move == "tuck";
    }
    CHECK(tucksAfterArmMoves >= 1);  // the state arose
    CHECK(result.stood == start.stands);
    CHECK(rise::MeasureFastestBox(result.clip).speed < 10.0);
  }
}

TEST_CASE("roll: a body flat on its back on a slope rolls downhill, so the roll gets over") {
  // Stress-runner starts (issue 8; seeds 108 on 8.5 deg, 168 on 6.9 deg): lying
  // near flat on the back, the seed picked the uphill side, and the roll fell
  // back until its moves ran out (seed 108 three times, then the time; seed
  // 168 once, and neither stood). Rolled downhill, each is placed without a
  // retry, at 11.4 and 8.5 s.
  const char* starts[] = {
      R"({"character":{"height_m":1.885,"mass_kg":51.084},"fps":240.0,"seed":108,"start":{"drop_height_m":0.879,"joints_deg":{"abdomen":[5.316,1.368,-2.056],"chest":[36.266,-9.666,-18.739],"foot_l":[22.079,-17.486],"foot_r":[16.667,7.956],"forearm_l":[79.263],"forearm_r":[93.814],"hand_l":[-39.445,-1.978],"hand_r":[18.876,9.944],"head":[-19.046,-20.918,54.466],"shin_l":[64.225],"shin_r":[81.074],"thigh_l":[-25.524,-28.685],"thigh_r":[32.724,0.033],"upper_arm_l":[-40.977,65.266],"upper_arm_r":[104.888,54.029]},"posture":"custom","root_euler_deg":[144.951,116.736,90.167]},"style":{"look_around":0.233,"speed":2.784,"stance_width_m":0.464,"step_height_m":0.077,"sway":0.524,"tiredness":0.061},"terrain":{"friction":0.581,"slope_deg":8.483}})",
      R"({"character":{"height_m":2.075,"mass_kg":74.059},"fps":240.0,"seed":168,"start":{"drop_height_m":0.031,"joints_deg":{"abdomen":[26.602,0.67,7.079],"chest":[35.098,-8.337,-6.496],"foot_l":[17.984,16.047],"foot_r":[19.958,-10.241],"forearm_l":[68.79],"forearm_r":[62.12],"hand_l":[-8.637,11.265],"hand_r":[72.626,-31.318],"head":[-0.994,-9.62,43.915],"shin_l":[146.56],"shin_r":[93.583],"thigh_l":[38.734,35.575],"thigh_r":[-11.894,18.147],"upper_arm_l":[122.931,81.568],"upper_arm_r":[-33.484,15.559]},"posture":"custom","root_euler_deg":[143.85,163.11,152.609]},"style":{"look_around":0.015,"speed":2.481,"stance_width_m":0.405,"step_height_m":0.24,"sway":0.785,"tiredness":0.45},"terrain":{"friction":0.602,"slope_deg":6.852}})"};
  for (const char* text : starts) {
    const auto spec = rise::RiseSpecFromJson(nlohmann::json::parse(text), "stress.json");
    REQUIRE(spec.IsOk());
    INFO("seed " << spec.Value().seed);
    const RollOver roll = RollOverFrom(spec.Value(), 13.0);
    CHECK_FALSE(roll.retried);
    CHECK(roll.placeTime > 0.0);
    CHECK(roll.placeTime < 12.0);
  }
}

TEST_CASE("roll: the arm left overhead comes out round the side without touching the ground") {
  // Swung in its two shoulder angles straight to the side it passed through
  // the directions in front of the chest and dragged the hand 40-48 cm along
  // the ground; abducted to 90 deg and turned about itself there it stays
  // above the shoulder's height less the hand's thickness.
  for (const RollStart& start : kRollStarts) {
    INFO(std::string(rise::PostureName(start.posture)) << ", " << start.heightM << " m, " << start.massKg << " kg");
    const RollOutcome roll = Roll(start.posture, start.heightM, start.massKg);
    CHECK(roll.armTurned);
    CHECK(roll.armOutClearance > 0.01);
  }
}

TEST_CASE("roll: from the back, the default body turns over without dragging a hand or foot along the ground") {
  // The clip's contact-slip bar on the roll of the supine start alone. The
  // near arm overhead slid 14-18 cm as the chest turned onto it, the near leg
  // 10-20 cm as the hips turned over it; with the arm bent and drawn in and
  // the leg kept aloft after the push off, 17 of bench/prone_variants' 24
  // supine starts pass every bar (0 before).
  CHECK(Roll(rise::Posture::kSupine, 1.75, 70.0).contactSlip < 0.05);
}

TEST_CASE("roll: a hand or foot on the ground does not drag along it while the body turns over") {
  // The clip's contact-slip bar, on the roll alone: contacts up to the first
  // step of place (the prone path from there on is not the roll's). The tall
  // body's top foot, set down in front on its right side, slid 6.6 cm as the
  // turn began while lifted only a step's height; lifted 0.3 of the leg's
  // length (kTopLegLift), 3.9 cm.
  for (const RollStart& start : kRollStarts) {
    INFO(std::string(rise::PostureName(start.posture)) << ", " << start.heightM << " m, " << start.massKg << " kg");
    CHECK(Roll(start.posture, start.heightM, start.massKg).contactSlip < 0.05);
  }
}

TEST_CASE("roll: at a tired style's pace the arm swung down from overhead comes down with the chest, not dragged") {
  // Rolled at the tired style's pace (0.61), the far arm swung down from
  // overhead was still out in front of the chest as it came down onto the
  // front, and its hand was dragged 53-58 cm (the library's tired back clips).
  // The roll goes at least at the normal pace (kMinRollPace).
  rise::StyleSpec tired;
  tired.speed = 0.8;
  tired.tiredness = 0.6;
  tired.sway = 0.3;
  const RollOutcome roll = Roll(rise::Posture::kSupine, 1.75, 70.0, tired);
  CHECK(roll.placeTime > 0.0);
  CHECK(roll.contactSlip < 0.05);
}

TEST_CASE("the trace has one sample per control step") {
  rise::GenerateSettings settings;
  settings.keepTrace = true;
  const rise::GeneratedClip result = rise::GenerateClip(ProneSpec(1.0), settings);
  CHECK(result.trace.size() == 241u);  // steps 0..240 at 240 Hz
  const std::string lines = rise::TraceToJsonLines(result.trace, result.clip.skeleton);
  CHECK(std::count(lines.begin(), lines.end(), '\n') == 241);
  // Each hand and foot: its measured wrist/ankle and how far its box is above
  // the ground. Lying prone at the start the feet rest on the ground.
  const nlohmann::json last = nlohmann::json::parse(lines.substr(lines.rfind('\n', lines.size() - 2) + 1));
  for (int i = 0; i < rise::kLimbCount; ++i) {
    const char* limb = rise::LimbName(static_cast<rise::Limb>(i));
    INFO(limb);
    REQUIRE(last[limb]["at"].size() == 3u);
    const glm::vec3 at(last[limb]["at"][0].get<float>(), last[limb]["at"][1].get<float>(), last[limb]["at"][2].get<float>());
    CHECK(glm::length(at - result.trace.back().limbPositions[i]) < 1e-5f);
    CHECK(last[limb]["clearance"].get<float>() < at.y);
  }
  CHECK(std::fabs(result.trace.front().clearance[2]) < 0.01f);
}

TEST_CASE("the trace shows the CoM's velocity, where the weight is aimed, each support's load and the joint torques") {
  // Up to the crawl: lying (no loads), the push on two hands, a foot step.
  rise::GenerateSettings settings;
  settings.keepTrace = true;
  const rise::RiseSpec spec = ProneSpec(5.0);
  const rise::GeneratedClip result = rise::GenerateClip(spec, settings);
  const std::vector<rise::TraceSample>& trace = result.trace;
  REQUIRE(trace.size() > 2u);
  const rise::BipedDef def = rise::MakeBipedDef(spec.character);
  const int joints = static_cast<int>(def.skeleton.joints.size());

  // The velocity is the CoM's: the central difference of its positions
  // (which a contact's jolt makes differ for a step).
  float meanError = 0.0f;
  for (size_t k = 1; k + 1 < trace.size(); ++k) {
    const glm::vec3 difference =
        (trace[k + 1].com - trace[k - 1].com) / static_cast<float>(trace[k + 1].time - trace[k - 1].time);
    meanError += glm::length(difference - trace[k].comVelocity) / static_cast<float>(trace.size() - 2);
  }
  CHECK(meanError < 0.005f);

  // The weight goes on planted hands and feet that touch, all of it.
  int loaded = 0;
  std::vector<float> peak(joints, 0.0f);
  for (size_t k = 0; k < trace.size(); ++k) {
    const rise::TraceSample& sample = trace[k];
    float total = 0.0f;
    for (int i = 0; i < rise::kLimbCount; ++i) {
      CHECK(sample.load[i] >= 0.0f);
      if (!sample.planted[i] || !sample.touching[i]) CHECK(sample.load[i] == 0.0f);
      total += sample.load[i];
    }
    if (total > 0.0f) {
      ++loaded;
      CHECK(total == doctest::Approx(1.0f).epsilon(1e-4));
    }
    CHECK(std::fabs(sample.pressure.y) < 1e-4f);  // on the level ground
    // The torques of the step after the sample (none after the last).
    if (k + 1 == trace.size()) continue;
    REQUIRE(static_cast<int>(sample.jointTorques.size()) == joints);
    for (int j = 0; j < joints; ++j) peak[j] = std::max(peak[j], sample.jointTorques[j]);
  }
  CHECK(loaded > 240);
  CHECK(peak[0] == 0.0f);
  // Their maxima are the clip's peak torques.
  for (const auto& [joint, torque] : result.clip.metadata.peakTorques) {
    INFO(joint);
    CHECK(torque > 0.0);
    CHECK(peak[def.Find(joint)] == torque);
  }

  const std::string lines = rise::TraceToJsonLines(trace, result.clip.skeleton);
  const nlohmann::json first = nlohmann::json::parse(lines.substr(0, lines.find('\n')));
  CHECK(first["com_velocity"].size() == 3u);
  CHECK(first["pressure"].size() == 3u);
  CHECK(first["hand_l"]["load"].get<float>() == 0.0f);
  CHECK(first["torques"].size() == 15u);
  CHECK(first["torques"]["shin_l"].get<float>() == doctest::Approx(trace.front().jointTorques[def.Find("shin_l")]));
}
}

TEST_CASE("the trace shows the roll: its side and how far pelvis and chest have turned from the back") {
  // A supine start turns over onto its front and places its hands in its first 8 s.
  const rise::GeneratedClip result = Generate(
      R"({"character":{"height_m":1.60,"mass_kg":55},"start":{"posture":"supine","heading_deg":0},"seed":1,"max_duration_s":8})",
      true);
  const std::vector<rise::TraceSample>& trace = result.trace;
  REQUIRE(!trace.empty());
  // No side while the body settles; once chosen, the side holds for the whole roll.
  CHECK(trace.front().rollSide == 0.0f);
  size_t chosen = 0;
  while (chosen < trace.size() && trace[chosen].rollSide == 0.0f) ++chosen;
  REQUIRE(chosen < trace.size());
  CHECK(trace[chosen].phase == rise::RisePhase::kRoll);
  float peak = -10.0f;
  size_t placed = trace.size();
  for (size_t k = chosen; k < trace.size(); ++k) {
    CHECK(trace[k].rollSide == trace[chosen].rollSide);
    if (trace[k].phase == rise::RisePhase::kPlace && placed == trace.size()) placed = k;
    if (placed == trace.size()) peak = std::max(peak, trace[k].pelvisRoll);
  }
  // From flat on the back (0 deg) to the front (past 135 deg) before the hands are placed.
  CHECK(std::fabs(glm::degrees(trace[chosen].pelvisRoll)) < 10.0f);
  CHECK(std::fabs(glm::degrees(trace[chosen].chestRoll)) < 10.0f);
  REQUIRE(placed < trace.size());
  CHECK(glm::degrees(trace[placed].pelvisRoll) > 135.0f);
  CHECK(glm::degrees(trace[placed].chestRoll) > 135.0f);
  CHECK(glm::degrees(peak) < 200.0f);

  // In the JSON lines: null before the side is chosen, then the side and both angles in degrees.
  const std::string lines = rise::TraceToJsonLines(trace, result.clip.skeleton);
  std::vector<nlohmann::json> parsed;
  for (size_t at = 0; at < lines.size();) {
    const size_t end = lines.find('\n', at);
    parsed.push_back(nlohmann::json::parse(lines.substr(at, end - at)));
    at = end + 1;
  }
  REQUIRE(parsed.size() == trace.size());
  CHECK(parsed.front()["roll"].is_null());
  const nlohmann::json& roll = parsed[placed]["roll"];
  CHECK(roll["side"] == (trace[chosen].rollSide > 0.0f ? "left" : "right"));
  CHECK(roll["pelvis_deg"].get<float>() == doctest::Approx(glm::degrees(trace[placed].pelvisRoll)));
  CHECK(roll["chest_deg"].get<float>() == doctest::Approx(glm::degrees(trace[placed].chestRoll)));
}
