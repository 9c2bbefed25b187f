// SPDX-License-Identifier: MIT
// The 15-box ragdoll: segment sizes and masses after Winter's anthropometric tables, rounded.
#include "scenes/ragdoll_drop.h"

#include <glm/gtc/quaternion.hpp>

#include <algorithm>
#include <limits>

namespace rise::scenes {

namespace {

using physics::AngleRange;
using physics::JointType;

constexpr float kPi = 3.14159265358979f;

// Joint frame whose x axis is world +Y: the twist axis of vertical bones at the bind pose; its y
// axis is world -X (flexion, positive = forward) and its z axis world +Z (abduction).
glm::quat VerticalTwistFrame() { return glm::angleAxis(0.5f * kPi, glm::vec3(0.0f, 0.0f, 1.0f)); }

// Hinge frame whose x axis is world +X (the lateral axis of elbows, wrists and knees).
glm::quat LateralHingeFrame() { return glm::quat(1.0f, 0.0f, 0.0f, 0.0f); }

// The fields every joint kind sets alike.
RagdollJoint Joint(const char* name, int parent, int child, JointType type, glm::vec3 anchor, glm::quat frame) {
  RagdollJoint joint;
  joint.name = name;
  joint.parent = parent;
  joint.child = child;
  joint.type = type;
  joint.anchor = anchor;
  joint.frame = frame;
  return joint;
}

RagdollJoint Ball(const char* name, int parent, int child, glm::vec3 anchor, AngleRange twist, float cone) {
  RagdollJoint joint = Joint(name, parent, child, JointType::kBall, anchor, VerticalTwistFrame());
  joint.twistLimits = twist;
  joint.swingCone = cone;
  return joint;
}

RagdollJoint Hinge(const char* name, int parent, int child, glm::vec3 anchor, AngleRange angle) {
  RagdollJoint joint = Joint(name, parent, child, JointType::kHinge, anchor, LateralHingeFrame());
  joint.twistLimits = angle;
  return joint;
}

RagdollJoint Universal(const char* name, int parent, int child, glm::vec3 anchor, AngleRange flexion,
                       AngleRange abduction) {
  RagdollJoint joint = Joint(name, parent, child, JointType::kUniversal, anchor, VerticalTwistFrame());
  joint.swingYLimits = flexion;
  joint.swingZLimits = abduction;
  return joint;
}

// Abduction moves a left limb towards +X (positive angle about +Z) and a right limb towards -X.
AngleRange Mirror(AngleRange leftRange, float side) {
  return side > 0.0f ? leftRange : AngleRange{-leftRange.upper, -leftRange.lower};
}

}  // namespace

RagdollScene MakeRagdollDropScene() {
  RagdollScene scene;
  scene.boxes = {
      {"pelvis", {0.0f, 0.98f, 0.0f}, {0.16f, 0.10f, 0.10f}, 10.0f},
      {"torso", {0.0f, 1.28f, 0.0f}, {0.17f, 0.20f, 0.11f}, 25.0f},
      {"head", {0.0f, 1.635f, 0.0f}, {0.09f, 0.115f, 0.10f}, 5.0f},
  };
  // Limbs: left (+X) then right (-X), each root to leaf.
  for (float side : {1.0f, -1.0f}) {
    const char* prefix = side > 0.0f ? "left_" : "right_";
    const float x = 0.23f * side;
    scene.boxes.push_back({std::string(prefix) + "upper_arm", {x, 1.29f, 0.0f}, {0.045f, 0.15f, 0.045f}, 2.0f});
    scene.boxes.push_back({std::string(prefix) + "forearm", {x, 1.005f, 0.0f}, {0.04f, 0.125f, 0.04f}, 1.2f});
    scene.boxes.push_back({std::string(prefix) + "hand", {x, 0.785f, 0.0f}, {0.035f, 0.085f, 0.025f}, 0.5f});
  }
  for (float side : {1.0f, -1.0f}) {
    const char* prefix = side > 0.0f ? "left_" : "right_";
    const float x = 0.1f * side;
    scene.boxes.push_back({std::string(prefix) + "thigh", {x, 0.71f, 0.0f}, {0.075f, 0.21f, 0.075f}, 7.0f});
    scene.boxes.push_back({std::string(prefix) + "shin", {x, 0.29f, 0.0f}, {0.055f, 0.21f, 0.055f}, 3.3f});
    scene.boxes.push_back({std::string(prefix) + "foot", {x, 0.04f, 0.05f}, {0.05f, 0.04f, 0.12f}, 1.0f});
  }

  scene.joints.push_back(Ball("waist", 0, 1, {0.0f, 1.08f, 0.0f}, {-0.5f, 0.5f}, 0.6f));
  scene.joints.push_back(Ball("neck", 1, 2, {0.0f, 1.50f, 0.0f}, {-0.9f, 0.9f}, 0.7f));
  for (int s = 0; s < 2; ++s) {
    const float side = s == 0 ? 1.0f : -1.0f;
    const char* prefix = s == 0 ? "left_" : "right_";
    const int upperArm = 3 + 3 * s;
    const float x = 0.23f * side;
    scene.joints.push_back(Universal((std::string(prefix) + "shoulder").c_str(), 1, upperArm, {x, 1.44f, 0.0f},
                                     {-0.8f, 2.5f}, Mirror({-0.2f, 1.4f}, side)));
    scene.joints.push_back(Hinge((std::string(prefix) + "elbow").c_str(), upperArm, upperArm + 1, {x, 1.135f, 0.0f},
                                 {-2.5f, 0.0f}));
    scene.joints.push_back(Hinge((std::string(prefix) + "wrist").c_str(), upperArm + 1, upperArm + 2,
                                 {x, 0.87f, 0.0f}, {-1.2f, 1.2f}));
  }
  for (int s = 0; s < 2; ++s) {
    const float side = s == 0 ? 1.0f : -1.0f;
    const char* prefix = s == 0 ? "left_" : "right_";
    const int thigh = 9 + 3 * s;
    const float x = 0.1f * side;
    scene.joints.push_back(Universal((std::string(prefix) + "hip").c_str(), 0, thigh, {x, 0.92f, 0.0f}, {-0.5f, 2.0f},
                                     Mirror({-0.3f, 0.8f}, side)));
    scene.joints.push_back(Hinge((std::string(prefix) + "knee").c_str(), thigh, thigh + 1, {x, 0.50f, 0.0f},
                                 {0.0f, 2.5f}));
    scene.joints.push_back(Universal((std::string(prefix) + "ankle").c_str(), thigh + 1, thigh + 2,
                                     {x, 0.08f, 0.0f}, {-0.8f, 0.35f}, {-0.35f, 0.35f}));
  }

  // On its back (head towards -Z), rolled 20 deg about the long axis, head raised 10 deg.
  const glm::quat lie = glm::angleAxis(-0.5f * kPi, glm::vec3(1.0f, 0.0f, 0.0f));
  const glm::quat roll = glm::angleAxis(20.0f * kPi / 180.0f, glm::vec3(0.0f, 0.0f, 1.0f));
  const glm::quat pitch = glm::angleAxis(10.0f * kPi / 180.0f, glm::vec3(1.0f, 0.0f, 0.0f));
  scene.startRotation = pitch * roll * lie;
  return scene;
}

physics::Transform StartTransform(const RagdollScene& scene, int box) {
  float lowest = std::numeric_limits<float>::max();
  for (const RagdollBox& b : scene.boxes) {
    for (int corner = 0; corner < 8; ++corner) {
      const glm::vec3 sign((corner & 1) ? 1.0f : -1.0f, (corner & 2) ? 1.0f : -1.0f, (corner & 4) ? 1.0f : -1.0f);
      lowest = std::min(lowest, (scene.startRotation * (b.center + sign * b.halfExtents)).y);
    }
  }
  physics::Transform transform;
  transform.rotation = scene.startRotation;
  transform.position = scene.startRotation * scene.boxes[box].center + glm::vec3(0.0f, scene.dropHeight - lowest, 0.0f);
  return transform;
}

physics::WorldSettings FastDropSettings() {
  physics::WorldSettings settings;
  settings.jointSolver = physics::JointSolver::kDirectTree;
  // One sub-step x 2 solves let the drop's deepest corner reach 10.3 mm; 3 solves keep it at 7.9.
  settings.substepCount = 1;
  settings.solveIterations = 3;
  return settings;
}

BuiltRagdoll BuildRagdollDrop(const RagdollScene& scene, physics::World& world) {
  world.AddStaticPlane(physics::PlaneShape{{0.0f, 1.0f, 0.0f}, 0.0f}, scene.friction);
  BuiltRagdoll built;
  for (int i = 0; i < int(scene.boxes.size()); ++i) {
    physics::BodyDef def;
    def.box.halfExtents = scene.boxes[i].halfExtents;
    def.mass = scene.boxes[i].mass;
    def.transform = StartTransform(scene, i);
    def.friction = scene.friction;
    built.bodies.push_back(world.CreateBody(def));
  }
  // Joint frames are given at the bind pose; moved with the same rigid motion as the boxes.
  const glm::vec3 lift = StartTransform(scene, 0).position - scene.startRotation * scene.boxes[0].center;
  for (const RagdollJoint& joint : scene.joints) {
    physics::JointDef def;
    def.type = joint.type;
    def.bodyA = built.bodies[joint.parent];
    def.bodyB = built.bodies[joint.child];
    def.anchor = scene.startRotation * joint.anchor + lift;
    def.frame = scene.startRotation * joint.frame;
    def.enableLimits = true;
    def.twistLimits = joint.twistLimits;
    def.swingCone = joint.swingCone;
    def.swingYLimits = joint.swingYLimits;
    def.swingZLimits = joint.swingZLimits;
    built.joints.push_back(world.CreateJoint(def));
  }
  return built;
}

}  // namespace rise::scenes
