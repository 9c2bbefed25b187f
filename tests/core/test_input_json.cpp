// SPDX-License-Identifier: MIT
// The input loader: defaults, every kind of mistake by message content, round trip, samples.
#include <fstream>
#include <sstream>

#include "core/input_json.h"
#include "test_support.h"

namespace {

rise::RiseSpec ParseOk(const std::string& text) {
  const rise::Result<rise::RiseSpec> result = rise::ParseRiseSpec(text, "in.json");
  INFO(text);
  if (!result) INFO(result.Error().Format());
  REQUIRE(result.IsOk());
  return result.Value();
}

// The one-line message for a bad input.
std::string ErrorOf(const std::string& text) {
  const rise::Result<rise::RiseSpec> result = rise::ParseRiseSpec(text, "in.json");
  INFO(text);
  REQUIRE_FALSE(result.IsOk());
  return result.Error().Format();
}

bool Contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

}  // namespace

TEST_SUITE("input_json") {
  TEST_CASE("an empty object gives every default of the format") {
    const rise::RiseSpec spec = ParseOk("{}");
    CHECK(spec.character.heightM == 1.75);
    CHECK(spec.character.massKg == 70.0);
    CHECK(spec.character.segments.empty());
    CHECK(spec.start.posture == rise::Posture::kSupine);
    CHECK(spec.start.headingDeg == 0.0);
    CHECK(spec.start.dropHeightM == 0.0);
    CHECK(spec.start.jointsDeg.empty());
    CHECK(spec.terrain.slopeDeg == 0.0);
    CHECK(spec.terrain.friction == 0.8);
    CHECK(spec.style.speed == 1.0);
    CHECK(spec.style.stepHeightM == 0.08);
    CHECK(spec.style.stanceWidthM == 0.3);
    CHECK(spec.style.sway == 0.0);
    CHECK(spec.seed == 1u);
    CHECK(spec.fps == 30.0);
    CHECK(spec.maxDurationS == 60.0);  // the default start is supine: DefaultMaxDurationS
    CHECK(spec.output.names == "default");
    CHECK(spec.output.rootMotion);
    CHECK(spec.disturbances.empty());
  }

  TEST_CASE("max_duration_s left out follows the start and the style's pace; given, it is kept") {
    CHECK(ParseOk(R"({"start": {"posture": "prone"}})").maxDurationS == 35.0);
    CHECK(ParseOk(R"({"start": {"posture": "side_left"}})").maxDurationS == 60.0);
    CHECK(ParseOk(R"({"start": {"posture": "custom"}})").maxDurationS == 60.0);
    // pace 0.5 x (1 - 0.4 x 0.5) = 0.4: 35 / 0.4 = 87.5 s; a fast style keeps the base.
    CHECK(ParseOk(R"({"start": {"posture": "prone"}, "style": {"speed": 0.5, "tiredness": 0.5}})").maxDurationS ==
          doctest::Approx(87.5));
    CHECK(ParseOk(R"({"start": {"posture": "prone"}, "style": {"speed": 3}})").maxDurationS == 35.0);
    CHECK(ParseOk(R"({"style": {"speed": 0.25, "tiredness": 1}})").maxDurationS == 120.0);
    CHECK(ParseOk(R"({"start": {"posture": "supine"}, "max_duration_s": 12})").maxDurationS == 12.0);
    // A value given in a base (a library's defaults) survives patches that leave it out.
    const rise::RiseSpec base = ParseOk(R"({"max_duration_s": 10})");
    const auto patched = rise::RiseSpecFromJson(nlohmann::json::parse(R"({"style": {"speed": 0.5}})"), "in.json", "", base);
    REQUIRE(patched.IsOk());
    CHECK(patched.Value().maxDurationS == 10.0);
  }

  TEST_CASE("every key is read") {
    const rise::RiseSpec spec = ParseOk(R"({
    "character": {"height_m": 1.9, "mass_kg": 95, "segments": {"thigh_l": {"length_m": 0.5, "mass_kg": 11}}},
    "start": {"posture": "custom", "heading_deg": -30, "root_euler_deg": [-90, 10, 5],
              "joints_deg": {"shin_r": [45], "thigh_l": [30, -10], "chest": [10, 5, -20]}, "drop_height_m": 0.4},
    "terrain": {"slope_deg": 10, "friction": 0.6},
    "style": {"speed": 1.5, "step_height_m": 0.1, "stance_width_m": 0.25, "sway": 0.5, "tiredness": 0.2,
              "look_around": 0.7},
    "disturbances": [{"time_s": 3, "body": "chest", "force_n": [150, 0, -20], "duration_s": 0.2}],
    "seed": 42, "fps": 60, "max_duration_s": 15,
    "output": {"names": "mixamo", "root_motion": false}})");
    CHECK(spec.character.heightM == 1.9);
    CHECK(spec.character.massKg == 95.0);
    CHECK(*spec.character.segments.at("thigh_l").lengthM == 0.5f);
    CHECK(*spec.character.segments.at("thigh_l").massKg == 11.0f);
    CHECK_FALSE(spec.character.segments.at("thigh_l").widthM.has_value());
    CHECK(spec.start.posture == rise::Posture::kCustom);
    CHECK(spec.start.headingDeg == -30.0);
    CHECK(spec.start.rootEulerDeg[0] == -90.0);
    CHECK(spec.start.rootEulerDeg[2] == 5.0);
    CHECK(spec.start.jointsDeg.at("shin_r") == std::vector<double>{45.0});
    CHECK(spec.start.jointsDeg.at("chest") == std::vector<double>{10.0, 5.0, -20.0});
    CHECK(spec.start.dropHeightM == 0.4);
    CHECK(spec.terrain.slopeDeg == 10.0);
    CHECK(spec.terrain.friction == 0.6);
    CHECK(spec.style.speed == 1.5);
    CHECK(spec.style.lookAround == 0.7);
    REQUIRE(spec.disturbances.size() == 1u);
    CHECK(spec.disturbances[0].body == "chest");
    CHECK(spec.disturbances[0].forceN[2] == -20.0);
    CHECK(spec.disturbances[0].durationS == 0.2);
    CHECK(spec.seed == 42u);
    CHECK(spec.fps == 60.0);
    CHECK(spec.maxDurationS == 15.0);
    CHECK(spec.output.names == "mixamo");
    CHECK_FALSE(spec.output.rootMotion);
  }

  TEST_CASE("bad inputs: one message naming file, path, what was found and what is allowed") {
    // 1. the example of the issue, verbatim
    CHECK(ErrorOf(R"({"start": {"posture": "sitting"}})") ==
          R"(in.json: start.posture: found "sitting", allowed: supine, prone, side_left, side_right, custom)");
    // 2. syntax error with line and column
    const std::string syntax = ErrorOf("{\n  \"seed\": 1,\n  \"fps\": }\n");
    CHECK(Contains(syntax, "in.json:3:10: invalid JSON: "));
    CHECK(Contains(syntax, "unexpected '}'"));
    // 3. unknown key with a did-you-mean hint and the allowed list
    CHECK(
        ErrorOf(R"({"character": {"heigth_m": 1.8}})") ==
        R"(in.json: character.heigth_m: unknown key "heigth_m", did you mean "height_m"? allowed: height_m, mass_kg, segments)");
    // 4. unknown top-level key far from every name: no hint
    CHECK(ErrorOf(R"({"zzzzzzzz": 1})")
              .rfind("in.json: zzzzzzzz: unknown key \"zzzzzzzz\" allowed: $schema, character", 0) == 0);
    // 5. wrong type
    CHECK(ErrorOf(R"({"character": {"height_m": "tall"}})") ==
          R"(in.json: character.height_m: found "tall" (a string), allowed: a number from 1.2 to 2.3 m)");
    // 6. out of range, range stated
    CHECK(ErrorOf(R"({"character": {"mass_kg": 250}})") ==
          "in.json: character.mass_kg: found 250, allowed: 30 to 200 kg");
    CHECK(ErrorOf(R"({"terrain": {"slope_deg": 45}})") ==
          "in.json: terrain.slope_deg: found 45, allowed: 0 to 30 degrees");
    CHECK(ErrorOf(R"({"terrain": {"friction": 0.01}})") == "in.json: terrain.friction: found 0.01, allowed: 0.05 to 2");
    CHECK(ErrorOf(R"({"fps": 1000})") == "in.json: fps: found 1000, allowed: 1 to 240 frames per second");
    // 7. huge numbers: beyond a double at parse time, and merely huge
    CHECK(ErrorOf("{\n \"fps\": 1e400}") ==
          "in.json:2:9: found the number 1e400, allowed: numbers a double can hold (about 1e308)");
    CHECK(ErrorOf(R"({"max_duration_s": 1e300})") == "in.json: max_duration_s: found 1e+300, allowed: 1 to 120 s");
    // 8. NaN is not JSON
    CHECK(Contains(ErrorOf(R"({"fps": NaN})"), "in.json:1:9: invalid JSON: "));
    // 9. a count that is not whole
    CHECK(ErrorOf(R"({"seed": 1.5})") == "in.json: seed: found 1.5, allowed: a whole number from 0 to 9.0072e+15");
    CHECK(ErrorOf(R"({"seed": -3})") == "in.json: seed: found -3, allowed: a whole number from 0 to 9.0072e+15");
    // 10. joint angle outside the joint's limit
    CHECK(ErrorOf(R"({"start": {"posture": "custom", "joints_deg": {"shin_l": [170]}}})") ==
          "in.json: start.joints_deg.shin_l[0]: found 170, allowed: 0 to 150 degrees (flexion)");
    // 11. wrong DOF count
    CHECK(ErrorOf(R"({"start": {"joints_deg": {"thigh_r": [10]}}})") ==
          "in.json: start.joints_deg.thigh_r: found an array of 1, allowed: an array of 2 values "
          "[flexion -30 to 120, abduction -30 to 50] degrees");
    // 12. a joint named after the joint instead of the bone
    CHECK(Contains(ErrorOf(R"({"start": {"joints_deg": {"knee_l": [10]}}})"),
                   "start.joints_deg.knee_l: unknown joint \"knee_l\"; joints are named after the bone they move: "
                   "did you mean \"shin_l\"?"));
    // 13. end joints have no angles
    CHECK(Contains(ErrorOf(R"({"start": {"joints_deg": {"head_end": []}}})"), "unknown joint \"head_end\""));
    // 14. root orientation without posture custom
    CHECK(ErrorOf(R"({"start": {"posture": "prone", "root_euler_deg": [0, 0, 0]}})") ==
          "in.json: start.root_euler_deg: found with posture \"prone\", allowed: only with posture \"custom\" "
          "(the other postures set the root themselves)");
    // 15. a vector with the wrong length
    CHECK(
        ErrorOf(R"({"start": {"posture": "custom", "root_euler_deg": [0, 0]}})") ==
        "in.json: start.root_euler_deg: found an array of 2, allowed: an array of 3 numbers, each -360 to 360 degrees");
    // 16. unknown segment, with a hint
    CHECK(Contains(ErrorOf(R"({"character": {"segments": {"thigh_left": {"length_m": 0.4}}}})"),
                   "character.segments.thigh_left: unknown key \"thigh_left\", did you mean \"thigh_l\"?"));
    // 17. overridden masses leave nothing for the rest
    CHECK(ErrorOf(
              R"({"character": {"mass_kg": 50, "segments": {"chest": {"mass_kg": 30}, "pelvis": {"mass_kg": 20}}}})") ==
          "in.json: character.segments: found overridden masses summing to 50 kg, allowed: less than 90 % of mass_kg "
          "(45 kg), so the other segments keep a share");
    // 18. a disturbance missing a key, and one with an unknown body
    CHECK(ErrorOf(R"({"disturbances": [{"time_s": 1, "body": "chest", "force_n": [1, 0, 0]}]})") ==
          "in.json: disturbances[0]: missing key \"duration_s\"; required: time_s, body, force_n, duration_s");
    CHECK(ErrorOf(R"({"disturbances": [{"time_s": 1, "body": "chets", "force_n": [1, 0, 0], "duration_s": 0.2}]})")
              .rfind("in.json: disturbances[0].body: found \"chets\" (did you mean \"chest\"?), allowed: pelvis, ",
                     0) == 0);
    // 19. a push after the end of the simulation
    CHECK(
        ErrorOf(
            R"({"max_duration_s": 10, "disturbances": [{"time_s": 12, "body": "chest", "force_n": [1, 0, 0], "duration_s": 0.2}]})") ==
        "in.json: disturbances[0].time_s: found 12, allowed: 0 to max_duration_s (10 s)");
    // 20. duplicate keys, with the path of the second
    CHECK(ErrorOf(R"({"style": {"sway": 0.1, "sway": 0.9}})") ==
          "in.json: style.sway: found this key twice in the same object, allowed: once");
    CHECK(ErrorOf(R"({"disturbances": [{}, {"time_s": 1, "time_s": 2}]})") ==
          "in.json: disturbances[1].time_s: found this key twice in the same object, allowed: once");
    // 21. wrong container types
    CHECK(ErrorOf("[1, 2]") == "in.json: found an array of 2, allowed: an object");
    CHECK(ErrorOf(R"({"terrain": 3})") == "in.json: terrain: found 3, allowed: an object");
    CHECK(ErrorOf(R"({"output": {"root_motion": "no"}})") ==
          R"(in.json: output.root_motion: found "no" (a string), allowed: true or false)");
    CHECK(ErrorOf(R"({"output": {"names": "unreal"}})") ==
          R"(in.json: output.names: found "unreal", allowed: default, mixamo, ue)");
    // 22. empty file
    CHECK(Contains(ErrorOf(""), "in.json:1:1: invalid JSON: "));
    // 23. a start pose with the limbs through each other: the left leg crossed through the right
    CHECK(ErrorOf(R"({"start": {"posture": "custom", "joints_deg": {"thigh_l": [-19, -18], "shin_l": [143],
                  "thigh_r": [-25, -15]}}})") ==
          "in.json: start.joints_deg: found a pose in which the thigh_l and thigh_r boxes pass 14.4 cm into each other, "
          "allowed: at most 5 cm (a body cannot start inside itself; turn one of them clear)");
  }

  TEST_CASE("a missing file is an error naming the file") {
    const rise::Result<rise::RiseSpec> result = rise::LoadRiseSpec("/nonexistent/dir/input.json");
    REQUIRE_FALSE(result.IsOk());
    CHECK(result.Error().Format() == "/nonexistent/dir/input.json: cannot open the file for reading");
  }

  TEST_CASE("line and column of byte offsets, and edit distance") {
    int line = 0, column = 0;
    rise::TextPosition("ab\ncd\n\nx", 7, line, column);
    CHECK(line == 4);
    CHECK(column == 1);
    rise::TextPosition("ab\ncd", 4, line, column);
    CHECK(line == 2);
    CHECK(column == 2);
    CHECK(rise::EditDistance("kitten", "sitting") == 3);
    CHECK(rise::EditDistance("", "abc") == 3);
    CHECK(rise::EditDistance("same", "same") == 0);
  }

  TEST_CASE("a manifest entry merges onto a base and prefixes its error paths") {
    rise::RiseSpec base;
    base.character.heightM = 1.5;
    base.seed = 9;
    const auto merged = rise::RiseSpecFromJson(nlohmann::json::parse(R"({"seed": 3})"), "lib.json", "clips[2]", base);
    REQUIRE(merged.IsOk());
    CHECK(merged.Value().character.heightM == 1.5);
    CHECK(merged.Value().seed == 3u);
    const auto bad = rise::RiseSpecFromJson(nlohmann::json::parse(R"({"fps": 0})"), "lib.json", "clips[2]", base);
    REQUIRE_FALSE(bad.IsOk());
    CHECK(bad.Error().Format() == "lib.json: clips[2].fps: found 0, allowed: 1 to 240 frames per second");
  }

  TEST_CASE("RiseSpecToJson round-trips a spec with every key set") {
    const std::string text = R"({
    "character": {"height_m": 1.83, "mass_kg": 81.5, "segments": {"forearm_r": {"length_m": 0.3, "width_m": 0.07},
                                                                    "head": {"mass_kg": 6.1, "depth_m": 0.21}}},
    "start": {"posture": "custom", "heading_deg": 12.25, "root_euler_deg": [-85, 3, 0.1],
              "joints_deg": {"foot_l": [-20, 5], "head": [1, 2, 3]}, "drop_height_m": 0.25},
    "terrain": {"slope_deg": 7.5, "friction": 1.1},
    "style": {"speed": 0.9, "step_height_m": 0.12, "stance_width_m": 0.33, "sway": 0.4, "tiredness": 0.3,
              "look_around": 0.1},
    "disturbances": [{"time_s": 2.5, "body": "pelvis", "force_n": [0, 0, 150], "duration_s": 0.15}],
    "seed": 123456789, "fps": 24, "max_duration_s": 12.5, "output": {"names": "ue", "root_motion": false}})";
    const rise::RiseSpec spec = ParseOk(text);
    const std::string once = rise::RiseSpecToJson(spec).dump();
    const rise::RiseSpec again = ParseOk(once);
    CHECK(rise::RiseSpecToJson(again).dump() == once);
    // Spot-check fields that the text comparison could hide behind formatting.
    CHECK(again.character.massKg == 81.5);
    CHECK(*again.character.segments.at("forearm_r").widthM == *spec.character.segments.at("forearm_r").widthM);
    CHECK(again.start.rootEulerDeg == spec.start.rootEulerDeg);
    CHECK(again.start.jointsDeg == spec.start.jointsDeg);
    CHECK(again.disturbances[0].forceN == spec.disturbances[0].forceN);
    CHECK(again.seed == 123456789u);
    // Float overrides are written as their short decimal, not as the float's binary expansion.
    CHECK(Contains(once, "\"length_m\":0.3,"));
    // The default spec round-trips too and names every key of the format.
    const nlohmann::ordered_json defaults = rise::RiseSpecToJson(rise::RiseSpec{});
    CHECK(rise::RiseSpecToJson(ParseOk(defaults.dump())) == defaults);
    CHECK(defaults["style"].size() == 6u);
  }

  TEST_CASE("every sample loads, and reference.json holds exactly the defaults") {
    for (const char* name : rise::test::kSampleInputs) {
      const std::string path = std::string(RISE_SOURCE_DIR) + "/samples/" + name + ".json";
      const rise::Result<rise::RiseSpec> result = rise::LoadRiseSpec(path);
      INFO(path);
      if (!result) INFO(result.Error().Format());
      CHECK(result.IsOk());
    }
    const auto reference = rise::LoadRiseSpec(std::string(RISE_SOURCE_DIR) + "/samples/reference.json");
    REQUIRE(reference.IsOk());
    CHECK(rise::RiseSpecToJson(reference.Value()) == rise::RiseSpecToJson(rise::RiseSpec{}));
    const auto slope = rise::LoadRiseSpec(std::string(RISE_SOURCE_DIR) + "/samples/slope.json");
    REQUIRE(slope.IsOk());
    CHECK(slope.Value().terrain.slopeDeg == 10.0);
    const auto push = rise::LoadRiseSpec(std::string(RISE_SOURCE_DIR) + "/samples/push.json");
    REQUIRE(push.IsOk());
    REQUIRE(push.Value().disturbances.size() == 1u);
    CHECK(push.Value().disturbances[0].body == "chest");
    CHECK(push.Value().disturbances[0].forceN[0] == 150.0);
    CHECK(push.Value().disturbances[0].durationS == 0.2);
  }
}
