// SPDX-License-Identifier: MIT
// Anthropometric body model: Winter's length fractions and Dempster's mass fractions.
#include "core/biped_def.h"

#include <algorithm>
#include <cmath>
#include <glm/geometric.hpp>
#include <glm/gtx/euler_angles.hpp>
#include <glm/mat3x3.hpp>

#include "base/assert.h"

namespace rise {
namespace {

// Default size of one segment as fractions of body height, and its mass as a
// fraction of body mass.
struct SegmentProportion {
  const char* name;
  float length, width, depth;
  float massFraction;
};

// Winter's joint heights (fractions of H): ankle 0.039, knee 0.285, hip 0.530,
// shoulder 0.818, top of head 1.0. The trunk between the hips and the neck
// base (0.84) is split into pelvis (its box starts below the hip joints, which
// sit 40 % up from its bottom, as the buttocks hang below them), abdomen and
// chest; head+neck takes 0.16.
// Widths and depths are typical adult breadths; the hand's width is its
// thickness because the palms face the thighs in the bind pose.
// One segment per row, as in the tables it comes from.
// clang-format off
constexpr SegmentProportion kProportions[] = {
    // name         length   width    depth    mass fraction
    {"pelvis",      0.100f,  0.180f,  0.110f,  0.142f},
    {"abdomen",     0.110f,  0.160f,  0.100f,  0.139f},
    {"chest",       0.140f,  0.180f,  0.115f,  0.216f},
    {"head",        0.160f,  0.090f,  0.110f,  0.081f},
    {"upper_arm_l", 0.186f,  0.055f,  0.055f,  0.028f},
    {"forearm_l",   0.146f,  0.045f,  0.045f,  0.016f},
    {"hand_l",      0.108f,  0.020f,  0.050f,  0.006f},
    {"upper_arm_r", 0.186f,  0.055f,  0.055f,  0.028f},
    {"forearm_r",   0.146f,  0.045f,  0.045f,  0.016f},
    {"hand_r",      0.108f,  0.020f,  0.050f,  0.006f},
    {"thigh_l",     0.245f,  0.080f,  0.085f,  0.100f},
    {"shin_l",      0.246f,  0.055f,  0.060f,  0.0465f},
    {"foot_l",      0.152f,  0.055f,  0.039f,  0.0145f},
    {"thigh_r",     0.245f,  0.080f,  0.085f,  0.100f},
    {"shin_r",      0.246f,  0.055f,  0.060f,  0.0465f},
    {"foot_r",      0.152f,  0.055f,  0.039f,  0.0145f},
};
// clang-format on
constexpr int kSegmentCount = static_cast<int>(sizeof(kProportions) / sizeof(kProportions[0]));

constexpr float kPelvisBelowHip = 0.4f;      // fraction of pelvis length below the hip joints
constexpr float kShoulderBelowNeck = 0.15f;  // fraction of chest length from the neck down to the shoulders
constexpr float kHeelBehindAnkle = 0.2f;     // fraction of foot length behind the ankle
constexpr float kHipHalfSpacing = 0.05f;     // hip joint centres at +-0.05 H
// Clearance between the hanging arms and the trunk/thighs, and between the thighs:
// the bind pose must not start with boxes touching.
constexpr float kArmGap = 0.012f;   // fraction of H
constexpr float kThighGap = 0.01f;  // metres

// Servo defaults: the torque cap is reached at this angle error, and damping
// follows as kp times this time constant. Starting points for the controller.
constexpr float kServoSaturationRad = 0.3f;
constexpr float kServoDampingTimeS = 0.08f;
// Closing a large error (an arm left overhead, a leg swung from lying) at the
// spring's own pace whipped hands and feet past 10 m/s; a joint closes it at
// this speed at most, and errors under kServoMaxSpeed * kServoDampingTimeS
// (in rad) are tracked as before.
constexpr float kServoMaxSpeed = 12.0f;  // rad/s (8: prone starts passing every bar 141 -> 134 of 144; 12: 141, and 14 of 300 stress runs over the 10 m/s bound -> 6)

struct Size {
  float length, width, depth, mass;
};

JointDof Dof(const char* name, glm::vec3 axis, float minDeg, float maxDeg) {
  return JointDof{name, axis, minDeg, maxDeg};
}

// Left/right mirrored axis: the given axis for the left side, its negation for the right.
glm::vec3 Side(bool left, glm::vec3 leftAxis) {
  return left ? leftAxis : -leftAxis;
}

}  // namespace

const std::vector<std::string>& SegmentNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> list;
    for (const SegmentProportion& p : kProportions) list.emplace_back(p.name);
    return list;
  }();
  return names;
}

