// SPDX-License-Identifier: MIT
// Building the biped in the physics world, its start poses, and reading its state back.
#include "core/biped.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtc/quaternion.hpp>
#include <glm/mat3x3.hpp>
#include <limits>
#include <map>
#include <string>

#include "base/assert.h"

namespace rise {
namespace {

constexpr float kPi = 3.14159265358979f;
// Collision categories of the body's boxes (see the constructor).
constexpr uint32_t kTrunkCategory = 0x2u, kLimbCategory = 0x4u, kHeadCategory = 0x8u;
const glm::vec3 kAxisX(1, 0, 0), kAxisY(0, 1, 0), kAxisZ(0, 0, 1);

float Radians(double degrees) {
  return static_cast<float>(degrees) * kPi / 180.0f;
}

physics::AngleRange RangeOf(const JointDof& dof) {
  return {Radians(dof.minDeg), Radians(dof.maxDeg)};
}

physics::JointType EngineType(JointKind kind) {
  switch (kind) {
    case JointKind::kHinge:
      return physics::JointType::kHinge;
    case JointKind::kUniversal:
      return physics::JointType::kUniversal;
    default:
      return physics::JointType::kGimbal;
  }
}

physics::Transform BoxTransform(const SkeletonJoint& joint, const physics::Transform& frame) {
  return {frame.position + frame.rotation * joint.box.center, frame.rotation};
}

// Lying on a side, the body rests on the lower shoulder, which sticks out farther from the
// mid-line than the hip does; with a straight spine the hips would hang in the air and the body
// would drop onto them. The pelvis is therefore tilted hips-down by this angle (degrees) so that
// shoulder and hip both touch, the spine bends back so the chest stays level, and the hips bend
// the legs back parallel to the ground.
float SideTiltDeg(const BipedDef& def) {
  const std::vector<glm::vec3> bind = def.skeleton.BindPositions();
  const SkeletonJoint& arm = def.skeleton.joints[def.Find("upper_arm_l")];
  const SkeletonJoint& thigh = def.skeleton.joints[def.Find("thigh_l")];
  const float shoulderReach = bind[def.Find("upper_arm_l")].x + arm.box.halfExtents.x;
  const float hipReach =
      std::max(def.skeleton.joints[0].box.halfExtents.x, bind[def.Find("thigh_l")].x + thigh.box.halfExtents.x);
  const float lever = bind[def.Find("upper_arm_l")].y - bind[0].y;
  return std::atan2(std::max(0.0f, shoulderReach - hipReach), lever) * 180.0f / kPi;
}

// Joint angles of a posture, degrees, for the joints it bends; the rest stay at the bind pose.
// Lying on the back or front the limbs rest almost straight with the feet relaxed (pointing
// away from the shins as far as the ankles allow when prone, so the toes do not prop the legs).
// On a side the lower arm reaches forward and the legs are bent, the recovery-position shape
// that keeps a body from rolling.
std::map<std::string, std::vector<float>> PostureAngles(const BipedDef& def, Posture posture) {
  switch (posture) {
    case Posture::kSupine:
      return {{"forearm_l", {10}}, {"forearm_r", {10}}, {"foot_l", {-20, 0}}, {"foot_r", {-20, 0}}};
    case Posture::kProne:
      return {{"forearm_l", {10}}, {"forearm_r", {10}}, {"foot_l", {-50, 0}}, {"foot_r", {-50, 0}}};
    case Posture::kSideLeft:
    case Posture::kSideRight: {
      const bool left = posture == Posture::kSideLeft;
      const std::string low = left ? "_l" : "_r";
      const std::string high = left ? "_r" : "_l";
      const float tilt = SideTiltDeg(def);
      const float bend = (left ? 0.5f : -0.5f) * tilt;  // toward the lower side, split over the spine
      return {{"abdomen", {0, bend, 0}},
              {"chest", {0, bend, 0}},
              {"upper_arm" + low, {80, 0}},
              {"forearm" + low, {30}},
              {"upper_arm" + high, {80, -25}},
              {"forearm" + high, {60}},
              {"thigh" + low, {20, -tilt}},
              {"shin" + low, {30}},
              {"thigh" + high, {70, tilt - 25}},
              {"shin" + high, {90}},
              {"foot_l", {-20, 0}},
              {"foot_r", {-20, 0}}};
    }
    case Posture::kCustom:
      return {};
  }
  return {};
}

glm::quat PostureRotation(const BipedDef& def, const StartSpec& start) {
  // The side postures' pelvis tilt, hips toward the ground (see SideTiltDeg).
  const glm::quat sideTilt = glm::angleAxis(Radians(SideTiltDeg(def)), kAxisZ);
  switch (start.posture) {
    case Posture::kSupine:
      return glm::angleAxis(-0.5f * kPi, kAxisX);  // front up, head to -Z
    case Posture::kProne:
      return glm::angleAxis(0.5f * kPi, kAxisX);  // front down, head to +Z
    case Posture::kSideLeft:
      return glm::angleAxis(-0.5f * kPi, kAxisZ) * sideTilt;  // left side down, head to +X
    case Posture::kSideRight:
      return glm::angleAxis(0.5f * kPi, kAxisZ) * glm::conjugate(sideTilt);  // head to -X
    case Posture::kCustom:
      return glm::angleAxis(Radians(start.rootEulerDeg[0]), kAxisX) *
             glm::angleAxis(Radians(start.rootEulerDeg[1]), kAxisY) *
             glm::angleAxis(Radians(start.rootEulerDeg[2]), kAxisZ);
  }
  return glm::quat(1, 0, 0, 0);
}

}  // namespace

physics::WorldSettings BipedWorldSettings() {
  physics::WorldSettings settings;
  settings.contactHertz = 60.0f;
  return settings;
}

physics::PlaneShape GroundPlane(double slopeDeg) {
  const float s = Radians(slopeDeg);
  return physics::PlaneShape{glm::vec3(0.0f, std::cos(s), -std::sin(s)), 0.0f};
}

physics::StaticShapeId AddGround(physics::World& world, const TerrainSpec& terrain) {
  return world.AddStaticPlane(GroundPlane(terrain.slopeDeg), static_cast<float>(terrain.friction));
}

BipedPose BindPose(const BipedDef& def) {
  BipedPose pose;
  pose.root.position = def.skeleton.joints[0].restOffset;
  pose.local.assign(def.skeleton.joints.size(), glm::quat(1, 0, 0, 0));
  return pose;
}

std::vector<physics::Transform> JointWorldTransforms(const BipedDef& def, const BipedPose& pose) {
  RISE_ASSERT(pose.local.size() == def.skeleton.joints.size());
  std::vector<physics::Transform> world(def.skeleton.joints.size());
  world[0] = pose.root;
  for (size_t j = 1; j < world.size(); ++j) {
    const SkeletonJoint& joint = def.skeleton.joints[j];
    const physics::Transform& parent = world[joint.parent];
    world[j].position = parent.position + parent.rotation * joint.restOffset;
    world[j].rotation = glm::normalize(parent.rotation * pose.local[j]);
  }
  return world;
}

float LowestCorner(const BipedDef& def, const BipedPose& pose, const physics::PlaneShape& plane) {
  const std::vector<physics::Transform> world = JointWorldTransforms(def, pose);
  float lowest = std::numeric_limits<float>::max();
  for (size_t j = 0; j < world.size(); ++j) {
    const SkeletonJoint& joint = def.skeleton.joints[j];
    if (!joint.hasBox) continue;
    const physics::Transform box = BoxTransform(joint, world[j]);
    for (int corner = 0; corner < 8; ++corner) {
      const glm::vec3 p = box.position + box.rotation * (BoneBox::CornerSign(corner) * joint.box.halfExtents);
      lowest = std::min(lowest, glm::dot(plane.normal, p) - plane.offset);
    }
  }
  return lowest;
}

BipedPose StartPose(const BipedDef& def, const StartSpec& start, double slopeDeg) {
  BipedPose pose = BindPose(def);
  std::map<std::string, std::vector<float>> angles = PostureAngles(def, start.posture);
  for (const auto& entry : start.jointsDeg) angles[entry.first].assign(entry.second.begin(), entry.second.end());
  for (const auto& entry : angles) {
    const int joint = def.Find(entry.first);
    RISE_ASSERT_MSG(joint >= 0 && def.DofCount(joint) == static_cast<int>(entry.second.size()),
                    "joint angles must match the joint's DOF count (the loader checks user input)");
    pose.local[joint] = def.JointRotation(joint, entry.second.data());
  }
  const physics::PlaneShape ground = GroundPlane(slopeDeg);
  const glm::quat slope = glm::angleAxis(-Radians(slopeDeg), kAxisX);  // turns +Y onto the ground normal
  pose.root.rotation =
      glm::normalize(slope * glm::angleAxis(Radians(start.headingDeg), kAxisY) * PostureRotation(def, start));
  pose.root.position = glm::vec3(0.0f);
  const float lift = kGroundClearance + static_cast<float>(start.dropHeightM) - LowestCorner(def, pose, ground);
  pose.root.position = lift * ground.normal;
  return pose;
}

std::optional<SelfOverlap> DeepestSelfOverlap(const BipedDef& def, const BipedPose& pose) {
  // The body alone in an empty world, stepped once: the step's contacts report their
  // separations at its start, found by the same broad phase, filters and narrow phase as a clip.
  physics::World world(BipedWorldSettings());
  const Biped biped(def, world, pose, 0.0f);
  world.Step();
  std::optional<SelfOverlap> deepest;
  std::vector<physics::ContactInfo> contacts;
  for (int j = 0; j < def.skeleton.JointCount(); ++j) {
    if (!def.skeleton.joints[j].hasBox) continue;
    world.GetContacts(biped.BodyOf(j), contacts);
    for (const physics::ContactInfo& contact : contacts) {
      if (contact.separation >= 0.0f || (deepest && -contact.separation <= deepest->depthM)) continue;
      const int k = biped.JointOfBody(contact.otherBody.index);
      if (k >= 0) deepest = SelfOverlap{def.skeleton.joints[j].name, def.skeleton.joints[k].name, -contact.separation};
    }
  }
  return deepest;
}

int Biped::JointOfBody(int32_t bodyIndex) const {
  for (int j = 0; j < def_.skeleton.JointCount(); ++j) {
    if (bodies_[j].IsValid() && bodies_[j].index == bodyIndex) return j;
  }
  return -1;
}

Biped::Biped(const BipedDef& def, physics::World& world, const BipedPose& pose, float friction)
    : def_(def), world_(&world) {
  const int count = def_.skeleton.JointCount();
  bodies_.assign(count, physics::BodyId{});
  joints_.assign(count, physics::JointId{});
  frames_.assign(count, glm::quat(1, 0, 0, 0));
  // Bodies and joints are made at the bind pose, where every joint frame is the same in both
  // bodies, and only then moved to `pose`: the engine takes the creation pose as qRel = identity.
  const std::vector<physics::Transform> bind = rise::JointWorldTransforms(def_, BindPose(def_));
  for (int j = 0; j < count; ++j) {
    const SkeletonJoint& joint = def_.skeleton.joints[j];
    if (!joint.hasBox) continue;
    physics::BodyDef body;
    body.box.halfExtents = joint.box.halfExtents;
    body.mass = def_.bones[j].massKg;
    body.transform = BoxTransform(joint, bind[j]);
    body.friction = friction;
    // The trunk's boxes (pelvis, abdomen, chest) and the limbs' boxes pass
    // through each other. Boxes are a coarse body: where a person's thigh
    // presses into the belly in a squat or the upper arm lies against the
    // ribs, the boxes overlap by centimetres, and colliding, they held the
    // body out of the squat it rises from (0 of 36 prone starts stood, 14
    // with this filter). Head, limbs and the ground still collide.
    const bool trunk = joint.name == "pelvis" || joint.name == "abdomen" || joint.name == "chest";
    const bool head = joint.name == "head";
    body.categoryBits = trunk ? kTrunkCategory : head ? kHeadCategory : kLimbCategory;
    body.maskBits = trunk ? ~kLimbCategory : head ? ~0u : ~kTrunkCategory;
    bodies_[j] = world.CreateBody(body);
  }
  for (int j = 1; j < count; ++j) {
    const BoneDef& bone = def_.bones[j];
    if (bone.kind == JointKind::kEnd) continue;
    RISE_ASSERT(bone.kind != JointKind::kFree);
    frames_[j] = def_.JointFrame(j);
    physics::JointDef joint;
    joint.type = EngineType(bone.kind);
    joint.bodyA = bodies_[def_.skeleton.joints[j].parent];
    joint.bodyB = bodies_[j];
    joint.anchor = bind[j].position;
    joint.frame = frames_[j];
    joint.enableLimits = true;
    if (bone.kind == JointKind::kHinge) joint.twistLimits = RangeOf(bone.dofs[0]);
    if (bone.kind == JointKind::kUniversal) {
      joint.swingYLimits = RangeOf(bone.dofs[0]);
      joint.swingZLimits = RangeOf(bone.dofs[1]);
    }
    if (bone.kind == JointKind::kBall) {
      // The gimbal's angles are about the frame's y, z and x axes (JointFrame), which are the
      // DOF axes except that z may be the second axis reversed.
      joint.swingYLimits = RangeOf(bone.dofs[0]);
      const physics::AngleRange second = RangeOf(bone.dofs[1]);
      const bool reversed = glm::dot(frames_[j] * glm::vec3(0, 0, 1), bone.dofs[1].axis) < 0.0f;
      joint.swingZLimits = reversed ? physics::AngleRange{-second.upper, -second.lower} : second;
      joint.twistLimits = RangeOf(bone.dofs[2]);
    }
    joint.motor.enabled = false;
    joint.motor.stiffness = bone.servoKp;
    joint.motor.damping = bone.servoKd;
    joint.motor.maxTorque = bone.maxTorqueNm;
    joint.motor.maxSpeed = bone.servoMaxSpeed > 0.0f ? bone.servoMaxSpeed : std::numeric_limits<float>::infinity();
    joints_[j] = world.CreateJoint(joint);
  }
  SetPose(pose);
}

void Biped::SetPose(const BipedPose& pose) {
  const std::vector<physics::Transform> world = rise::JointWorldTransforms(def_, pose);
  for (int j = 0; j < def_.skeleton.JointCount(); ++j) {
    if (!bodies_[j].IsValid()) continue;
    world_->SetTransform(bodies_[j], BoxTransform(def_.skeleton.joints[j], world[j]));
    world_->SetLinearVelocity(bodies_[j], glm::vec3(0.0f));
    world_->SetAngularVelocity(bodies_[j], glm::vec3(0.0f));
  }
}

std::vector<physics::Transform> Biped::JointWorldTransforms() const {
  std::vector<physics::Transform> world(def_.skeleton.joints.size());
  for (size_t j = 0; j < world.size(); ++j) {
    const SkeletonJoint& joint = def_.skeleton.joints[j];
    if (bodies_[j].IsValid()) {
      const physics::Transform& body = world_->GetTransform(bodies_[j]);
      world[j] = {body.position - body.rotation * joint.box.center, body.rotation};
    } else {
      const physics::Transform& parent = world[joint.parent];
      world[j] = {parent.position + parent.rotation * joint.restOffset, parent.rotation};
    }
  }
  return world;
}

BipedPose Biped::Pose() const {
  const std::vector<physics::Transform> world = JointWorldTransforms();
  BipedPose pose;
  pose.root = world[0];
  pose.local.assign(world.size(), glm::quat(1, 0, 0, 0));
  for (size_t j = 1; j < world.size(); ++j) {
    pose.local[j] = glm::normalize(glm::conjugate(world[def_.skeleton.joints[j].parent].rotation) * world[j].rotation);
  }
  return pose;
}

glm::vec3 Biped::CenterOfMass() const {
  glm::vec3 sum(0.0f);
  float mass = 0.0f;
  for (const physics::BodyId body : bodies_) {
    if (!body.IsValid()) continue;
    sum += world_->GetMass(body) * world_->GetTransform(body).position;
    mass += world_->GetMass(body);
  }
  return sum / mass;
}

glm::vec3 Biped::CenterOfMassVelocity() const {
  glm::vec3 sum(0.0f);
  float mass = 0.0f;
  for (const physics::BodyId body : bodies_) {
    if (!body.IsValid()) continue;
    sum += world_->GetMass(body) * world_->GetLinearVelocity(body);
    mass += world_->GetMass(body);
  }
  return sum / mass;
}

float Biped::MaxBodySpeed() const {
  float fastest = 0.0f;
  for (const physics::BodyId body : bodies_) {
    if (body.IsValid()) fastest = std::max(fastest, glm::length(world_->GetLinearVelocity(body)));
  }
  return fastest;
}

float Biped::LowestCorner(const physics::PlaneShape& plane) const {
  return rise::LowestCorner(def_, Pose(), plane);
}

void Biped::SetServosEnabled(bool enabled) {
  for (const physics::JointId joint : joints_) {
    if (joint.IsValid()) world_->SetMotorEnabled(joint, enabled);
  }
}

void Biped::SetServoGains(int joint, float kp, float kd, float maxTorqueNm) {
  RISE_ASSERT(joints_[joint].IsValid());
  world_->SetMotorGains(joints_[joint], kp, kd, maxTorqueNm);
}

void Biped::SetLocalTarget(int joint, const glm::quat& local) {
  RISE_ASSERT(joints_[joint].IsValid());
  world_->SetMotorTarget(joints_[joint], glm::normalize(glm::conjugate(frames_[joint]) * local * frames_[joint]));
}

void Biped::SetTargetPose(const BipedPose& pose) {
  for (int j = 0; j < def_.skeleton.JointCount(); ++j) {
    if (joints_[j].IsValid()) SetLocalTarget(j, pose.local[j]);
  }
}

glm::quat Biped::LocalRotation(int joint) const {
  RISE_ASSERT(joints_[joint].IsValid());
  return glm::normalize(frames_[joint] * world_->GetJointRelativeRotation(joints_[joint]) *
                        glm::conjugate(frames_[joint]));
}

}  // namespace rise
