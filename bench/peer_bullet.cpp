// SPDX-License-Identifier: MIT
// The ragdoll drop in Bullet 3.24 (Debian libbullet-dev), set up as Bullet's own ragdoll demo does.
//
// btDiscreteDynamicsWorld with the sequential-impulse solver at its default 10 iterations, one
// fixed step per call. Joints as in Bullet's RagdollDemo: cone-twist for waist and neck, hinges
// for elbows, wrists and knees, and btUniversalConstraint for hips, shoulders and ankles; jointed
// pairs do not collide. Bullet multiplies the two friction coefficients of a pair, so each
// surface gets sqrt(0.8) for a pair friction of 0.8 as in the other engines. Sleeping is off:
// a rise-gen character is never at rest, so every engine pays for every step.
#include "bench/ragdoll_engine.h"

#include <btBulletDynamicsCommon.h>

#include <cmath>

namespace rise::bench {

namespace {

btVector3 Bt(const glm::vec3& v) { return btVector3(v.x, v.y, v.z); }
btQuaternion Bt(const glm::quat& q) { return btQuaternion(q.x, q.y, q.z, q.w); }

class BulletRagdoll final : public RagdollEngine {
 public:
  BulletRagdoll(const scenes::RagdollScene& scene, float timeStep)
      : dispatcher_(&configuration_), world_(&dispatcher_, &broadphase_, &solver_, &configuration_), timeStep_(timeStep) {
    world_.setGravity(btVector3(0.0f, -9.81f, 0.0f));
    world_.getSolverInfo().m_numIterations = 10;
    const float friction = std::sqrt(scene.friction);

    ground_ = std::make_unique<btStaticPlaneShape>(btVector3(0.0f, 1.0f, 0.0f), 0.0f);
    groundBody_ = std::make_unique<btRigidBody>(0.0f, nullptr, ground_.get());
    groundBody_->setFriction(friction);
    world_.addRigidBody(groundBody_.get());

    for (int i = 0; i < int(scene.boxes.size()); ++i) {
      const scenes::RagdollBox& box = scene.boxes[i];
      const physics::Transform start = scenes::StartTransform(scene, i);
      shapes_.push_back(std::make_unique<btBoxShape>(Bt(box.halfExtents)));
      btVector3 inertia;
      shapes_.back()->calculateLocalInertia(box.mass, inertia);
      btRigidBody::btRigidBodyConstructionInfo info(box.mass, nullptr, shapes_.back().get(), inertia);
      info.m_startWorldTransform = btTransform(Bt(start.rotation), Bt(start.position));
      info.m_friction = friction;
      bodies_.push_back(std::make_unique<btRigidBody>(info));
      bodies_.back()->setActivationState(DISABLE_DEACTIVATION);
      world_.addRigidBody(bodies_.back().get());
    }

    for (const scenes::RagdollJoint& joint : scene.joints) {
      btRigidBody& a = *bodies_[joint.parent];
      btRigidBody& b = *bodies_[joint.child];
      const glm::quat frame = scene.startRotation * joint.frame;
      const physics::Transform startA = scenes::StartTransform(scene, joint.parent);
      const glm::vec3 anchor = startA.position + scene.startRotation * (joint.anchor - scene.boxes[joint.parent].center);
      // A joint frame as each body sees it (Bullet wants body-local frames).
      auto localFrames = [&](const glm::quat& worldFrame, btTransform& inA, btTransform& inB) {
        const btTransform world(Bt(worldFrame), Bt(anchor));
        inA = a.getCenterOfMassTransform().inverse() * world;
        inB = b.getCenterOfMassTransform().inverse() * world;
      };
      btTransform inA, inB;
      std::unique_ptr<btTypedConstraint> constraint;
      switch (joint.type) {
        case physics::JointType::kBall: {
          // Cone-twist: twist about the frame's x, swings about its y and z, symmetric twist span.
          localFrames(frame, inA, inB);
          auto coneTwist = std::make_unique<btConeTwistConstraint>(a, b, inA, inB);
          coneTwist->setLimit(joint.swingCone, joint.swingCone, joint.twistLimits.upper);
          constraint = std::move(coneTwist);
          break;
        }
        case physics::JointType::kHinge: {
          // Bullet's hinge axis is its frame's z and its angle is measured left-handed about it
          // (btHingeConstraint::getHingeAngle), so z goes along -x: the angle is then ours.
          localFrames(frame * glm::angleAxis(-0.5f * 3.14159265f, glm::vec3(0.0f, 1.0f, 0.0f)), inA, inB);
          auto hinge = std::make_unique<btHingeConstraint>(a, b, inA, inB);
          hinge->setLimit(joint.twistLimits.lower, joint.twistLimits.upper);
          constraint = std::move(hinge);
          break;
        }
        case physics::JointType::kUniversal: {
          // btUniversalConstraint is a 6-DOF joint with x locked and Euler XYZ angles, so with
          // axis1 = our z and axis2 = our y its frame is ours and R = Ry(alpha) Rz(beta).
          auto universal = std::make_unique<btUniversalConstraint>(a, b, Bt(anchor), Bt(frame * glm::vec3(0, 0, 1)),
                                                                   Bt(frame * glm::vec3(0, 1, 0)));
          universal->setLowerLimit(joint.swingYLimits.lower, joint.swingZLimits.lower);
          universal->setUpperLimit(joint.swingYLimits.upper, joint.swingZLimits.upper);
          constraint = std::move(universal);
          break;
        }
        case physics::JointType::kGimbal: {
          // RO_YZX composes R = Ry Rz Rx, as our gimbal; Bullet's angular limits are per axis x, y, z.
          localFrames(frame, inA, inB);
          auto gimbal = std::make_unique<btGeneric6DofSpring2Constraint>(a, b, inA, inB, RO_YZX);
          gimbal->setLinearLowerLimit(btVector3(0.0f, 0.0f, 0.0f));
          gimbal->setLinearUpperLimit(btVector3(0.0f, 0.0f, 0.0f));
          gimbal->setAngularLowerLimit(btVector3(joint.twistLimits.lower, joint.swingYLimits.lower, joint.swingZLimits.lower));
          gimbal->setAngularUpperLimit(btVector3(joint.twistLimits.upper, joint.swingYLimits.upper, joint.swingZLimits.upper));
          constraint = std::move(gimbal);
          break;
        }
      }
      world_.addConstraint(constraint.get(), true);
      constraints_.push_back(std::move(constraint));
    }
  }

