// SPDX-License-Identifier: MIT
#include <nlohmann/json.hpp>

#include "export/biped_fixture.h"
#include "export/clip_metadata_json.h"
#include "test_support.h"

TEST_SUITE("clip_metadata_json") {
  TEST_CASE("every metadata field survives a round trip") {
    rise::Clip clip = rise::test::SwingClip(30.0, 1.0);
    clip.metadata.rootMotion = "in-place";
    clip.metadata.removedTravel = {1.5f, 0.0f, -2.0f};
    clip.metadata.removedHeading = -0.75;
    clip.metadata.seed = 18446744073709551557ull;  // the largest 64-bit prime: no precision loss
    const std::string text = rise::MetadataToJson(clip);
    const nlohmann::json doc = nlohmann::json::parse(text);
    CHECK(doc["fps"] == 30.0);
    CHECK(doc["frameCount"] == 31);
    CHECK(doc["parameters"]["height"] == 1.75);
    rise::ClipMetadata back;
    REQUIRE(rise::MetadataFromJson(text, back) == "");
    CHECK(back.seed == clip.metadata.seed);
    CHECK(back.generatorVersion == RISE_VERSION);
    CHECK(back.rootMotion == "in-place");
    CHECK(back.removedTravel == clip.metadata.removedTravel);
    CHECK(back.removedHeading == -0.75);
    CHECK(back.timeToStand == 0.8);
    REQUIRE(back.phases.size() == 2);
    CHECK(back.phases[0].name == "roll");
    CHECK(back.phases[0].end == 0.4);
    REQUIRE(back.contacts.size() == 2);
    CHECK(back.contacts[1].effector == "hand_r");
    CHECK_FALSE(back.contacts[1].locked);
    CHECK(back.peakTorques == clip.metadata.peakTorques);
    CHECK(nlohmann::json::parse(back.parametersJson) == doc["parameters"]);
  }
  TEST_CASE("sidecar path and malformed documents") {
    CHECK(rise::SidecarPath("out/rise.glb") == "out/rise.meta.json");
    CHECK(rise::SidecarPath("rise.bvh") == "rise.meta.json");
    rise::ClipMetadata metadata;
    CHECK(rise::MetadataFromJson("[1, 2]", metadata).find("not a JSON object") != std::string::npos);
    CHECK(rise::MetadataFromJson(R"({"phases": [{"name": 3}]})", metadata).find("malformed") != std::string::npos);
  }
}
