// SPDX-License-Identifier: MIT
#include <algorithm>
#include <set>
#include <string>
#include <vector>

#include "core/input_json.h"
#include "core/library_manifest.h"
#include "test_support.h"

namespace {

rise::LibraryManifest Parse(const std::string& text) {
  rise::Result<rise::LibraryManifest> result = rise::ParseLibraryManifest(text, "lib.json");
  if (!result) FAIL_CHECK(result.Error().Format());
  REQUIRE(result.IsOk());
  return result.Value();
}

std::vector<std::string> Names(const rise::LibraryManifest& manifest) {
  std::vector<std::string> names;
  for (const rise::ManifestClip& clip : manifest.clips) names.push_back(clip.name);
  return names;
}

rise::StartSpec Custom(double x, double y, double z) {
  rise::StartSpec start;
  start.posture = rise::Posture::kCustom;
  start.rootEulerDeg = {x, y, z};
  return start;
}

}  // namespace

TEST_SUITE("library_manifest") {
  TEST_CASE("a cross product runs starts outermost and seeds innermost, named by category and parameters") {
    const rise::LibraryManifest manifest = Parse(R"({
      "defaults": { "max_duration_s": 5 },
      "cross": {
        "starts": ["supine", { "name": "turned", "posture": "prone", "heading_deg": 30 }],
        "bodies": [ { "name": "avg", "height_m": 1.75 }, { "name": "big", "height_m": 2.0, "mass_kg": 110 } ],
        "styles": [ { "name": "calm", "speed": 0.8 } ],
        "seeds": [1, 2]
      } })");
    CHECK(Names(manifest) == std::vector<std::string>{"back_supine_avg_calm_s1", "back_supine_avg_calm_s2",
                                                      "back_supine_big_calm_s1", "back_supine_big_calm_s2",
                                                      "stomach_turned_avg_calm_s1", "stomach_turned_avg_calm_s2",
                                                      "stomach_turned_big_calm_s1", "stomach_turned_big_calm_s2"});
    const rise::ManifestClip& clip = manifest.clips[7];
    CHECK(clip.category == rise::StartCategory::kStomach);
    CHECK(clip.body == "big");
    CHECK(clip.spec.start.posture == rise::Posture::kProne);
    CHECK(clip.spec.start.headingDeg == 30.0);
    CHECK(clip.spec.character.heightM == 2.0);
    CHECK(clip.spec.character.massKg == 110.0);
    CHECK(clip.spec.style.speed == 0.8);
    CHECK(clip.spec.seed == 2u);
    CHECK(clip.spec.maxDurationS == 5.0);  // from the defaults
    CHECK(manifest.formats == std::vector<std::string>{"glb"});
  }

  TEST_CASE("explicit clips come first, keep their name and body, and axes left out add nothing to names") {
    const rise::LibraryManifest manifest = Parse(R"({
      "formats": ["gltf", "bvh"],
      "defaults": { "fps": 60 },
      "clips": [ { "name": "pushed", "body": "hero", "start": { "posture": "side_right" }, "seed": 9 } ],
      "cross": { "seeds": { "from": 5, "count": 3 } } })");
    CHECK(Names(manifest) == std::vector<std::string>{"pushed", "back_supine_s5", "back_supine_s6", "back_supine_s7"});
    CHECK(manifest.clips[0].body == "hero");
    CHECK(manifest.clips[0].category == rise::StartCategory::kSide);
    CHECK(manifest.clips[0].spec.seed == 9u);
    CHECK(manifest.clips[0].spec.fps == 60.0);
    CHECK(manifest.clips[1].body == "default");
    CHECK(manifest.clips[3].spec.seed == 7u);
    CHECK(manifest.formats == std::vector<std::string>{"gltf", "bvh"});
  }

  TEST_CASE("a body range expands into evenly spaced bodies named by their values") {
    const rise::LibraryManifest manifest = Parse(R"({ "cross": { "bodies": [
      { "name": "r", "height_m": { "from": 1.5, "to": 1.9, "count": 3 }, "mass_kg": { "from": 60, "to": 80, "count": 2 } } ] } })");
    CHECK(Names(manifest) == std::vector<std::string>{"back_supine_r_h1.5_m60_s1", "back_supine_r_h1.5_m80_s1",
                                                      "back_supine_r_h1.7_m60_s1", "back_supine_r_h1.7_m80_s1",
                                                      "back_supine_r_h1.9_m60_s1", "back_supine_r_h1.9_m80_s1"});
    CHECK(manifest.clips[2].spec.character.heightM == 1.7);
    CHECK(manifest.clips[3].spec.character.massKg == 80.0);
  }

  TEST_CASE("start categories: postures by name, custom poses by where the pelvis's front points") {
    rise::StartSpec start;
    start.posture = rise::Posture::kSupine;
    CHECK(rise::CategoryOf(start) == rise::StartCategory::kBack);
    start.posture = rise::Posture::kProne;
    CHECK(rise::CategoryOf(start) == rise::StartCategory::kStomach);
    start.posture = rise::Posture::kSideLeft;
    CHECK(rise::CategoryOf(start) == rise::StartCategory::kSide);
    // -90 deg about X is the supine orientation (front up), +90 the prone one (core/biped.cpp).
    CHECK(rise::CategoryOf(Custom(-90, 0, 0)) == rise::StartCategory::kBack);
    CHECK(rise::CategoryOf(Custom(90, 0, 0)) == rise::StartCategory::kStomach);
    CHECK(rise::CategoryOf(Custom(0, 0, 90)) == rise::StartCategory::kSide);
    // The boundary: a front 29 deg above level is side, 31 deg above is back.
    CHECK(rise::CategoryOf(Custom(-29, 0, 0)) == rise::StartCategory::kSide);
    CHECK(rise::CategoryOf(Custom(-31, 0, 0)) == rise::StartCategory::kBack);
    CHECK(std::string(rise::StartCategoryName(rise::StartCategory::kStomach)) == "stomach");
  }

  TEST_CASE("every mistake names its JSON path and what is allowed") {
    struct Case {
      const char* text;
      const char* path;
      const char* message;
    };
    const Case cases[] = {
        {R"({ "clips": [], "crosss": {} })", "crosss", "did you mean \"cross\"?"},
        {R"({ "cross": { "sedes": [1] } })", "cross.sedes", "did you mean \"seeds\"?"},
        {R"({ "cross": { "starts": ["supine", { "posture": "lying" }] } })", "cross.starts[1].posture",
         "found \"lying\""},
        {R"({ "cross": { "bodies": [ { "name": "x", "height_m": 2.9 } ] } })", "cross.bodies[0].height_m",
         "found 2.9, allowed: 1.2 to 2.3 m"},
        {R"({ "cross": { "bodies": [ { "height_m": 1.8 } ] } })", "cross.bodies[0]", "missing key \"name\""},
        {R"({ "cross": { "styles": [ { "name": "a b" } ] } })", "cross.styles[0].name", "a file name"},
        {R"({ "cross": { "seeds": [1, 2.5] } })", "cross.seeds[1]", "a whole number"},
        {R"({ "cross": { "seeds": { "from": 1, "count": 0 } } })", "cross.seeds.count", "found 0"},
        {R"({ "cross": { "bodies": [ { "name": "r", "height_m": { "from": 1.5, "count": 2 } } ] } })",
         "cross.bodies[0].height_m", "missing key \"to\""},
        {R"({ "clips": [ { "seed": 1 } ] })", "clips[0]", "missing key \"name\""},
        {R"({ "clips": [ { "name": "index" } ] })", "clips[0].name", "the batch writes index.json"},
        {R"({ "clips": [ { "name": "a" }, { "name": "a" } ] })", "clips[1]", "a second time (first from clips[0])"},
        {R"({ "clips": [ { "name": "a", "fps": 900 } ] })", "clips[0].fps", "found 900"},
        {R"({ "defaults": { "strat": {} }, "clips": [] })", "defaults.strat", "did you mean \"start\"?"},
        {R"({ "formats": ["bvh"], "clips": [] })", "formats", "found no \"glb\" and \"gltf\""},
        {R"({ "formats": ["glb", "glb"], "clips": [] })", "formats[1]", "twice"},
        {R"({ "formats": "glb", "clips": [] })", "formats", "a non-empty array"},
        {R"({ "defaults": {} })", "", "found no \"clips\" and no \"cross\""},
        {R"({ "clips": [ { "name": "a", "body": "b" }, { "name": "c", "body": "b", "output": { "names": "ue" } } ] })",
         "clips[1]", "one skeleton per body name"},
        {R"({ "clips": [], "clips": [] })", "clips", "found this key twice"},
    };
    for (const Case& c : cases) {
      CAPTURE(c.text);
      const rise::Result<rise::LibraryManifest> result = rise::ParseLibraryManifest(c.text, "lib.json");
      REQUIRE_FALSE(result.IsOk());
      CHECK(result.Error().file == "lib.json");
      CHECK(result.Error().jsonPath == c.path);
      CHECK(result.Error().message.find(c.message) != std::string::npos);
    }
  }

  TEST_CASE("a syntax error gives line and column") {
    const rise::Result<rise::LibraryManifest> result = rise::ParseLibraryManifest("{\n  \"clips\": [,]\n}", "lib.json");
    REQUIRE_FALSE(result.IsOk());
    CHECK(result.Error().line == 2);
    CHECK(result.Error().column == 13);
    CHECK(result.Error().Format().rfind("lib.json:2:13: invalid JSON", 0) == 0);
  }

  TEST_CASE("an unreadable manifest names the file") {
    const rise::Result<rise::LibraryManifest> result = rise::LoadLibraryManifest("no/such/library.json");
    REQUIRE_FALSE(result.IsOk());
    CHECK(result.Error().Format() == "no/such/library.json: cannot open the file for reading");
  }

  TEST_CASE("shards: I/N parsing and a round-robin split whose union is every clip once") {
    CHECK(rise::ParseShard("0/1", "--shard").IsOk());
    const rise::Result<rise::Shard> shard = rise::ParseShard("3/4", "--shard");
    REQUIRE(shard.IsOk());
    CHECK(shard.Value().index == 3);
    CHECK(shard.Value().count == 4);
    for (const char* bad : {"4/4", "1", "a/b", "-1/2", "1/0", "/2", "2/", "1/2/3"}) {
      CAPTURE(bad);
      const rise::Result<rise::Shard> result = rise::ParseShard(bad, "--shard");
      REQUIRE_FALSE(result.IsOk());
      CHECK(result.Error().Format().rfind("--shard: found \"" + std::string(bad) + "\", allowed: I/N", 0) == 0);
    }
    for (int count : {1, 3, 7, 50}) {
      std::vector<size_t> all;
      size_t smallest = 1000, largest = 0;
      for (int i = 0; i < count; ++i) {
        const std::vector<size_t> part = rise::ShardClips(40, rise::Shard{i, count});
        CHECK(std::is_sorted(part.begin(), part.end()));
        smallest = std::min(smallest, part.size());
        largest = std::max(largest, part.size());
        all.insert(all.end(), part.begin(), part.end());
      }
      std::sort(all.begin(), all.end());
      CHECK(all.size() == 40);
      CHECK(std::set<size_t>(all.begin(), all.end()).size() == 40);
      CHECK(largest - smallest <= 1);
    }
  }

  TEST_CASE("the input hash changes with any input value and not with key order") {
    rise::RiseSpec spec;
    const std::string hash = rise::InputHash(spec);
    CHECK(hash.size() == 16);
    CHECK(rise::InputHash(spec) == hash);
    rise::RiseSpec other = spec;
    other.seed = 2;
    CHECK(rise::InputHash(other) != hash);
    other = spec;
    other.style.sway = 1e-9;
    CHECK(rise::InputHash(other) != hash);
    CHECK(rise::InputHashOfJson(R"({"a": 1, "b": [2, 3]})") == rise::InputHashOfJson(R"({"b":[2,3],"a":1})"));
    CHECK(rise::InputHashOfJson(rise::RiseSpecToJson(spec).dump()) == hash);
  }
}
