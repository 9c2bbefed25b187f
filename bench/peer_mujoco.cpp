// SPDX-License-Identifier: MIT
// The ragdoll drop in MuJoCo 2.2.2 (Debian libmujoco-dev), as an MJCF model built in memory.
//
// MuJoCo defaults except the time step (1/240 s) and gravity along -y: Euler integrator, Newton
// solver, pyramidal friction cone, soft contacts (solref 0.02 1). The ragdoll is a kinematic tree
// in joint coordinates: a free pelvis, ball joints at waist and neck, hinges at elbows, wrists and
// knees, and two hinges (first about the parent's y, then about the child's z) for hips,
// shoulders and ankles. MuJoCo's ball limit bounds the whole rotation angle, so waist and neck are
// limited by their cone angle. Joint separation is zero by construction in joint coordinates and
// is measured anyway. Friction 0.8 on every geom (MuJoCo takes the pair's maximum); MuJoCo skips
// parent-child contacts, as the other engines skip jointed pairs.
#include "bench/ragdoll_engine.h"

#include <mujoco/mujoco.h>

#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <string>

namespace rise::bench {

namespace {

std::string Number(float value) {
  char text[32];
  std::snprintf(text, sizeof(text), "%.9g", double(value));
  return text;
}

std::string Vec(const glm::vec3& v) {
  char text[96];
  std::snprintf(text, sizeof(text), "%.9g %.9g %.9g", double(v.x), double(v.y), double(v.z));
  return text;
}

std::string Quat(const glm::quat& q) {
  char text[128];
  std::snprintf(text, sizeof(text), "%.9g %.9g %.9g %.9g", double(q.w), double(q.x), double(q.y), double(q.z));
  return text;
}

std::string Range(physics::AngleRange range) {
  char text[64];
  std::snprintf(text, sizeof(text), "%.9g %.9g", double(range.lower), double(range.upper));
  return text;
}

// The body of box `index` and its subtree: body frames sit at the box centres, axis-aligned at
// the bind pose, so a child's position is its bind centre minus its parent's.
void AppendBody(const scenes::RagdollScene& scene, int index, std::string& xml) {
  const scenes::RagdollBox& box = scene.boxes[index];
  if (index == 0) {
    const physics::Transform start = scenes::StartTransform(scene, 0);
    xml += "<body name='" + box.name + "' pos='" + Vec(start.position) + "' quat='" + Quat(start.rotation) + "'>";
    xml += "<freejoint/>";
  }
  for (const scenes::RagdollJoint& joint : scene.joints) {
    if (joint.child != index) continue;
    const scenes::RagdollBox& parent = scene.boxes[joint.parent];
    xml += "<body name='" + box.name + "' pos='" + Vec(box.center - parent.center) + "'>";
    const std::string pos = " pos='" + Vec(joint.anchor - box.center) + "'";
    switch (joint.type) {
      case physics::JointType::kBall:
        xml += "<joint type='ball'" + pos + " limited='true' range='" + Range({0.0f, joint.swingCone}) + "'/>";
        break;
      case physics::JointType::kHinge:
        xml += "<joint type='hinge'" + pos + " axis='" + Vec(joint.frame * glm::vec3(1, 0, 0)) +
               "' limited='true' range='" + Range(joint.twistLimits) + "'/>";
        break;
      case physics::JointType::kUniversal:
        xml += "<joint type='hinge'" + pos + " axis='" + Vec(joint.frame * glm::vec3(0, 1, 0)) +
               "' limited='true' range='" + Range(joint.swingYLimits) + "'/>";
        xml += "<joint type='hinge'" + pos + " axis='" + Vec(joint.frame * glm::vec3(0, 0, 1)) +
               "' limited='true' range='" + Range(joint.swingZLimits) + "'/>";
        break;
      case physics::JointType::kGimbal:
        // Three hinges in a body compose in order: Ry(alpha) Rz(beta) Rx(gamma), as ours.
        xml += "<joint type='hinge'" + pos + " axis='" + Vec(joint.frame * glm::vec3(0, 1, 0)) +
               "' limited='true' range='" + Range(joint.swingYLimits) + "'/>";
        xml += "<joint type='hinge'" + pos + " axis='" + Vec(joint.frame * glm::vec3(0, 0, 1)) +
               "' limited='true' range='" + Range(joint.swingZLimits) + "'/>";
        xml += "<joint type='hinge'" + pos + " axis='" + Vec(joint.frame * glm::vec3(1, 0, 0)) +
               "' limited='true' range='" + Range(joint.twistLimits) + "'/>";
        break;
    }
  }
  xml += "<geom type='box' size='" + Vec(box.halfExtents) + "' mass='" + Number(box.mass) + "'/>";
  for (const scenes::RagdollJoint& joint : scene.joints) {
    if (joint.parent == index) AppendBody(scene, joint.child, xml);
  }
  xml += "</body>";
}

std::string RagdollMjcf(const scenes::RagdollScene& scene, float timeStep) {
  std::string xml = "<mujoco model='ragdoll_drop'><compiler angle='radian'/>";
  xml += "<option timestep='" + Number(timeStep) + "' gravity='0 -9.81 0'/>";
  xml += "<default><geom friction='" + Number(scene.friction) + " 0.005 0.0001'/></default>";
  // The plane's normal is its z axis; turned -90 deg about x it points along +y.
  xml += "<worldbody><geom type='plane' size='0 0 1' quat='0.707106781 -0.707106781 0 0'/>";
  AppendBody(scene, 0, xml);
  xml += "</worldbody></mujoco>";
  return xml;
}

class MujocoRagdoll final : public RagdollEngine {
 public:
  MujocoRagdoll(const scenes::RagdollScene& scene, float timeStep) {
    const std::string xml = RagdollMjcf(scene, timeStep);
    auto vfs = std::make_unique<mjVFS>();
    mj_defaultVFS(vfs.get());
    const char* kFile = "ragdoll_drop.xml";
    mj_makeEmptyFileVFS(vfs.get(), kFile, int(xml.size()));
    std::memcpy(vfs->filedata[mj_findFileVFS(vfs.get(), kFile)], xml.data(), xml.size());
    char error[1000] = "";
    model_ = mj_loadXML(kFile, vfs.get(), error, sizeof(error));
    mj_deleteVFS(vfs.get());
    if (!model_) throw std::runtime_error(std::string("MuJoCo rejected the ragdoll model: ") + error);
    data_ = mj_makeData(model_);
    for (const scenes::RagdollBox& box : scene.boxes) bodyIds_.push_back(mj_name2id(model_, mjOBJ_BODY, box.name.c_str()));
  }

