// SPDX-License-Identifier: MIT
#include <cstring>
#include <nlohmann/json.hpp>
#include <set>

#include "export/biped_fixture.h"
#include "export/clip_metadata_json.h"
#include "export/gltf_reader.h"
#include "export/gltf_writer.h"
#include "export/root_motion.h"
#include "test_support.h"

namespace {

// The JSON chunk of a .glb (header: magic, version, length; then chunk 0).
nlohmann::json GlbJson(const std::string& path) {
  const std::string bytes = rise::test::FileContents(path);
  REQUIRE(bytes.size() > 20);
  REQUIRE(bytes.compare(0, 4, "glTF") == 0);
  uint32_t version = 0, length = 0, chunkLength = 0;
  std::memcpy(&version, bytes.data() + 4, 4);
  std::memcpy(&length, bytes.data() + 8, 4);
  std::memcpy(&chunkLength, bytes.data() + 12, 4);
  CHECK(version == 2);
  CHECK(length == bytes.size());
  CHECK(bytes.compare(16, 4, "JSON") == 0);
  return nlohmann::json::parse(bytes.substr(20, chunkLength));
}

// Every joint's world position at frames spread over the clip agrees within `tolerance`.
void CheckSameMotion(const rise::Clip& a, const rise::Clip& b, float tolerance) {
  REQUIRE(a.FrameCount() == b.FrameCount());
  REQUIRE(a.skeleton.JointCount() == b.skeleton.JointCount());
  for (int f : {0, 1, a.FrameCount() / 3, a.FrameCount() / 2, a.FrameCount() - 2, a.FrameCount() - 1}) {
    CAPTURE(f);
    const auto pa = a.WorldPositions(f);
    const auto pb = b.WorldPositions(f);
    for (size_t j = 0; j < pa.size(); ++j) CHECK_VEC3_NEAR(pa[j], pb[j], tolerance);
  }
}

}  // namespace

