// SPDX-License-Identifier: MIT
// The format-neutral animation clip: what the simulation produces and every
// writer (glTF, BVH) consumes. Writers own their file conventions; the clip owns
// only motion in rise-gen's world conventions (see skeleton.h).
//
// Validate() rules:
// - the skeleton is valid (see Skeleton::Validate);
// - fps > 0, frameCount >= 1, every track holds exactly frameCount keys;
// - rotations are unit quaternions (|q| within 1e-3 of 1) with no NaN/Inf;
// - rootTranslation is finite; metadata times lie inside [0, Duration()];
// - translations is empty or has one (empty or full, finite) track per joint.
// Frame i is at time i / fps; the duration is (frameCount - 1) / fps.
#pragma once

#include "export/skeleton.h"

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include <string>
#include <vector>

namespace rise {

// One named interval of the motion (a controller phase, e.g. "settle", "roll",
// "crawl", "rise", "stand").
struct PhaseSpan {
  std::string name;
  double start = 0.0;  // seconds
  double end = 0.0;    // seconds
};

// An interval in which an end effector rests on the ground.
struct ContactSpan {
  std::string effector;  // "hand_l", "hand_r", "foot_l", "foot_r"
  double start = 0.0;    // seconds
  double end = 0.0;      // seconds
  bool locked = false;   // planted: an engine's IK may lock it in place
};

struct ClipMetadata {
  std::vector<PhaseSpan> phases;
  std::vector<ContactSpan> contacts;
  std::string parametersJson = "{}";  // the fully resolved input, as JSON text
  std::string generatorVersion;       // rise-gen version that made the clip
  unsigned long long seed = 0;
  double timeToStand = -1.0;          // seconds; < 0 when the body never stood
  std::vector<std::pair<std::string, double>> peakTorques;  // joint -> N*m
  // How the root motion was written (export/root_motion.h): "bake", "in-place"
  // or "extract". For "in-place", what was taken out between the first and the
  // last frame, so an engine can move the character's capsule by it afterwards.
  std::string rootMotion = "bake";
  glm::vec3 removedTravel{0.0f};  // metres, horizontal (y = 0), world axes
  double removedHeading = 0.0;    // radians about +Y, counter-clockwise seen from above
};

struct Clip {
  Skeleton skeleton;
  double fps = 30.0;
  // rootTranslation[f]: world position of the root joint at frame f.
  std::vector<glm::vec3> rootTranslation;
  // rotations[j][f]: local rotation of joint j at frame f (relative to its
  // parent; for the root, its world rotation).
  std::vector<std::vector<glm::quat>> rotations;
  // Local translation tracks of joints other than the root, for the rare joint
  // that moves relative to its parent (the pelvis under an extracted ground
  // root, export/root_motion.h). Either empty, or one entry per joint where an
  // empty track means "stays at its rest offset" and a full one holds one key
  // per frame (translations[0] stays empty: the root uses rootTranslation).
  std::vector<std::vector<glm::vec3>> translations;
  ClipMetadata metadata;

  int FrameCount() const { return static_cast<int>(rootTranslation.size()); }
  double Duration() const;
  // Empty when the clip obeys the rules above, otherwise what is wrong.
  std::string Validate() const;
  // World position of every joint at frame f (forward kinematics).
  std::vector<glm::vec3> WorldPositions(int frame) const;
  // Local translation of joint j at frame f: its track key if it has one, else
  // its rest offset (for the root: rootTranslation[f]).
  glm::vec3 LocalTranslation(int joint, int frame) const;
  // World rotation of every joint at frame f.
  std::vector<glm::quat> WorldRotations(int frame) const;
};

}  // namespace rise
