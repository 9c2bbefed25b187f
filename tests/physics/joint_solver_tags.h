// SPDX-License-Identifier: MIT
// The joint solvers every joint test runs with (doctest TEST_CASE_TEMPLATE over these tags).
#pragma once

#include "physics/settings.h"

#include <doctest/doctest.h>

namespace rise::test {

struct SequentialImpulseJoints {
  static constexpr physics::JointSolver kSolver = physics::JointSolver::kSequentialImpulse;
};
struct DirectTreeJoints {
  static constexpr physics::JointSolver kSolver = physics::JointSolver::kDirectTree;
};

// `settings` with the joint solver of tag T.
template <typename T>
physics::WorldSettings WithJointSolver(physics::WorldSettings settings = {}) {
  settings.jointSolver = T::kSolver;
  return settings;
}

}  // namespace rise::test

TYPE_TO_STRING(rise::test::SequentialImpulseJoints);
TYPE_TO_STRING(rise::test::DirectTreeJoints);

#define RISE_JOINT_SOLVERS rise::test::SequentialImpulseJoints, rise::test::DirectTreeJoints
