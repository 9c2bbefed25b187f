// SPDX-License-Identifier: MIT
// Direct solve of the joints' point parts over the joint forest (Baraff, "Linear-Time Dynamics
// using Lagrange Multipliers", SIGGRAPH 1996), used when WorldSettings::jointSolver is kDirectTree.
//
// Why: a sequential-impulse pass fixes one joint at a time, so along a 15-body chain with
// heavy and light bodies a pass leaves most of the error where it was, and the ragdoll's anchors
// separate unless many sub-steps are taken. Solving all point rows together is exact in one pass.
//
// The system. Body i has velocity V_i = (v_i, w_i) and mass M_i = diag(m_i 1, I_i). Joint j joins
// child c and parent p with anchor offsets r_c, r_p (R = [r]x, so R w = r x w and R^T = -R):
//   C_j = (x_c + r_c) - (x_p + r_p),  Cdot_j = G_c V_c + G_p V_p,  G_c = [1, -R_c],  G_p = -[1, -R_p].
// (When the child is the joint's body A both G change sign; `sign` folds that in.) One solve
// finds the velocity change dV and impulses lambda with M dV = G^T lambda and G (V + dV) = -b,
// with the bias b = biasRate C in the biased solve and 0 in the relax. As a symmetric system:
//   [M  G^T] [dV]   [ 0           ]
//   [G   0 ] [ y] = [-(G V + b)   ],   lambda = -y.
// Ordering the unknowns leaves first (child body, then its joint, then the parent body, ...)
// makes the elimination fill-free, so the LDL^T factorisation costs O(n) in 6x6 and 3x3 blocks:
//   leaf to root, for each joint j with child c:
//     D_c^-1 (6x6): M_c^-1 for a leaf; else the inverse of D_c = M_c + sum over c's child joints k
//                   of G_ck^T S_k^-1 G_ck (the articulated mass of c's subtree), by a Schur
//                   complement of its 3x3 blocks;
//     L_cj = D_c^-1 G_c^T (6x3, kept as lowerLinear/lowerAngular),
//     S_j  = G_c L_cj  (3x3; for a leaf child: m^-1 1 - R I^-1 R, the usual point-part K),
//     D_j  = -S_j,  and the parent gets  D_p += G_p^T S_j^-1 G_p = [[S^-1, -S^-1 R_p], [R_p S^-1, -R_p S^-1 R_p]].
// Solve: forward (leaf to root) x_j = rhs_j - L_cj^T x_c, x_p -= L_jp^T x_j with L_jp = S_j^-1 [1, -R_p];
// diagonal x_i = D_i^-1 x_i; backward (root to leaf) x_j -= L_jp x_p, x_c -= L_cj x_j.
// The body part of x is dV; adding it to the velocities applies all joint impulses at once.
//
// The factorisation depends on the poses, so it is redone after every position integration, when
// the joints' lever arms are refreshed: the relax pass, the next warm start and the next biased
// solve then use exactly the rows that were factorised. Factorising once per step and solving
// with the turning lever arms cost 8 % fewer instructions on the ragdoll drop but is not a
// projection any more: a 15-link chain of 0.5 and 5 kg links thrown at 3 m/s gained energy and
// exploded (1 and 2 sub-steps), where refactorising keeps it within a few mm and losing energy.
// No softness: an exact solve needs no regularisation. The bias removes a fixed fraction of C per
// sub-step (WorldSettings::jointTreeErrorReduction), and the relax pass takes its velocity out.
//
// Everything else stays sequential impulses: the joints' angular rows (hinge and universal axis
// locks, limits, PD motors) and the contacts. A pass solves those first and this last
// (solver.cpp), a block Gauss-Seidel between an inexact and an exact block, so the anchors have
// the last word: with contacts last instead, the drop's joints opened to 8 mm at 2 sub-steps.
// Of three or more biased passes per sub-step only the first and the last end with this solve.
#include "physics/joint_tree.h"

#include "base/assert.h"
#include "physics/constraint_parts.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <numeric>

