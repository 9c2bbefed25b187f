// SPDX-License-Identifier: MIT
// Unit and axis conventions of BVH files.
#include "export/bvh_format.h"

namespace rise {

std::optional<BvhUnits> ParseBvhUnits(std::string_view name) {
  if (name == "m") return BvhUnits::kMetres;
  if (name == "cm") return BvhUnits::kCentimetres;
  return std::nullopt;
}

std::optional<BvhUp> ParseBvhUp(std::string_view name) {
  if (name == "y") return BvhUp::kY;
  if (name == "z") return BvhUp::kZ;
  return std::nullopt;
}

}  // namespace rise
