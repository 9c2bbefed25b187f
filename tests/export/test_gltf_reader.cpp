// SPDX-License-Identifier: MIT
#include <fstream>

#include "export/biped_fixture.h"
#include "export/gltf_reader.h"
#include "test_support.h"

namespace {

// A hand-written glTF in another tool's style: an "Armature" node above the
// skeleton that turns Z-up into Y-up and scales centimetres to metres, a joint
// with a rest rotation, mixamo names, a 10 fps rotation track, no mesh.
// Joint "mixamorig:Hips" sits at (0, 0, 100) cm in the armature's Z-up space,
// i.e. 1 m up in the world; "mixamorig:Spine" is 50 cm further along the Hips
// frame's +Y, which the Hips rest rotation (90 degrees about X) turns into +Z
// of the armature, i.e. world +Y again.
constexpr const char* kForeignGltf = R"({
  "asset": {"version": "2.0", "generator": "another tool"},
  "scene": 0,
  "scenes": [{"nodes": [0]}],
  "nodes": [
    {"name": "Armature", "rotation": [-0.7071068, 0, 0, 0.7071068], "scale": [0.01, 0.01, 0.01], "children": [1]},
    {"name": "mixamorig:Hips", "translation": [0, 0, 100], "rotation": [0.7071068, 0, 0, 0.7071068], "children": [2]},
    {"name": "mixamorig:Spine", "translation": [0, 50, 0]}
  ],
  "skins": [{"joints": [1, 2]}],
  "animations": [{
    "channels": [{"sampler": 0, "target": {"node": 2, "path": "rotation"}}],
    "samplers": [{"input": 0, "output": 1, "interpolation": "LINEAR"}]
  }],
  "accessors": [
    {"bufferView": 0, "componentType": 5126, "count": 3, "type": "SCALAR", "min": [0], "max": [0.2]},
    {"bufferView": 1, "componentType": 5126, "count": 3, "type": "VEC4"}
  ],
  "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 12}, {"buffer": 0, "byteOffset": 12, "byteLength": 48}],
  "buffers": [{"byteLength": 60, "uri": "data:application/octet-stream;base64,AAAAAM3MzD3NzEw+AAAAAAAAAAAAAAAAAACAPwAAAAAAAAAAAAAAAAAAgD8AAAAAAAAAAAAAAAAAAIA/"}]
})";

}  // namespace

TEST_SUITE("gltf_reader") {
  TEST_CASE("another tool's armature transform, rest rotations and names are brought to rise-gen's conventions") {
    rise::test::TempFolder folder;
    const std::string path = folder.File("foreign.gltf");
    std::ofstream(path) << kForeignGltf;
    rise::Clip clip;
    REQUIRE(rise::ReadGltf(path, clip) == "");
    REQUIRE(clip.Validate() == "");
    REQUIRE(clip.skeleton.JointCount() == 2);
    CHECK(clip.skeleton.joints[0].name == "pelvis");
    CHECK(clip.skeleton.joints[1].name == "abdomen");
    CHECK_VEC3_NEAR(clip.skeleton.joints[0].restOffset, glm::vec3(0, 1, 0), 1e-5f);
    CHECK_VEC3_NEAR(clip.skeleton.joints[1].restOffset, glm::vec3(0, 0.5f, 0), 1e-5f);
    CHECK(clip.fps == 10.0);
    CHECK(clip.FrameCount() == 3);
    // Identity keys everywhere: the spine stays at its rest place.
    for (int f = 0; f < 3; ++f) {
      CHECK_QUAT_NEAR(clip.rotations[1][f], glm::quat(1, 0, 0, 0), 1e-5f);
      CHECK_VEC3_NEAR(clip.WorldPositions(f)[1], glm::vec3(0, 1.5f, 0), 1e-5f);
    }
  }
  TEST_CASE("a file without a skin, a missing file and a skin with two roots are refused with a reason") {
    rise::test::TempFolder folder;
    rise::Clip clip;
    CHECK(rise::ReadGltf(folder.File("missing.glb"), clip) != "");
    const auto without = [](std::string text, const std::string& cut, const std::string& put) {
      return text.replace(text.find(cut), cut.size(), put);
    };
    const std::string noSkin = without(kForeignGltf, R"("skins": [{"joints": [1, 2]}],)", "");
    std::ofstream(folder.File("noskin.gltf")) << noSkin;
    CHECK(rise::ReadGltf(folder.File("noskin.gltf"), clip).find("no skin") != std::string::npos);
    const std::string twoRoots = without(kForeignGltf, R"(, "children": [2]})", "}");
    std::ofstream(folder.File("tworoots.gltf")) << twoRoots;
    CHECK(rise::ReadGltf(folder.File("tworoots.gltf"), clip).find("2 root joints") != std::string::npos);
    // Spine made a parent of the Armature: Armature -> Hips -> Spine -> Armature.
    const std::string cycle =
        without(kForeignGltf, R"("translation": [0, 50, 0]})", R"("translation": [0, 50, 0], "children": [0]})");
    std::ofstream(folder.File("cycle.gltf")) << cycle;
    CHECK(rise::ReadGltf(folder.File("cycle.gltf"), clip).find("cycle") != std::string::npos);
    // A .glb cut short.
    std::ofstream(folder.File("short.glb"), std::ios::binary) << std::string("glTF\x02\0\0\0\x40\0\0\0", 12);
    CHECK(rise::ReadGltf(folder.File("short.glb"), clip) != "");
  }
}