  ~BulletRagdoll() override {
    for (auto& constraint : constraints_) world_.removeConstraint(constraint.get());
    for (auto& body : bodies_) world_.removeRigidBody(body.get());
    world_.removeRigidBody(groundBody_.get());
  }

  void Step() override { world_.stepSimulation(timeStep_, 1, timeStep_); }

  BoxState Box(int box) override {
    const btRigidBody& body = *bodies_[box];
    const btTransform& t = body.getCenterOfMassTransform();
    const btQuaternion q = t.getRotation();
    const btVector3 v = body.getLinearVelocity();
    return BoxState{{t.getOrigin().x(), t.getOrigin().y(), t.getOrigin().z()}, {q.w(), q.x(), q.y(), q.z()},
                    {v.x(), v.y(), v.z()}};
  }

 private:
  btDefaultCollisionConfiguration configuration_;
  btCollisionDispatcher dispatcher_;
  btDbvtBroadphase broadphase_;
  btSequentialImpulseConstraintSolver solver_;
  btDiscreteDynamicsWorld world_;
  float timeStep_;
  std::unique_ptr<btCollisionShape> ground_;
  std::unique_ptr<btRigidBody> groundBody_;
  std::vector<std::unique_ptr<btBoxShape>> shapes_;
  std::vector<std::unique_ptr<btRigidBody>> bodies_;
  std::vector<std::unique_ptr<btTypedConstraint>> constraints_;
};

}  // namespace

std::unique_ptr<RagdollEngine> MakeBulletRagdoll(const scenes::RagdollScene& scene, float timeStep) {
  return std::make_unique<BulletRagdoll>(scene, timeStep);
}

}  // namespace rise::bench
