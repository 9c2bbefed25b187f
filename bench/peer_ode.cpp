// SPDX-License-Identifier: MIT
// The ragdoll drop in ODE 0.16 (Debian libode-dev, double precision), set up as ODE's demos do.
//
// dWorldQuickStep at its default 20 iterations, default ERP 0.2 and CFM; a hash space; up to 4
// contacts per box pair with mu = 0.8 (dContactApprox1: the friction pyramid scaled by the normal
// force); jointed pairs skipped in the near callback. Hinges and universal joints use their own
// stops; ODE's ball joint has no limits, so waist and neck get an Euler angular motor whose stops
// bound flexion and side bend by the cone angle and the twist by the twist range (a box instead
// of a cone). ODE measures hinge and universal angles as body 1 relative to body 2, so with the
// parent as body 1 the axes are reversed to measure the child relative to the parent as we do.
#include "bench/ragdoll_engine.h"

#include <ode/ode.h>

namespace rise::bench {

namespace {

glm::vec3 ToVec(const dReal* v) { return glm::vec3(float(v[0]), float(v[1]), float(v[2])); }

class OdeRagdoll final : public RagdollEngine {
 public:
  OdeRagdoll(const scenes::RagdollScene& scene, float timeStep) : timeStep_(timeStep), friction_(scene.friction) {
    dInitODE2(0);
    world_ = dWorldCreate();
    space_ = dHashSpaceCreate(nullptr);
    contacts_ = dJointGroupCreate(0);
    dWorldSetGravity(world_, 0.0, -9.81, 0.0);
    dCreatePlane(space_, 0.0, 1.0, 0.0, 0.0);

    for (int i = 0; i < int(scene.boxes.size()); ++i) {
      const scenes::RagdollBox& box = scene.boxes[i];
      const physics::Transform start = scenes::StartTransform(scene, i);
      const glm::vec3 size = 2.0f * box.halfExtents;
      dBodyID body = dBodyCreate(world_);
      dMass mass;
      dMassSetBoxTotal(&mass, box.mass, size.x, size.y, size.z);
      dBodySetMass(body, &mass);
      dBodySetPosition(body, start.position.x, start.position.y, start.position.z);
      const dQuaternion q = {start.rotation.w, start.rotation.x, start.rotation.y, start.rotation.z};
      dBodySetQuaternion(body, q);
      dGeomID geom = dCreateBox(space_, size.x, size.y, size.z);
      dGeomSetBody(geom, body);
      bodies_.push_back(body);
    }

    for (const scenes::RagdollJoint& joint : scene.joints) {
      dBodyID a = bodies_[joint.parent];
      dBodyID b = bodies_[joint.child];
      const glm::quat frame = scene.startRotation * joint.frame;
      const physics::Transform startA = scenes::StartTransform(scene, joint.parent);
      const glm::vec3 p = startA.position + scene.startRotation * (joint.anchor - scene.boxes[joint.parent].center);
      const glm::vec3 x = frame * glm::vec3(1, 0, 0), y = frame * glm::vec3(0, 1, 0), z = frame * glm::vec3(0, 0, 1);
      switch (joint.type) {
        case physics::JointType::kBall:
        case physics::JointType::kGimbal: {
          dJointID ball = dJointCreateBall(world_, nullptr);
          dJointAttach(ball, a, b);
          dJointSetBallAnchor(ball, p.x, p.y, p.z);
          // Euler motor: axis 0 on the parent (flexion), axis 2 on the child (twist).
          dJointID motor = dJointCreateAMotor(world_, nullptr);
          dJointAttach(motor, a, b);
          dJointSetAMotorMode(motor, dAMotorEuler);
          dJointSetAMotorAxis(motor, 0, 1, y.x, y.y, y.z);
          dJointSetAMotorAxis(motor, 2, 2, x.x, x.y, x.z);
          // A ball's cone becomes a box of swings; a gimbal's ranges are the Euler motor's own
          // (ODE's middle axis is axis 2 x axis 0, our z).
          const bool gimbal = joint.type == physics::JointType::kGimbal;
          const physics::AngleRange cone{-joint.swingCone, joint.swingCone};
          const physics::AngleRange first = gimbal ? joint.swingYLimits : cone;
          const physics::AngleRange second = gimbal ? joint.swingZLimits : cone;
          dJointSetAMotorParam(motor, dParamLoStop, first.lower);
          dJointSetAMotorParam(motor, dParamHiStop, first.upper);
          dJointSetAMotorParam(motor, dParamLoStop2, second.lower);
          dJointSetAMotorParam(motor, dParamHiStop2, second.upper);
          dJointSetAMotorParam(motor, dParamLoStop3, joint.twistLimits.lower);
          dJointSetAMotorParam(motor, dParamHiStop3, joint.twistLimits.upper);
          break;
        }
        case physics::JointType::kHinge: {
          dJointID hinge = dJointCreateHinge(world_, nullptr);
          dJointAttach(hinge, a, b);
          dJointSetHingeAnchor(hinge, p.x, p.y, p.z);
          dJointSetHingeAxis(hinge, -x.x, -x.y, -x.z);
          dJointSetHingeParam(hinge, dParamLoStop, joint.twistLimits.lower);
          dJointSetHingeParam(hinge, dParamHiStop, joint.twistLimits.upper);
          break;
        }
        case physics::JointType::kUniversal: {
          dJointID universal = dJointCreateUniversal(world_, nullptr);
          dJointAttach(universal, a, b);
          dJointSetUniversalAnchor(universal, p.x, p.y, p.z);
          dJointSetUniversalAxis1(universal, -y.x, -y.y, -y.z);
          dJointSetUniversalAxis2(universal, -z.x, -z.y, -z.z);
          dJointSetUniversalParam(universal, dParamLoStop, joint.swingYLimits.lower);
          dJointSetUniversalParam(universal, dParamHiStop, joint.swingYLimits.upper);
          dJointSetUniversalParam(universal, dParamLoStop2, joint.swingZLimits.lower);
          dJointSetUniversalParam(universal, dParamHiStop2, joint.swingZLimits.upper);
          break;
        }
      }
    }
  }

