// SPDX-License-Identifier: MIT
// How close the whole-body CoM can come to the feet while both hands stay on the ground, for the
// body the input describes (default 1.75 m / 70 kg): the geometry that decides whether a get-up can
// hand its weight from hands to feet quasi-statically, or needs a dynamic transfer.
//
// Two stances, each searched over the trunk (pelvis height and position, pitch, spine curl) and the
// heel lift, with every hand and foot on its spot (the body's own IK, joint limits included) and no
// trunk or limb box through the ground:
//   hands ahead   feet on their toes at z = 0, hands D ahead: how far back can the CoM go?
//   hands behind  feet flat at z = 0 (ankles), hands H behind: how far forward can the CoM go?
// A CoM still outside the soles in the best pose means that stance cannot let go of its hands
// without falling, whatever the controller does.
//
//   reach_probe [--samples N] [--height M] [--mass KG]
#include "core/biped_def.h"
#include "core/body_pose_ik.h"
#include "core/rise_spec.h"

#include <glm/geometric.hpp>
#include <glm/gtc/constants.hpp>
#include <glm/gtc/quaternion.hpp>

#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <random>

namespace {

using rise::BodyPose;
using rise::PoseGoal;

struct Probe {
  rise::BipedDef def;
  rise::BodyRig rig;
  float mass = 0.0f;

  explicit Probe(const rise::CharacterSpec& character)
      : def(rise::MakeBipedDef(character)), rig(rise::BodyRig::FromDef(def)) {
    for (const rise::BoneDef& bone : def.bones) mass += bone.massKg;
  }

  glm::vec3 Com(const BodyPose& pose) const {
    glm::vec3 sum(0.0f);
    for (int j = 0; j < def.skeleton.JointCount(); ++j) {
      const rise::SkeletonJoint& joint = def.skeleton.joints[j];
      if (joint.hasBox) sum += def.bones[j].massKg * (pose.worldPositions[j] + pose.worldRotations[j] * joint.box.center);
    }
    return sum / mass;
  }

  // Every hand and foot on its spot, the feet's soles as wanted, no trunk or limb box centre
  // lower than its own half depth would allow.
  bool Valid(const PoseGoal& goal, const BodyPose& pose) const {
    for (int i = 0; i < rise::kLimbCount; ++i) {
      if (glm::length(pose.worldPositions[rig.end[i]] - goal.limbs[i].target) > 0.01f) return false;
    }
    if (!pose.endMatched[2] || !pose.endMatched[3]) return false;
    for (int j = 0; j < def.skeleton.JointCount(); ++j) {
      const rise::SkeletonJoint& joint = def.skeleton.joints[j];
      bool end = false;
      for (int i = 0; i < rise::kLimbCount; ++i) end = end || j == rig.end[i];
      if (!joint.hasBox || end) continue;
      if ((pose.worldPositions[j] + pose.worldRotations[j] * joint.box.center).y < 0.04f) return false;
    }
    return true;
  }

  // Best CoM z over random trunks: sign +1 maximises (hands behind), -1 minimises (hands ahead).
  float Search(float handZ, bool feetOnToes, float sign, int samples, std::mt19937& rng) const {
    std::uniform_real_distribution<float> unit(0.0f, 1.0f);
    const rise::BoneBox& foot = def.skeleton.joints[rig.end[2]].box;
    const glm::vec3 toeLocal(0.0f, foot.center.y - foot.halfExtents.y, foot.center.z + foot.halfExtents.z);
    const float pi = glm::pi<float>();
    float best = -1e9f;
    for (int k = 0; k < samples; ++k) {
      const float pitch = glm::radians(-80.0f + 210.0f * unit(rng));  // from face down: pi/2 upright
      const float curl = glm::radians(-10.0f + 85.0f * unit(rng));
      const float heel = feetOnToes ? glm::radians(70.0f * unit(rng)) : 0.0f;
      PoseGoal goal;
      goal.pelvisPosition = {0.0f, 0.12f + 0.7f * unit(rng), -0.8f + 1.6f * unit(rng)};
      goal.pelvisRotation = glm::angleAxis(0.5f * pi - pitch, glm::vec3(1, 0, 0));
      goal.chestRotation = goal.headRotation = glm::angleAxis(0.5f * pi - pitch + curl, glm::vec3(1, 0, 0));
      const glm::quat sole = glm::angleAxis(heel, glm::vec3(1, 0, 0));
      for (int i = 2; i < 4; ++i) {
        const float x = i == 2 ? 0.15f : -0.15f;
        goal.limbs[i].endRotation = sole;
        goal.limbs[i].target = feetOnToes ? glm::vec3(x, 0.002f, 0.0f) - sole * toeLocal
                                          : glm::vec3(x, foot.halfExtents.y - foot.center.y + 0.002f, 0.0f);
      }
      for (int i = 0; i < 2; ++i) {
        goal.limbs[i].target = {i == 0 ? 0.25f : -0.25f, 0.05f, handZ};
        goal.limbs[i].endRotation = glm::angleAxis(glm::radians(i == 0 ? 90.0f : -90.0f), glm::vec3(0, 0, 1));
      }
      const BodyPose pose = rise::SolveBodyPose(def.skeleton, rig, goal);
      if (Valid(goal, pose)) best = std::max(best, sign * Com(pose).z);
    }
    return sign * best;
  }
};

}  // namespace

int main(int argc, char** argv) {
  int samples = 300000;
  rise::CharacterSpec character;
  for (int i = 1; i + 1 < argc; i += 2) {
    if (!std::strcmp(argv[i], "--samples")) samples = std::atoi(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--height")) character.heightM = std::atof(argv[i + 1]);
    else if (!std::strcmp(argv[i], "--mass")) character.massKg = std::atof(argv[i + 1]);
  }
  const Probe probe(character);
  const rise::BoneBox& foot = probe.def.skeleton.joints[probe.rig.end[2]].box;
  const float heel = foot.center.z - foot.halfExtents.z, toe = foot.center.z + foot.halfExtents.z;
  std::mt19937 rng(1);
  std::printf("body %.2f m %.0f kg; flat sole spans z = %.3f .. %.3f m around the ankle\n", character.heightM,
              character.massKg, heel, toe);
  std::printf("hands ahead (feet on toes, toe edge at z = 0): most-back CoM\n");
  for (const float d : {1.1f, 0.9f, 0.7f, 0.5f, 0.4f, 0.3f}) {
    const float z = probe.Search(d, true, -1.0f, samples, rng);
    std::printf("  hands %.1f m ahead: CoM %+.3f m from the toe edge (%s)\n", d, z, z < 0.0f ? "over the toes" : "ahead of the feet");
  }
  std::printf("hands behind (feet flat, ankles at z = 0): most-forward CoM\n");
  for (const float h : {0.7f, 0.5f, 0.3f}) {
    const float z = probe.Search(-h, false, 1.0f, samples, rng);
    std::printf("  hands %.1f m behind: CoM %+.3f m (%s)\n", h, z, z >= heel ? "over the soles" : "behind the heels");
  }
}
