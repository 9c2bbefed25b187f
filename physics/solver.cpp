// SPDX-License-Identifier: MIT
// The soft step (Box2D v3's solver, scalar and single-threaded).
//
// Stage order and why:
// - Collide once per step: manifolds and effective masses are reused by every sub-step; anchors
//   move with the bodies, so separations stay current without re-running the narrow phase.
// - Sub-steps: each integrates gravity and applied forces, warm starts with the last impulses,
//   solves once with a soft position bias, integrates positions, then relaxes once without bias.
//   The relax pass removes the velocity that the bias added, so overlap and joint drift are
//   corrected in position only and never turn into kinetic energy (see contact_solver.cpp).
// - Joints before contacts within each pass: contacts then see the limbs where the joints put
//   them, which keeps hands and feet resting on the ground from being pulled through it.
// Determinism: one thread, fixed loop orders, no containers with unspecified iteration order,
// and the build uses -ffp-contract=off, so the same input gives bit-identical states.
#include "physics/solver.h"

#include "physics/constraint_parts.h"
#include "physics/contact_solver.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace rise::physics {

namespace {

Body& BodyOrStatic(WorldState& state, int32_t index) {
  return index >= 0 ? state.bodies[index] : state.staticBody;
}

SolverContext MakeContext(const WorldSettings& settings) {
  SolverContext context;
  context.h = settings.timeStep / float(settings.substepCount);
  context.invH = 1.0f / context.h;
  // A spring stiffer than a quarter of the sub-step rate is no longer resolved by the integrator:
  // uncapped 240 Hz joints at one or two sub-steps pumped energy into a swinging chain (measured).
  const float contactHertz = std::min(settings.contactHertz, 0.25f * context.invH);
  context.contactSoftness = MakeSoftness(contactHertz, settings.contactDampingRatio, context.h);
  // Only one side moves against static geometry, so the same response needs half the effective
  // mass-weighted stiffness; doubling the frequency keeps resting bodies shallower in the ground.
  context.staticContactSoftness = MakeSoftness(2.0f * contactHertz, settings.contactDampingRatio, context.h);
  const float jointHertz = std::min(settings.jointHertz, 0.25f * context.invH);
  context.jointSoftness = MakeSoftness(jointHertz, settings.jointDampingRatio, context.h);
  context.contactPushMaxSpeed = settings.contactPushMaxSpeed;
  context.contactRigidDepth = settings.contactRigidDepth;
  context.contactImpactSpeed = settings.contactImpactSpeed;
  context.stepTime = settings.timeStep;
  context.warmStart = settings.enableWarmStarting;
  return context;
}

void PrepareJoints(WorldState& state, const SolverContext& context) {
  JointTree& tree = state.jointTree;
  const bool direct = state.settings.jointSolver == JointSolver::kDirectTree;
  if (tree.active != direct || tree.builtJointCount != int32_t(state.joints.size())) {
    BuildJointTree(tree, state.joints, int(state.bodies.size()), direct);
  }
  bool posesChanged = false;
  for (Joint& joint : state.joints) {
    posesChanged = posesChanged || !joint.rowsCurrent;
    PrepareJoint(joint, BodyOrStatic(state, joint.bodyA), state.bodies[joint.bodyB], context);
  }
  // The last position integration factorised at these poses unless a body was moved since.
  if (tree.active && (posesChanged || !tree.factorCurrent)) FactorJointTree(tree, state.joints, state.bodies);
}

void WarmStart(WorldState& state) {
  WarmStartJoints(state.joints, state.bodies, state.staticBody);
  WarmStartContacts(state.contacts, state.bodies, state.staticBody);
}

// exactJoints: whether this pass ends with the joint forest's exact solve (kDirectTree only).
void Solve(WorldState& state, const SolverContext& context, bool useBias, bool exactJoints) {
  const bool exact = state.jointTree.active && exactJoints;
  auto solveTree = [&] {
    SolveJointTree(state.jointTree, state.joints, state.bodies, state.staticBody,
                   useBias ? state.settings.jointTreeErrorReduction * context.invH : 0.0f);
  };
  SolveJoints(state.joints, state.bodies, state.staticBody, context, useBias);
  bool hard = SolveContacts(state.contacts, state.bodies, state.staticBody, context, useBias);
  // A hard contact (settings.h) is a limb the ground stops while the body above it still moves:
  // one joint pass hands on only part of that stop, and the soft joint rows leak, so the joint
  // next to the limb opened by 1-1.5 cm in one step. More joint passes with rigid rows carry the
  // stop up the chain. Passes without hard contacts, all of a resting or crawling body's, skip it.
  // Under the direct solver the joints' point parts are the exact solve, so it is in the loop too:
  // left to the end alone, it handed the whole stop back to the limbs after the ground's last
  // word, and a foot striking at 4.6 m/s went 2 cm into the ground (a dropped biped's landing,
  // stress seed 5101; 1.2 cm with it in the loop).
  if (hard && state.settings.hardContactIterations > 0) {
    SolverContext hardContext = context;
    hardContext.jointSoftness.massScale = 1.0f;
    hardContext.jointSoftness.impulseScale = 0.0f;
    for (int i = 0; hard && i < state.settings.hardContactIterations; ++i) {
      SolveJoints(state.joints, state.bodies, state.staticBody, hardContext, useBias);
      if (exact) solveTree();
      hard = SolveContacts(state.contacts, state.bodies, state.staticBody, context, useBias);
    }
  }
  // Last, so the joints' anchors have the final word in every pass: contacts forgive a little
  // overlap (soft, and the next pass corrects it) where an open joint would show on screen.
  if (exact) solveTree();
}

// Moves the bodies, then refreshes the joints' pose-dependent rows (and the joint forest's
// factorisation) once for every pass that sees these poses (this sub-step's relax, the next
// sub-step's warm start and solve).
void IntegratePositions(WorldState& state, const SolverContext& context) {
  IntegratePositions(state.bodies, context.h);
  for (Joint& joint : state.joints) {
    UpdateJointGeometry(joint, BodyOrStatic(state, joint.bodyA), state.bodies[joint.bodyB], context);
  }
  if (state.jointTree.active) FactorJointTree(state.jointTree, state.joints, state.bodies);
}

bool IsFinite(const glm::vec3& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); }