namespace rise::physics {

namespace {

int32_t FindRoot(std::vector<int32_t>& parent, int32_t i) {
  while (parent[i] != i) {
    parent[i] = parent[parent[i]];
    i = parent[i];
  }
  return i;
}

// m [r]x and [r]x m without the multiplications by the zeros of the cross-product matrix.
inline glm::mat3 TimesSkew(const glm::mat3& m, const glm::vec3& r) {
  return glm::mat3(r.z * m[1] - r.y * m[2], r.x * m[2] - r.z * m[0], r.y * m[0] - r.x * m[1]);
}
inline glm::mat3 SkewTimes(const glm::vec3& r, const glm::mat3& m) {
  return glm::mat3(glm::cross(r, m[0]), glm::cross(r, m[1]), glm::cross(r, m[2]));
}

// The inverse of a symmetric 3x3 matrix from one triangle of it: six cofactors instead of nine.
// Every matrix inverted here is symmetric up to rounding (a mass, or G D^-1 G^T).
inline glm::mat3 InverseSymmetric(const glm::mat3& m) {
  const float c00 = m[1][1] * m[2][2] - m[1][2] * m[1][2];
  const float c01 = m[0][2] * m[1][2] - m[0][1] * m[2][2];
  const float c02 = m[0][1] * m[1][2] - m[0][2] * m[1][1];
  const float c11 = m[0][0] * m[2][2] - m[0][2] * m[0][2];
  const float c12 = m[0][1] * m[0][2] - m[0][0] * m[1][2];
  const float c22 = m[0][0] * m[1][1] - m[0][1] * m[0][1];
  const float invDet = 1.0f / (m[0][0] * c00 + m[0][1] * c01 + m[0][2] * c02);
  // Entry by entry: built from vec3 columns, the result went through the stack in pieces and was
  // read back whole, which stalls store-to-load forwarding on this latency-bound path.
  return glm::mat3(invDet * c00, invDet * c01, invDet * c02, invDet * c01, invDet * c11, invDet * c12, invDet * c02,
                   invDet * c12, invDet * c22);
}

}  // namespace

void BuildJointTree(JointTree& tree, std::vector<Joint>& joints, int bodyCount, bool active) {
  tree = JointTree{};
  tree.active = active;
  tree.builtJointCount = int32_t(joints.size());
  for (Joint& joint : joints) joint.pointInTree = false;
  if (!active) return;

  // Union-find over the bodies and the world (node bodyCount): creation order decides which
  // joint of a loop is left to the sequential pass.
  const int32_t world = bodyCount;
  std::vector<int32_t> component(size_t(bodyCount) + 1);
  std::iota(component.begin(), component.end(), 0);
  std::vector<std::vector<int32_t>> adjacent(size_t(bodyCount) + 1);  // joint indices, creation order
  for (int32_t j = 0; j < int32_t(joints.size()); ++j) {
    const int32_t a = joints[j].bodyA >= 0 ? joints[j].bodyA : world;
    const int32_t b = joints[j].bodyB;
    const int32_t ra = FindRoot(component, a);
    const int32_t rb = FindRoot(component, b);
    if (ra == rb) continue;
    component[rb] = ra;
    joints[j].pointInTree = true;
    adjacent[a].push_back(j);
    adjacent[b].push_back(j);
  }

  // Breadth first from the world, then from the lowest-index body of every other tree, so each
  // link is listed before the links below it.
  std::vector<bool> visited(size_t(bodyCount) + 1, false);
  std::vector<int32_t> queue;
  auto visit = [&](int32_t root) {
    visited[root] = true;
    queue.assign(1, root);
    for (size_t head = 0; head < queue.size(); ++head) {
      const int32_t node = queue[head];
      for (int32_t j : adjacent[node]) {
        const Joint& joint = joints[j];
        const int32_t a = joint.bodyA >= 0 ? joint.bodyA : world;
        const int32_t other = a == node ? joint.bodyB : a;
        if (visited[other]) continue;
        visited[other] = true;
        queue.push_back(other);
        JointTreeLink link;
        link.joint = j;
        link.parent = node == world ? -1 : node;
        link.child = other;
        link.sign = other == joint.bodyB ? 1.0f : -1.0f;
        tree.links.push_back(link);
      }
    }
  };
  visit(world);
  for (int32_t body = 0; body < bodyCount; ++body) {
    if (!visited[body] && !adjacent[body].empty()) visit(body);
  }

  // Grouped by depth (a stable sort keeps every parent link before its children), so the
  // factorisation can work on one level's independent links side by side.
  std::vector<int32_t> depth(size_t(bodyCount) + 1, 0);
  for (const JointTreeLink& link : tree.links) depth[link.child] = (link.parent >= 0 ? depth[link.parent] : 0) + 1;
  std::stable_sort(tree.links.begin(), tree.links.end(), [&depth](const JointTreeLink& x, const JointTreeLink& y) {
    return depth[x.child] < depth[y.child];
  });
  for (size_t i = 0; i < tree.links.size(); ++i) {
    if (i == 0 || depth[tree.links[i].child] != depth[tree.links[i - 1].child]) tree.levelStarts.push_back(int32_t(i));
  }
  tree.levelStarts.push_back(int32_t(tree.links.size()));

  // Every parent body gets a slot, in link order.
  std::vector<int32_t> bodySlot(size_t(bodyCount), -1);
  for (const JointTreeLink& link : tree.links) {
    if (link.parent < 0 || bodySlot[link.parent] >= 0) continue;
    bodySlot[link.parent] = int32_t(tree.slotBodies.size());
    tree.slotBodies.push_back(link.parent);
  }
  std::vector<bool> isChild(size_t(bodyCount), false);
  for (JointTreeLink& link : tree.links) {
    link.childSlot = bodySlot[link.child];
    link.parentSlot = link.parent >= 0 ? bodySlot[link.parent] : -1;
    isChild[link.child] = true;
  }
  const size_t slotCount = tree.slotBodies.size();
  for (size_t slot = 0; slot < slotCount; ++slot) {
    if (!isChild[tree.slotBodies[slot]]) tree.rootSlots.push_back(int32_t(slot));
  }
  tree.inverses.resize(slotCount);
  tree.scratchA.resize(slotCount);
  tree.scratchB.resize(slotCount);
  tree.scratchC.resize(slotCount);
  tree.deltaV.resize(slotCount);
  tree.deltaW.resize(slotCount);
}

void FactorJointTree(JointTree& tree, const std::vector<Joint>& joints, const std::vector<Body>& bodies) {
  // D of every body with links below it starts as its own mass.
  for (size_t slot = 0; slot < tree.slotBodies.size(); ++slot) {
    const Body& body = bodies[tree.slotBodies[slot]];
    tree.scratchA[slot] = glm::mat3(body.mass);
    tree.scratchB[slot] = glm::mat3(0.0f);
    tree.scratchC[slot] = InverseSymmetric(body.invInertiaWorld);  // the world inertia
  }

  // Schur complement of the linear block; the explicit blocks of D^-1 are never formed, as every
  // use of D^-1 multiplies it by something narrower.
  auto invert = [&tree](int32_t slot) {
    JointTreeInverse& inverse = tree.inverses[slot];
    inverse.linearInverse = InverseSymmetric(tree.scratchA[slot]);
    inverse.coupling = inverse.linearInverse * tree.scratchB[slot];
    inverse.schurInverse =
        InverseSymmetric(tree.scratchC[slot] - glm::transpose(tree.scratchB[slot]) * inverse.coupling);
  };

  // Leaf to root, one level at a time and each level in three passes over its links: the links
  // of a level are independent, and a pass over several of them keeps more than one chain of
  // 3x3 inversions in flight than link after link did (the factorisation was latency-bound).
  for (size_t level = tree.levelStarts.size() - 1; level-- > 0;) {
    const auto first = tree.links.begin() + tree.levelStarts[level];
    const auto last = tree.links.begin() + tree.levelStarts[level + 1];
    for (auto it = first; it != last; ++it) {
      JointTreeLink& link = *it;
      const Joint& joint = joints[link.joint];
      link.childLever = link.sign > 0.0f ? joint.leverB : joint.leverA;
      link.parentLever = link.sign > 0.0f ? joint.leverA : joint.leverB;
      if (link.childSlot >= 0) invert(link.childSlot);  // every link below the child is done
    }
    for (auto it = first; it != last; ++it) {
      JointTreeLink& link = *it;
      const Body& child = bodies[link.child];
      const glm::vec3& r = link.childLever;
      glm::mat3 lowerLinear(child.invMass);
      if (link.childSlot < 0) {
        link.lowerAngular = TimesSkew(child.invInertiaWorld, r);
      } else {
        // L = D^-1 G^T with G^T = [1; [r]x]: angular rows T ([r]x - X^T), linear rows A^-1 - X (those).
        const JointTreeInverse& inverse = tree.inverses[link.childSlot];
        link.lowerAngular = inverse.schurInverse * (SkewMatrix(r) - glm::transpose(inverse.coupling));
        lowerLinear = inverse.linearInverse - inverse.coupling * link.lowerAngular;
        link.lowerLinear = lowerLinear;
      }
      link.invMass = InverseSymmetric(lowerLinear - SkewTimes(r, link.lowerAngular));
    }
    for (auto it = first; it != last; ++it) {
      const JointTreeLink& link = *it;
      if (link.parentSlot < 0) continue;
      const glm::vec3& rp = link.parentLever;
      const glm::mat3 sr = TimesSkew(link.invMass, rp);
      tree.scratchA[link.parentSlot] += link.invMass;
      tree.scratchB[link.parentSlot] -= sr;
      tree.scratchC[link.parentSlot] -= SkewTimes(rp, sr);
    }
  }
  for (int32_t slot : tree.rootSlots) invert(slot);
  tree.factorCurrent = true;
}

void SolveJointTree(JointTree& tree, std::vector<Joint>& joints, std::vector<Body>& bodies, const Body& staticBody,
                    float biasRate) {
  RISE_ASSERT_MSG(tree.factorCurrent, "the joint forest must be factorised before it is solved");
  // x_i = D_i^-1 x_i of a body with links below it (a slot), applied once its own row is complete.
  auto applyInverse = [&tree](int32_t slot) {
    const JointTreeInverse& inverse = tree.inverses[slot];
    const glm::vec3 v = tree.deltaV[slot];
    const glm::vec3 w = inverse.schurInverse * (tree.deltaW[slot] - v * inverse.coupling);
    tree.deltaV[slot] = inverse.linearInverse * v - inverse.coupling * w;
    tree.deltaW[slot] = w;
  };

  // Forward substitution, leaf to root; the right-hand side is each joint's velocity error. Only
  // bodies with links below them (slots) gather terms; a leaf child's are zero. A child's row is
  // complete when its link comes up, so its diagonal solve happens here rather than in the
  // backward pass: then L^T x_c = G_c D_c^-1 x_c costs a cross product, not two 3x3 products.
  std::fill(tree.deltaV.begin(), tree.deltaV.end(), glm::vec3(0.0f));
  std::fill(tree.deltaW.begin(), tree.deltaW.end(), glm::vec3(0.0f));
  for (auto it = tree.links.rbegin(); it != tree.links.rend(); ++it) {
    JointTreeLink& link = *it;
    const Body& child = bodies[link.child];
    const Body& parent = link.parent >= 0 ? bodies[link.parent] : staticBody;
    const glm::vec3& rc = link.childLever;
    const glm::vec3& rp = link.parentLever;
    // The child's anchor velocity minus the parent's, plus the bias on their separation.
    glm::vec3 error = PointVelocity(child, rc) - PointVelocity(parent, rp);
    if (biasRate > 0.0f) {
      error += biasRate * ((child.transform.position + rc) - (parent.transform.position + rp));
    }
    link.x = -error;
    if (link.childSlot >= 0) {
      applyInverse(link.childSlot);
      link.x -= tree.deltaV[link.childSlot] - glm::cross(rc, tree.deltaW[link.childSlot]);
    }
    if (link.parentSlot < 0) continue;
    const glm::vec3 s = link.invMass * link.x;
    tree.deltaV[link.parentSlot] -= s;
    tree.deltaW[link.parentSlot] -= glm::cross(rp, s);
  }

  // Backward substitution, root to leaf. A body's velocity change is final once its own row is
  // done, so it is applied there.
  auto applyDelta = [&tree, &bodies](int32_t slot) {
    Body& body = bodies[tree.slotBodies[slot]];
    body.linearVelocity += tree.deltaV[slot];
    body.angularVelocity += tree.deltaW[slot];
  };
  for (int32_t slot : tree.rootSlots) {
    applyInverse(slot);
    applyDelta(slot);
  }
  for (JointTreeLink& link : tree.links) {
    glm::vec3 y = link.x;
    if (link.parentSlot >= 0) {
      y += tree.deltaV[link.parentSlot] - glm::cross(link.parentLever, tree.deltaW[link.parentSlot]);
    }
    const glm::vec3 x = -(link.invMass * y);
    joints[link.joint].linearImpulse -= link.sign * x;  // lambda = -x acts on the child; the joint's on B
    if (link.childSlot >= 0) {
      tree.deltaV[link.childSlot] -= link.lowerLinear * x;
      tree.deltaW[link.childSlot] -= link.lowerAngular * x;
      applyDelta(link.childSlot);
    } else {
      // A leaf child: its velocity change is its own response to the joint impulse.
      Body& child = bodies[link.child];
      child.linearVelocity -= child.invMass * x;
      child.angularVelocity -= link.lowerAngular * x;
    }
  }
}

}  // namespace rise::physics
