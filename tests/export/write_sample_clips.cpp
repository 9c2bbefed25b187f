// SPDX-License-Identifier: MIT
// Writes the synthetic sample clips that the external checks (glTF-Validator,
// Blender import) read: every glTF variant the writer makes, and a BVH.
// Usage: write_sample_clips <folder>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "export/biped_fixture.h"
#include "export/bvh_writer.h"
#include "export/gltf_writer.h"
#include "export/root_motion.h"

int main(int argc, char** argv) {
  if (argc != 2) {
    std::fprintf(stderr, "usage: write_sample_clips <folder>\n");
    return 2;
  }
  std::error_code ec;
  std::filesystem::create_directories(argv[1], ec);
  const std::string folder = std::string(argv[1]) + "/";
  // 3 s at 30 fps, resampled from 240 Hz like a simulation would be.
  const rise::Skeleton skeleton = rise::test::MakeBipedSkeleton();
  rise::Clip clip = rise::ResampleClip(skeleton, rise::test::SwingSamples(skeleton, 3.0, 240.0), 30.0,
                                       rise::test::SwingClip(30.0, 3.0).metadata);
  const rise::Clip inPlace = rise::ApplyRootMotion(clip, rise::RootMotion::kInPlace);
  const rise::Clip extracted = rise::ApplyRootMotion(clip, rise::RootMotion::kExtract);
  const rise::Clip fast = rise::ResampleClip(skeleton, rise::test::SwingSamples(skeleton, 1.5, 240.0), 60.0, {});

  std::string error;
  const auto check = [&error](const std::string& result) {
    if (error.empty()) error = result;
  };
  check(rise::WriteGltf(clip, folder + "sample.glb"));
  check(rise::WriteGltf(clip, folder + "sample.gltf", {rise::NamingPreset::kDefault, false}));
  check(rise::WriteGltf(inPlace, folder + "sample_in_place.glb"));
  check(rise::WriteGltf(extracted, folder + "sample_extract.glb"));
  check(rise::WriteGltf(clip, folder + "sample_mixamo.glb", {rise::NamingPreset::kMixamo, false}));
  check(rise::WriteGltf(clip, folder + "sample_ue.glb", {rise::NamingPreset::kUe, false}));
  check(rise::WriteGltfLibrary({{"swing_30", &clip}, {"swing_60", &fast}, {"in_place", &inPlace}},
                               folder + "sample_library.glb"));
  check(rise::WriteBvh(clip, folder + "sample.bvh", {{}, rise::NamingPreset::kDefault, false}));
  check(rise::WriteBvh(clip, folder + "sample_cm_z.bvh",
                       {{rise::BvhUnits::kCentimetres, rise::BvhUp::kZ}, rise::NamingPreset::kDefault, false}));
  // What the Blender check expects to find (rise-gen world: metres, Y-up).
  nlohmann::json expect;
  expect["fps"] = clip.fps;
  expect["frameCount"] = clip.FrameCount();
  for (const rise::SkeletonJoint& joint : clip.skeleton.joints) expect["joints"].push_back(joint.name);
  const glm::vec3 head = clip.WorldPositions(clip.FrameCount() - 1)[clip.skeleton.Find("head")];
  expect["headAtLastFrame"] = {head.x, head.y, head.z};
  std::ofstream(folder + "sample_expect.json") << expect.dump(2);

  if (!error.empty()) {
    std::fprintf(stderr, "%s\n", error.c_str());
    return 1;
  }
  return 0;
}