TEST_SUITE("gltf_writer") {
  TEST_CASE("a .glb reads back with the same skeleton, boxes, timing, motion (within 1 mm) and metadata") {
    rise::test::TempFolder folder;
    const rise::Clip clip = rise::test::SwingClip(30.0, 4.0);
    const std::string path = folder.File("swing.glb");
    REQUIRE(rise::WriteGltf(clip, path) == "");

    rise::Clip back;
    REQUIRE(rise::ReadGltf(path, back) == "");
    REQUIRE(back.Validate() == "");
    CHECK(back.skeleton.JointCount() == 21);
    CHECK(back.FrameCount() == 121);
    CHECK(back.fps == 30.0);
    CHECK(back.Duration() == doctest::Approx(4.0).epsilon(1e-9));
    CHECK(back.translations.empty());
    for (int j = 0; j < clip.skeleton.JointCount(); ++j) {
      const rise::SkeletonJoint& a = clip.skeleton.joints[j];
      const rise::SkeletonJoint& b = back.skeleton.joints[j];
      CHECK(a.name == b.name);
      CHECK(a.parent == b.parent);
      CHECK_VEC3_NEAR(a.restOffset, b.restOffset, 1e-6f);
      CHECK(a.hasBox == b.hasBox);
      CHECK_VEC3_NEAR(a.box.center, b.box.center, 1e-6f);
      CHECK_VEC3_NEAR(a.box.halfExtents, b.box.halfExtents, 1e-6f);
    }
    CheckSameMotion(clip, back, 1e-3f);
    CHECK(back.metadata.seed == 42);
    CHECK(back.metadata.timeToStand == doctest::Approx(0.8));
    REQUIRE(back.metadata.contacts.size() == 2);
    CHECK(back.metadata.contacts[0].effector == "foot_l");
    CHECK(back.metadata.contacts[0].locked);
    CHECK(back.metadata.peakTorques == clip.metadata.peakTorques);
    CHECK(nlohmann::json::parse(back.metadata.parametersJson) == nlohmann::json::parse(clip.metadata.parametersJson));

    // The same metadata in the sidecar.
    rise::ClipMetadata sidecar;
    REQUIRE(rise::MetadataFromJson(rise::test::FileContents(folder.File("swing.meta.json")), sidecar) == "");
    CHECK(sidecar.phases.size() == 2);
    CHECK(sidecar.phases[1].name == "rise");
    CHECK(sidecar.seed == 42);
  }
  TEST_CASE("the .glb holds one root joint, bind-pose rest nodes, a skinned box mesh and one LINEAR animation") {
    rise::test::TempFolder folder;
    const rise::Clip clip = rise::test::SwingClip(60.0, 1.0);
    const std::string path = folder.File("swing.glb");
    REQUIRE(rise::WriteGltf(clip, path) == "");
    const nlohmann::json doc = GlbJson(path);

    CHECK(doc["asset"]["version"] == "2.0");
    CHECK(doc["asset"]["generator"] == std::string("rise-gen ") + RISE_VERSION);
    const auto& skin = doc["skins"][0];
    REQUIRE(skin["joints"].size() == 21);
    // Exactly one joint is not a child of another joint, and it is a scene root.
    std::set<int> children;
    for (const auto& node : doc["nodes"]) {
      for (int child : node.value("children", std::vector<int>{})) children.insert(child);
    }
    int roots = 0;
    for (int joint : skin["joints"]) roots += children.count(joint) == 0 ? 1 : 0;
    CHECK(roots == 1);
    CHECK(doc["scenes"][0]["nodes"][0] == 0);
    // Rest TRS = bind pose: translation only, equal to the rest offset.
    for (int j = 0; j < 21; ++j) {
      const auto& node = doc["nodes"][j];
      CHECK(node["name"] == clip.skeleton.joints[j].name);
      CHECK_FALSE(node.contains("rotation"));
      CHECK(node["translation"][1].get<float>() == doctest::Approx(clip.skeleton.joints[j].restOffset.y));
    }
    // 16 boxes of 24 vertices, with normals and single-bone weights.
    const auto& primitive = doc["meshes"][0]["primitives"][0];
    const auto& attributes = primitive["attributes"];
    CHECK(doc["accessors"][attributes["POSITION"].get<int>()]["count"] == 16 * 24);
    CHECK(attributes.contains("NORMAL"));
    CHECK(attributes.contains("JOINTS_0"));
    CHECK(attributes.contains("WEIGHTS_0"));
    CHECK(doc["accessors"][primitive["indices"].get<int>()]["count"] == 16 * 36);
    CHECK(primitive.contains("material"));
    CHECK(doc["materials"].size() == 1);
    // One animation: root translation + 21 rotations, LINEAR, times from 0 to the duration.
    REQUIRE(doc["animations"].size() == 1);
    const auto& animation = doc["animations"][0];
    CHECK(animation["name"] == "swing");
    CHECK(animation["channels"].size() == 22);
    for (const auto& sampler : animation["samplers"]) CHECK(sampler["interpolation"] == "LINEAR");
    const auto& times = doc["accessors"][animation["samplers"][0]["input"].get<int>()];
    CHECK(times["count"] == 61);
    CHECK(times["min"][0] == 0.0);
    CHECK(times["max"][0].get<double>() == doctest::Approx(1.0));
    CHECK(animation["extras"]["seed"] == 42);
    CHECK(animation["extras"]["contacts"][0]["footLock"] == true);
  }
  TEST_CASE("a .gltf gets its buffer in a .bin beside it and reads back the same") {
    rise::test::TempFolder folder;
    const rise::Clip clip = rise::test::SwingClip(24.0, 2.0);
    REQUIRE(rise::WriteGltf(clip, folder.File("swing.gltf")) == "");
    const nlohmann::json doc = nlohmann::json::parse(rise::test::FileContents(folder.File("swing.gltf")));
    CHECK(doc["buffers"][0]["uri"] == "swing.bin");
    CHECK(doc["buffers"][0]["byteLength"] == std::filesystem::file_size(folder.File("swing.bin")));
    rise::Clip back;
    REQUIRE(rise::ReadGltf(folder.File("swing.gltf"), back) == "");
    CHECK(back.fps == 24.0);
    CheckSameMotion(clip, back, 1e-3f);
  }
  TEST_CASE("mixamo and ue names are written and read back as canonical names") {
    rise::test::TempFolder folder;
    const rise::Clip clip = rise::test::SwingClip(30.0, 1.0);
    for (rise::NamingPreset preset : {rise::NamingPreset::kMixamo, rise::NamingPreset::kUe}) {
      const std::string path = folder.File(std::string(rise::NamingPresetName(preset)) + ".glb");
      REQUIRE(rise::WriteGltf(clip, path, {preset, false}) == "");
      CHECK(GlbJson(path)["nodes"][0]["name"] == rise::PresetJointName(preset, "pelvis"));
      rise::Clip back;
      REQUIRE(rise::ReadGltf(path, back) == "");
      for (int j = 0; j < clip.skeleton.JointCount(); ++j)
        CHECK(back.skeleton.joints[j].name == clip.skeleton.joints[j].name);
    }
  }
  TEST_CASE("an extracted root is written with the pelvis translation track and reads back within 1 mm") {
    rise::test::TempFolder folder;
    const rise::Clip clip = rise::ApplyRootMotion(rise::test::SwingClip(30.0, 3.0), rise::RootMotion::kExtract);
    REQUIRE(rise::WriteGltf(clip, folder.File("extract.glb")) == "");
    CHECK(GlbJson(folder.File("extract.glb"))["animations"][0]["channels"].size() == 2 + 22);
    rise::Clip back;
    REQUIRE(rise::ReadGltf(folder.File("extract.glb"), back) == "");
    CHECK(back.skeleton.joints[0].name == "root");
    REQUIRE(back.translations.size() == 22);
    CHECK(back.translations[1].size() == 91);
    CheckSameMotion(clip, back, 1e-3f);
  }
  TEST_CASE("several clips of one skeleton become named animations of one .glb") {
    rise::test::TempFolder folder;
    const rise::Clip a = rise::test::SwingClip(30.0, 1.0);
    const rise::Clip b = rise::test::SwingClip(60.0, 2.5);
    const rise::Clip c = rise::ApplyRootMotion(rise::test::SwingClip(24.0, 1.5), rise::RootMotion::kInPlace);
    const std::string path = folder.File("library.glb");
    REQUIRE(rise::WriteGltfLibrary({{"fallen_back", &a}, {"fallen_front", &b}, {"fallen_side", &c}}, path) == "");
    const nlohmann::json doc = GlbJson(path);
    REQUIRE(doc["animations"].size() == 3);
    CHECK(doc["animations"][1]["name"] == "fallen_front");
    CHECK(doc["animations"][2]["extras"]["rootMotion"] == "in-place");
    CHECK(doc["skins"].size() == 1);
    const auto timesOf = [&](int animation) {
      return doc["accessors"][doc["animations"][animation]["samplers"][0]["input"].get<int>()];
    };
    CHECK(timesOf(0)["count"] == 31);
    CHECK(timesOf(1)["count"] == 151);
    CHECK(timesOf(2)["count"] == 37);
    CHECK(timesOf(1)["max"][0].get<double>() == doctest::Approx(2.5));
    rise::Clip first;
    REQUIRE(rise::ReadGltf(path, first) == "");
    CheckSameMotion(a, first, 1e-3f);
    CHECK(folder.Files() == std::vector<std::string>{"library.glb"});
  }
  TEST_CASE("clips of different skeletons, an unknown extension and a missing folder fail with no file written") {
    rise::test::TempFolder folder;
    const rise::Clip a = rise::test::SwingClip(30.0, 1.0);
    const rise::Clip extracted = rise::ApplyRootMotion(a, rise::RootMotion::kExtract);
    CHECK(rise::WriteGltfLibrary({{"a", &a}, {"b", &extracted}}, folder.File("lib.glb")).find("different skeleton") !=
          std::string::npos);
    CHECK(rise::WriteGltf(a, folder.File("clip.fbx")).find(".glb or .gltf") != std::string::npos);
    CHECK(rise::WriteGltf(a, folder.File("nowhere/clip.glb")).find("does not exist") != std::string::npos);
    CHECK(rise::WriteGltf(a, folder.File("nowhere/clip.gltf")).find("does not exist") != std::string::npos);
    CHECK(folder.Files().empty());
  }
}