  ~OdeRagdoll() override {
    dJointGroupDestroy(contacts_);
    dSpaceDestroy(space_);
    dWorldDestroy(world_);
    dCloseODE();
  }

  void Step() override {
    dSpaceCollide(space_, this, &NearCallback);
    dWorldQuickStep(world_, timeStep_);
    dJointGroupEmpty(contacts_);
  }

  BoxState Box(int box) override {
    dBodyID body = bodies_[box];
    const dReal* q = dBodyGetQuaternion(body);
    return BoxState{ToVec(dBodyGetPosition(body)), glm::quat(float(q[0]), float(q[1]), float(q[2]), float(q[3])),
                    ToVec(dBodyGetLinearVel(body))};
  }

 private:
  static void NearCallback(void* data, dGeomID g1, dGeomID g2) {
    OdeRagdoll& self = *static_cast<OdeRagdoll*>(data);
    dBodyID b1 = dGeomGetBody(g1);
    dBodyID b2 = dGeomGetBody(g2);
    if (b1 && b2 && dAreConnectedExcluding(b1, b2, dJointTypeContact)) return;
    constexpr int kMaxContacts = 4;
    dContact contacts[kMaxContacts];
    const int count = dCollide(g1, g2, kMaxContacts, &contacts[0].geom, sizeof(dContact));
    for (int i = 0; i < count; ++i) {
      contacts[i].surface.mode = dContactApprox1;
      contacts[i].surface.mu = self.friction_;
      dJointID contact = dJointCreateContact(self.world_, self.contacts_, &contacts[i]);
      dJointAttach(contact, b1, b2);
    }
  }

  float timeStep_;
  float friction_;
  dWorldID world_ = nullptr;
  dSpaceID space_ = nullptr;
  dJointGroupID contacts_ = nullptr;
  std::vector<dBodyID> bodies_;
};

}  // namespace

std::unique_ptr<RagdollEngine> MakeOdeRagdoll(const scenes::RagdollScene& scene, float timeStep) {
  return std::make_unique<OdeRagdoll>(scene, timeStep);
}

}  // namespace rise::bench
