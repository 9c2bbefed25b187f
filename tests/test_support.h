// SPDX-License-Identifier: MIT
// Shared helpers for the doctest suite.
#pragma once

#include <doctest/doctest.h>

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

#include <cmath>
#include <fstream>
#include <random>
#include <sstream>
#include <string>

namespace rise::test {

// The one random source of the suite: fixed seed, so every run sees the same numbers.
inline std::mt19937& Rng() {
  static std::mt19937 rng(12345u);
  return rng;
}

// The bytes of a file ("" when it cannot be read).
inline std::string FileContents(const std::string& path) {
  std::ifstream file(path, std::ios::binary);
  std::ostringstream text;
  text << file.rdbuf();
  return text.str();
}

inline float Distance(const glm::vec3& a, const glm::vec3& b) {
  const glm::vec3 d = a - b;
  return std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
}

// Angle in radians between two rotations; q and -q are the same rotation.
inline float AngleBetween(const glm::quat& a, const glm::quat& b) {
  const float d = std::fabs(a.x * b.x + a.y * b.y + a.z * b.z + a.w * b.w);
  return 2.0f * std::acos(d > 1.0f ? 1.0f : d);
}

// The bundled input files, samples/<name>.json (library.json, a batch manifest, aside).
inline constexpr const char* kSampleInputs[] = {"supine", "prone", "side", "custom", "tall", "slope", "push", "reference"};

}  // namespace rise::test

#define CHECK_VEC3_NEAR(a, b, tol)                                                  \
  do {                                                                              \
    const glm::vec3 rise_a_ = (a), rise_b_ = (b);                                   \
    INFO("(" << rise_a_.x << ", " << rise_a_.y << ", " << rise_a_.z << ") vs ("     \
             << rise_b_.x << ", " << rise_b_.y << ", " << rise_b_.z << ")");        \
    CHECK(::rise::test::Distance(rise_a_, rise_b_) <= (tol));                       \
  } while (0)

#define CHECK_QUAT_NEAR(a, b, tolRadians) CHECK(::rise::test::AngleBetween((a), (b)) <= (tolRadians))