glm::quat BipedDef::JointRotation(int joint, const float* anglesDeg) const {
  glm::quat q(1.0f, 0.0f, 0.0f, 0.0f);
  const std::vector<JointDof>& dofs = bones[joint].dofs;
  for (size_t i = 0; i < dofs.size(); ++i) q = q * glm::angleAxis(glm::radians(anglesDeg[i]), dofs[i].axis);
  return q;
}

glm::quat BipedDef::JointFrame(int joint) const {
  const BoneDef& bone = bones[joint];
  glm::vec3 x, y;
  switch (bone.kind) {
    case JointKind::kHinge:
      x = bone.dofs[0].axis;
      // Any y perpendicular to the hinge axis serves; take world Y (or Z for a vertical hinge).
      y = std::fabs(x.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(0, 0, 1);
      y = glm::normalize(y - glm::dot(y, x) * x);
      break;
    case JointKind::kUniversal:
      y = bone.dofs[0].axis;
      x = glm::cross(y, bone.dofs[1].axis);
      break;
    case JointKind::kBall:
      x = bone.dofs[2].axis;
      y = bone.dofs[0].axis;
      RISE_ASSERT(std::fabs(std::fabs(glm::dot(glm::cross(x, y), bone.dofs[1].axis)) - 1.0f) < 1e-5f);
      break;
    default:
      return glm::quat(1, 0, 0, 0);
  }
  return glm::normalize(glm::quat_cast(glm::mat3(x, y, glm::cross(x, y))));
}

void BipedDef::JointAngles(int joint, const glm::quat& local, float* anglesDeg) const {
  const glm::quat frame = JointFrame(joint);
  const glm::mat3 r = glm::mat3_cast(glm::conjugate(frame) * local * frame);
  if (bones[joint].kind == JointKind::kUniversal) {
    // As the engine measures it (physics/joint_universal.cpp): each angle in
    // (-180, 180], so a shoulder abducted past 90 deg reads as it is, where the
    // Euler extraction below folds it back with a half turn of twist.
    anglesDeg[0] = glm::degrees(std::atan2(r[2].x, r[2].z));
    anglesDeg[1] = glm::degrees(std::atan2(r[0].y, r[1].y));
    return;
  }
  float ay = 0.0f, az = 0.0f, ax = 0.0f;
  glm::extractEulerAngleYZX(glm::mat4(r), ay, az, ax);
  // F's z axis is the second DOF axis or its opposite (a ball joint's frame is right-handed
  // whichever way its DOF axes point).
  const float zSign =
      bones[joint].dofs.size() >= 2 ? glm::dot(frame * glm::vec3(0, 0, 1), bones[joint].dofs[1].axis) : 1.0f;
  const float yzx[3] = {glm::degrees(ay), zSign * glm::degrees(az), glm::degrees(ax)};
  switch (bones[joint].kind) {
    case JointKind::kHinge:
      anglesDeg[0] = yzx[2];
      break;
    case JointKind::kBall:
      for (int i = 0; i < 3; ++i) anglesDeg[i] = yzx[i];
      break;
    default:
      break;
  }
}

glm::vec3 BipedDef::BindCenterOfMass() const {
  const std::vector<glm::vec3> positions = skeleton.BindPositions();
  glm::vec3 sum(0.0f);
  float mass = 0.0f;
  for (int i = 0; i < skeleton.JointCount(); ++i) {
    if (!skeleton.joints[i].hasBox) continue;
    sum += bones[i].massKg * (positions[i] + skeleton.joints[i].box.center);
    mass += bones[i].massKg;
  }
  return sum / mass;
}

float BipedDef::BindHeadTop() const {
  return skeleton.BindPositions()[skeleton.Find("head_end")].y;
}

BipedDef MakeBipedDef(float heightM, float massKg, const SegmentOverrides& overrides) {
  RISE_ASSERT(heightM >= 1.2f && heightM <= 2.3f);
  RISE_ASSERT(massKg >= 30.0f && massKg <= 200.0f);
  const float h = heightM;

  // Sizes and masses per segment, overrides applied.
  std::map<std::string, Size> size;
  float fixedMass = 0.0f, freeFraction = 0.0f;
  for (const SegmentProportion& p : kProportions) {
    Size s{p.length * h, p.width * h, p.depth * h, -1.0f};
    const auto it = overrides.find(p.name);
    if (it != overrides.end()) {
      const SegmentOverride& o = it->second;
      if (o.lengthM) s.length = *o.lengthM;
      if (o.widthM) s.width = *o.widthM;
      if (o.depthM) s.depth = *o.depthM;
      if (o.massKg) s.mass = *o.massKg;
      RISE_ASSERT(s.length > 0.0f && s.width > 0.0f && s.depth > 0.0f);
    }
    if (s.mass >= 0.0f) {
      fixedMass += s.mass;
    } else {
      freeFraction += p.massFraction;
    }
    size[p.name] = s;
  }
  for (const auto& entry : overrides) RISE_ASSERT_MSG(size.count(entry.first) == 1, "unknown segment override");
  RISE_ASSERT_MSG(fixedMass < 0.9f * massKg, "overridden masses leave too little for the other segments");
  RISE_ASSERT_MSG(freeFraction > 0.0f, "at least one segment must keep its default mass share");
  // The segments without a mass override share what is left in their default ratios.
  const float freeMassScale = (massKg - fixedMass) / freeFraction;
  for (const SegmentProportion& p : kProportions) {
    if (size[p.name].mass < 0.0f) size[p.name].mass = p.massFraction * freeMassScale;
  }

  const Size& pelvis = size["pelvis"];
  const Size& abdomen = size["abdomen"];
  const Size& chest = size["chest"];
  const Size& head = size["head"];

  // Lateral placement: hips far enough apart that the thighs never touch; shoulders
  // far enough out that each arm segment clears the trunk and the thighs.
  float hipX = kHipHalfSpacing * h;
  for (const char* thigh : {"thigh_l", "thigh_r"}) hipX = std::max(hipX, 0.5f * size[thigh].width + 0.5f * kThighGap);
  float innerX = std::max({0.5f * pelvis.width, 0.5f * abdomen.width, 0.5f * chest.width});
  for (const char* thigh : {"thigh_l", "thigh_r"}) innerX = std::max(innerX, hipX + 0.5f * size[thigh].width);
  float armHalfWidth = 0.0f;
  for (const char* arm : {"upper_arm_l", "forearm_l", "hand_l", "upper_arm_r", "forearm_r", "hand_r"}) {
    armHalfWidth = std::max(armHalfWidth, 0.5f * size[arm].width);
  }
  const float shoulderX = innerX + kArmGap * h + armHalfWidth;

  BipedDef def;
  def.heightM = heightM;
  def.massKg = massKg;
  std::vector<SkeletonJoint>& joints = def.skeleton.joints;

  // Adds a joint; `box` false for end joints. Returns its index.
  auto add = [&](const std::string& name, const std::string& parent, glm::vec3 offset, const Size* s,
                 glm::vec3 boxCenter, BoneDef bone) {
    SkeletonJoint joint;
    joint.name = name;
    joint.parent = parent.empty() ? -1 : def.skeleton.Find(parent);
    RISE_ASSERT(parent.empty() || joint.parent >= 0);
    joint.restOffset = offset;
    if (s != nullptr) {
      joint.hasBox = true;
      joint.box.center = boxCenter;
      // The foot's length runs along z and its depth (height) along y.
      const bool foot = name.rfind("foot", 0) == 0;
      joint.box.halfExtents =
          0.5f * (foot ? glm::vec3(s->width, s->depth, s->length) : glm::vec3(s->width, s->length, s->depth));
      bone.massKg = s->mass;
    }
    if (bone.maxTorqueNm > 0.0f) {
      bone.servoKp = bone.maxTorqueNm / kServoSaturationRad;
      bone.servoKd = bone.servoKp * kServoDampingTimeS;
      bone.servoMaxSpeed = kServoMaxSpeed;
    }
    joints.push_back(joint);
    def.bones.push_back(std::move(bone));
  };
  auto joint = [&](JointKind kind, float torquePerKg, std::vector<JointDof> dofs) {
    BoneDef bone;
    bone.kind = kind;
    bone.dofs = std::move(dofs);
    bone.maxTorqueNm = torquePerKg * massKg;
    return bone;
  };
  const BoneDef end{};
  const glm::vec3 kX(1, 0, 0), kY(0, 1, 0), kZ(0, 0, 1);

  // Trunk and head. The soles are on y = 0, so the hips sit at ankle + shin + thigh.
  const float hipY = std::max(size["foot_l"].depth + size["shin_l"].length + size["thigh_l"].length,
                              size["foot_r"].depth + size["shin_r"].length + size["thigh_r"].length);
  BoneDef root;
  root.kind = JointKind::kFree;
  add("pelvis", "", {0, hipY, 0}, &pelvis, {0, (0.5f - kPelvisBelowHip) * pelvis.length, 0}, root);
  add("abdomen", "pelvis", {0, (1.0f - kPelvisBelowHip) * pelvis.length, 0}, &abdomen, {0, 0.5f * abdomen.length, 0},
      joint(JointKind::kBall, TorquePerKg::kSpine,
            {Dof("flexion", kX, -25, 45), Dof("bend_left", -kZ, -25, 25), Dof("twist_left", kY, -30, 30)}));
  add("chest", "abdomen", {0, abdomen.length, 0}, &chest, {0, 0.5f * chest.length, 0},
      joint(JointKind::kBall, TorquePerKg::kSpine,
            {Dof("flexion", kX, -20, 40), Dof("bend_left", -kZ, -20, 20), Dof("twist_left", kY, -35, 35)}));
  add("head", "chest", {0, chest.length, 0}, &head, {0, 0.5f * head.length, 0},
      joint(JointKind::kBall, TorquePerKg::kNeck,
            {Dof("flexion", kX, -50, 60), Dof("bend_left", -kZ, -40, 40), Dof("twist_left", kY, -70, 70)}));
  add("head_end", "head", {0, head.length, 0}, nullptr, {}, end);

  for (const bool left : {true, false}) {
    const std::string s = left ? "_l" : "_r";
    const float sign = left ? 1.0f : -1.0f;
    const Size& upper = size["upper_arm" + s];
    const Size& fore = size["forearm" + s];
    const Size& hand = size["hand" + s];
    add("upper_arm" + s, "chest", {sign * shoulderX, (1.0f - kShoulderBelowNeck) * chest.length, 0}, &upper,
        {0, -0.5f * upper.length, 0},
        joint(JointKind::kUniversal, TorquePerKg::kShoulder,
              {Dof("flexion", -kX, -60, 170), Dof("abduction", Side(left, kZ), -30, 100)}));
    add("forearm" + s, "upper_arm" + s, {0, -upper.length, 0}, &fore, {0, -0.5f * fore.length, 0},
        joint(JointKind::kHinge, TorquePerKg::kElbow, {Dof("flexion", -kX, 0, 150)}));
    add("hand" + s, "forearm" + s, {0, -fore.length, 0}, &hand, {0, -0.5f * hand.length, 0},
        joint(JointKind::kUniversal, TorquePerKg::kWrist,
              {Dof("flexion", Side(left, -kZ), -70, 80), Dof("radial_deviation", -kX, -35, 20)}));
    add("hand" + s + "_end", "hand" + s, {0, -hand.length, 0}, nullptr, {}, end);
  }
  for (const bool left : {true, false}) {
    const std::string s = left ? "_l" : "_r";
    const float sign = left ? 1.0f : -1.0f;
    const Size& thigh = size["thigh" + s];
    const Size& shin = size["shin" + s];
    const Size& foot = size["foot" + s];
    // A leg shorter than the other hangs with its sole above the ground; the
    // longer leg defines hipY, so neither foot starts inside the ground.
    add("thigh" + s, "pelvis", {sign * hipX, 0, 0}, &thigh, {0, -0.5f * thigh.length, 0},
        joint(JointKind::kUniversal, TorquePerKg::kHip,
              {Dof("flexion", -kX, -30, 120), Dof("abduction", Side(left, kZ), -30, 50)}));
    add("shin" + s, "thigh" + s, {0, -thigh.length, 0}, &shin, {0, -0.5f * shin.length, 0},
        joint(JointKind::kHinge, TorquePerKg::kKnee, {Dof("flexion", kX, 0, 150)}));
    // Dorsiflexion to 40 deg: with the knee bent and the body's weight on it, as
    // in a squat, an ankle bends about that far, further than it is bent
    // unloaded. At 30 a body squatting to rise facing up a slope could not bring
    // its CoM over its feet: 1500 stress starts stood 1070 -> 1124 with 40 (the
    // plan 5 deg short of it, see body_pose_ik.cpp), 868 -> 900 of 973 up to 10
    // deg of slope.
    add("foot" + s, "shin" + s, {0, -shin.length, 0}, &foot,
        {0, -0.5f * foot.depth, (0.5f - kHeelBehindAnkle) * foot.length},
        joint(JointKind::kUniversal, TorquePerKg::kAnkle,
              {Dof("dorsiflexion", -kX, -50, 40), Dof("inversion", Side(left, -kZ), -20, 35)}));
    add("foot" + s + "_end", "foot" + s, {0, -foot.depth, (1.0f - kHeelBehindAnkle) * foot.length}, nullptr, {}, end);
  }

  RISE_ASSERT(static_cast<int>(joints.size()) == kSegmentCount + 5);
  RISE_ASSERT(def.skeleton.Validate().empty());
  return def;
}

}  // namespace rise