// Impulses already live in the contacts and joints for the next warm start; what is left is to
// consume the applied forces and to check the state's health.
StepStatus StoreImpulses(WorldState& state) {
  StepStatus status;
  const float maxV2 = state.settings.maxHealthyLinearSpeed * state.settings.maxHealthyLinearSpeed;
  const float maxW2 = state.settings.maxHealthyAngularSpeed * state.settings.maxHealthyAngularSpeed;
  for (size_t i = 0; i < state.bodies.size(); ++i) {
    Body& body = state.bodies[i];
    body.force = glm::vec3(0.0f);
    body.torque = glm::vec3(0.0f);
    const glm::quat& q = body.transform.rotation;
    uint32_t flags = kStepOk;
    if (!IsFinite(body.transform.position) || !IsFinite(body.linearVelocity) || !IsFinite(body.angularVelocity) ||
        !std::isfinite(q.w) || !IsFinite(glm::vec3(q.x, q.y, q.z))) {
      flags |= kStepNonFinite;
    } else if (glm::dot(body.linearVelocity, body.linearVelocity) > maxV2 ||
               glm::dot(body.angularVelocity, body.angularVelocity) > maxW2) {
      flags |= kStepSpeedExceeded;
    }
    if (flags != kStepOk && status.firstBadBody < 0) status.firstBadBody = int32_t(i);
    status.flags |= flags;
  }
  return status;
}

}  // namespace

StepStatus Step(WorldState& state) {
  const SolverContext context = MakeContext(state.settings);

  Collide(state.bodies, state.statics, state.joinedPairs, state.settings, state.contacts, state.collideScratch);
  PrepareContacts(state.contacts, state.bodies, state.staticBody, context);
  PrepareJoints(state, context);

  for (int substep = 0; substep < state.settings.substepCount; ++substep) {
    IntegrateVelocities(state.bodies, state.settings.gravity, context.h);
    if (context.warmStart) WarmStart(state);
    const int solves = state.settings.solveIterations;
    const int relaxes = state.settings.relaxIterations;
    // The exact solve in the first biased pass spreads the joint impulses before the contacts
    // and limits converge, and in the last it gives the anchors the final word; in the passes
    // between, the rows after it undo most of what it did. Leaving it out of the middle pass of
    // 1 sub-step x 3 solves changed the ragdoll drop's peak penetration and joint separation by
    // 0.01 mm and saved 5 % of the step.
    for (int i = 0; i < solves; ++i) Solve(state, context, true, i == 0 || i == solves - 1);
    if (solves > 0 && relaxes == 0) StoreJointWarmStarts(state.joints, context);
    IntegratePositions(state, context);
    for (int i = 0; i < relaxes; ++i) Solve(state, context, false, true);
    if (relaxes > 0) StoreJointWarmStarts(state.joints, context);
  }

  state.status = StoreImpulses(state);
  return state.status;
}

}  // namespace rise::physics
