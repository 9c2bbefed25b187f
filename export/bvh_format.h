// SPDX-License-Identifier: MIT
// The unit and axis conventions of a BVH file, shared by the writer and the
// reader (a BVH file does not say which it uses).
//
// rise-gen's world is Y-up metres. With up = Z the file's axes are rise-gen's
// turned +90 degrees about X: (x, y, z) -> (x, -z, y), right-handed, so a
// character facing +Z stands up along +Z and faces -Y (Blender's front view).
#pragma once

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>
#include <optional>
#include <string_view>

namespace rise {

enum class BvhUnits { kMetres, kCentimetres };
enum class BvhUp { kY, kZ };

struct BvhFormat {
  BvhUnits units = BvhUnits::kMetres;
  BvhUp up = BvhUp::kY;

  // File length units per metre (1 or 100).
  float Scale() const { return units == BvhUnits::kCentimetres ? 100.0f : 1.0f; }
  // A rise-gen vector / rotation in the file's axes, and back. Exact
  // component swaps, so zeros stay zeros in the text.
  glm::vec3 AxesToFile(const glm::vec3& v) const { return up == BvhUp::kY ? v : glm::vec3(v.x, -v.z, v.y); }
  glm::vec3 AxesFromFile(const glm::vec3& v) const { return up == BvhUp::kY ? v : glm::vec3(v.x, v.z, -v.y); }
  glm::quat AxesToFile(const glm::quat& q) const { return up == BvhUp::kY ? q : glm::quat(q.w, q.x, -q.z, q.y); }
  // A rise-gen position (metres, Y-up) in file units and axes, and back.
  glm::vec3 ToFile(const glm::vec3& p) const { return Scale() * AxesToFile(p); }
  glm::vec3 FromFile(const glm::vec3& p) const { return AxesFromFile(p) / Scale(); }
};

// "m" | "cm" and "y" | "z"; anything else -> nullopt.
std::optional<BvhUnits> ParseBvhUnits(std::string_view name);
std::optional<BvhUp> ParseBvhUp(std::string_view name);

}  // namespace rise
