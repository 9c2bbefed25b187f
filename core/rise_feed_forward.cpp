// SPDX-License-Identifier: MIT
// Gravity compensation and virtual forces on the CoM, mapped to joint torques
// through the Jacobian transpose of the limbs in contact (Coros, Beaudoin and
// van de Panne 2010): internal torques only, no force from outside the body.
#include "core/rise_controller_detail.h"

namespace rise {

using namespace rise_controller_detail;

namespace {

// Phase 2's ankle strategy: the CoM's wanted acceleration toward the balance
// point, per m of offset and per m/s (omega 3 rad/s, critically damped).
constexpr float kBalanceStiffness = 9.0f;  // 1/s^2
constexpr float kBalanceDamping = 6.0f;    // 1/s

// The virtual CoM force on hands and feet: stiffness and damping per kg of body
// (omega ~3.5 rad/s, critically damped), bounded as a fraction of the weight.
constexpr float kVirtualStiffness = 12.0f;  // 1/s^2
constexpr float kVirtualDamping = 7.0f;     // 1/s
constexpr float kMaxVirtualForce = 0.25f;

}  // namespace

RiseController::WeightShare RiseController::FeedForward(const BodyReading& r, const glm::vec3& comGoal,
                                                        std::vector<glm::vec3>& out) const {
  const Skeleton& sk = def_.skeleton;
  out.assign(sk.joints.size(), glm::vec3(0.0f));
  // Only once the body is up on its hands and feet are the supports known;
  // lying, the trunk rests on the ground and needs no help.
  WeightShare shared;
  shared.pressure = Project(ground_, r.com);
  if (phase_ == RisePhase::kSettle || phase_ == RisePhase::kRoll || phase_ == RisePhase::kPlace || !hasMove_) return shared;

  const glm::vec3 gravity(0.0f, -9.81f, 0.0f);
  // Phase 2 balances on the feet alone: the ground's push is aimed so the CoM
  // accelerates toward the balance point. For an inverted pendulum that push
  // presses at the centre of pressure h a / g behind the CoM's ground point
  // (a the wanted acceleration, h the CoM's height), inside the feet. Pressing
  // right below the CoM instead only holds the weight: a body drifting off
  // the balance point at the end of a rise kept drifting until it fell.
  glm::vec3 pressure = r.com, balanceForce(0.0f);
  if (phase_ == RisePhase::kRise || phase_ == RisePhase::kStand) {
    glm::vec3 accel = kBalanceStiffness * (BalancePoint(r) - r.com) - kBalanceDamping * r.comVelocity;
    accel.y = 0.0f;
    const glm::vec2 wanted = Ground(r.com - accel * (Height(ground_, r.com) / 9.81f));
    const SupportPolygon feet = FeetRegion(r);
    const glm::vec2 cop = feet.SignedDistance(wanted) < 0.0f ? wanted : feet.Closest(wanted);
    pressure = Project(ground_, glm::vec3(cop.x, 0.0f, cop.y));
    // The horizontal push that goes with that pressure point (clipped to the
    // feet, it may be less than wanted): m g / h times the CoM's offset from it.
    balanceForce = totalMass_ * 9.81f / std::max(0.2f, Height(ground_, r.com)) * Horizontal(r.com - pressure);
    balanceForce = AlongPlane(ground_, balanceForce);
  }
  // Share the weight among planted, touching supports: the least-norm weights
  // whose weighted centre is the pressure point, negatives dropped.
  std::array<glm::vec3, kLimbCount> point{};
  std::array<float, kLimbCount> share{};
  std::vector<int> supports;
  for (int i = 0; i < kLimbCount; ++i) {
    if (!planted_[i] || !r.touching[i]) continue;
    point[i] = SupportPoint(r, static_cast<Limb>(i), pressure);
    supports.push_back(i);
  }
  if (supports.empty()) return shared;
  const glm::vec2 c = Ground(pressure);
  for (int pass = 0; pass < 3; ++pass) {
    // Solve A A^T y = b, w = A^T y with A = [1; x; z] over the supports.
    glm::mat3 normal(0.0f);
    for (int i : supports) {
      const glm::vec3 a(1.0f, point[i].x, point[i].z);
      normal += glm::outerProduct(a, a);
    }
    const float det = glm::determinant(normal);
    bool clipped = false;
    if (std::fabs(det) > 1e-8f) {
      const glm::vec3 y = glm::inverse(normal) * glm::vec3(1.0f, c.x, c.y);
      for (int i : supports) share[i] = glm::dot(y, glm::vec3(1.0f, point[i].x, point[i].z));
    } else {
      for (int i : supports) share[i] = 1.0f / static_cast<float>(supports.size());
    }
    for (size_t k = 0; k < supports.size();) {
      if (share[supports[k]] < 0.0f) share[supports[k]] = 0.0f, supports.erase(supports.begin() + k), clipped = true;
      else ++k;
    }
    if (!clipped || supports.empty()) break;
  }
  float total = 0.0f;
  for (int i : supports) total += share[i];
  if (total <= 0.0f) return shared;
  shared.pressure = Project(ground_, pressure);
  for (int i : supports) shared.share[i] = share[i] / total;
  std::array<glm::vec3, kLimbCount> force{};
  // On hands and feet, a virtual force on the CoM (Coros et al. 2010) pulls it
  // toward the plan's CoM: a spring-damper shared among the supports like the
  // weight, its ground forces turned into joint torques with the rest.
  glm::vec3 virtualForce = balanceForce;
  if (OnHandsAndFeet(phase_)) {
    virtualForce = totalMass_ * (kVirtualStiffness * (comGoal - r.com) - kVirtualDamping * r.comVelocity);
    virtualForce = AlongPlane(ground_, virtualForce);
    const float limit = kMaxVirtualForce * totalMass_ * 9.81f;
    if (glm::length(virtualForce) > limit) virtualForce *= limit / glm::length(virtualForce);
  }
  for (int i : supports) force[i] = (virtualForce - gravity * totalMass_) * shared.share[i];

  for (int j = 1; j < sk.JointCount(); ++j) {
    if (!sk.joints[j].hasBox) continue;
    const glm::vec3 pivot = r.jointPositions[j];
    glm::vec3 torque(0.0f);
    for (int s : subtree_[j]) {
      if (!sk.joints[s].hasBox) continue;
      const glm::vec3 centre = r.jointPositions[s] + r.jointRotations[s] * sk.joints[s].box.center;
      torque -= glm::cross(centre - pivot, gravity * def_.bones[s].massKg);
      for (int i = 0; i < kLimbCount; ++i) {
        if (rig_.end[i] == s && glm::length(force[i]) > 0.0f) torque -= glm::cross(point[i] - pivot, force[i]);
      }
    }
    out[j] = torque;
  }
  return shared;
}

}  // namespace rise
