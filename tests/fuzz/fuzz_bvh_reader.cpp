// SPDX-License-Identifier: MIT
// libFuzzer target: BVH text -> joint positions per frame, the reader `rise-gen check --bvh` uses.
#include <cstddef>
#include <cstdint>
#include <string>

#include "export/bvh_reader.h"

// Any text must give a motion or a message, never a crash, a hang or undefined behaviour. The
// first byte picks the unit and axis convention, so all four readings are explored. A motion that
// loads is consistent: one parent per joint, parents before children, every frame complete.
extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  if (size == 0) return 0;
  const rise::BvhFormat format{(data[0] & 1) ? rise::BvhUnits::kCentimetres : rise::BvhUnits::kMetres,
                               (data[0] & 2) ? rise::BvhUp::kZ : rise::BvhUp::kY};
  const std::string text(reinterpret_cast<const char*>(data) + 1, size - 1);
  rise::BvhMotion motion;
  const std::string error = rise::ParseBvh(text, format, "fuzz.bvh", motion);
  if (!error.empty()) return 0;
  const size_t joints = motion.names.size();
  if (joints == 0 || motion.parents.size() != joints || !(motion.frameTime > 0.0)) __builtin_trap();
  for (size_t j = 0; j < joints; ++j) {
    if (motion.parents[j] >= static_cast<int>(j) || (j > 0) != (motion.parents[j] >= 0)) __builtin_trap();
  }
  for (const auto& frame : motion.positions) {
    if (frame.size() != joints) __builtin_trap();
  }
  return 0;
}
