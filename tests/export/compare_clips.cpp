// SPDX-License-Identifier: MIT
// Reads two glTF files through the glTF reader and checks that they hold the
// same skeleton and motion: every joint of `other` that `reference` also has
// is within 1 mm at every frame, with the same bone box within 1 mm. Used on a
// file that Blender re-exported, to prove the reader handles another tool's
// conventions (bone rest rotations, its own inverse bind matrices).
// Usage: compare_clips <reference.glb> <other.glb>
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "export/gltf_reader.h"

namespace {

float Distance(const glm::vec3& a, const glm::vec3& b) {
  return glm::length(a - b);
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: compare_clips <reference.glb> <other.glb>\n");
    return 2;
  }
  rise::Clip reference, other;
  for (const auto& [path, clip] : {std::pair{argv[1], &reference}, std::pair{argv[2], &other}}) {
    if (const std::string error = rise::ReadGltf(path, *clip); !error.empty()) {
      std::fprintf(stderr, "%s\n", error.c_str());
      return 1;
    }
  }
  bool ok = other.Validate().empty() && other.FrameCount() == reference.FrameCount() &&
            other.skeleton.JointCount() == reference.skeleton.JointCount() && other.fps == reference.fps;
  std::printf("reference: %d joints, %d frames at %g fps; other: %d joints, %d frames at %g fps\n",
              reference.skeleton.JointCount(), reference.FrameCount(), reference.fps, other.skeleton.JointCount(),
              other.FrameCount(), other.fps);
  float worstPosition = 0.0f, worstBox = 0.0f;
  for (int j = 0; ok && j < other.skeleton.JointCount(); ++j) {
    const rise::SkeletonJoint& joint = other.skeleton.joints[j];
    const int r = reference.skeleton.Find(joint.name);
    if (r < 0) {
      std::printf("joint '%s' is not in the reference\n", joint.name.c_str());
      ok = false;
      break;
    }
    const rise::BoneBox& box = reference.skeleton.joints[r].box;
    if (joint.hasBox != reference.skeleton.joints[r].hasBox) ok = false;
    worstBox =
        std::max({worstBox, Distance(joint.box.center, box.center), Distance(joint.box.halfExtents, box.halfExtents)});
    for (int f = 0; f < other.FrameCount(); ++f) {
      worstPosition = std::max(worstPosition, Distance(other.WorldPositions(f)[j], reference.WorldPositions(f)[r]));
    }
  }
  std::printf("worst joint position difference %.6f m, worst box difference %.6f m\n", worstPosition, worstBox);
  ok = ok && worstPosition <= 1e-3f && worstBox <= 1e-3f;
  std::printf("%s\n", ok ? "same clip" : "the clips differ");
  return ok ? 0 : 1;
}