  ~MujocoRagdoll() override {
    mj_deleteData(data_);
    mj_deleteModel(model_);
  }

  // mj_step leaves the derived positions of the state it started from; they are brought up to
  // date only when read (outside the timed loop).
  void Step() override {
    mj_step(model_, data_);
    current_ = false;
  }

  BoxState Box(int box) override {
    if (!current_) {
      mj_forward(model_, data_);
      current_ = true;
    }
    const int id = bodyIds_[box];
    const mjtNum* p = data_->xpos + 3 * id;
    const mjtNum* q = data_->xquat + 4 * id;
    mjtNum velocity[6];  // angular, then linear at the body frame origin, world axes
    mj_objectVelocity(model_, data_, mjOBJ_BODY, id, velocity, 0);
    return BoxState{glm::vec3(float(p[0]), float(p[1]), float(p[2])),
                    glm::quat(float(q[0]), float(q[1]), float(q[2]), float(q[3])),
                    glm::vec3(float(velocity[3]), float(velocity[4]), float(velocity[5]))};
  }

 private:
  mjModel* model_ = nullptr;
  mjData* data_ = nullptr;
  std::vector<int> bodyIds_;
  bool current_ = true;
};

}  // namespace

std::unique_ptr<RagdollEngine> MakeMujocoRagdoll(const scenes::RagdollScene& scene, float timeStep) {
  return std::make_unique<MujocoRagdoll>(scene, timeStep);
}

}  // namespace rise::bench
