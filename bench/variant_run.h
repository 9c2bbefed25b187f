// SPDX-License-Identifier: MIT
// One run of the controller's development harnesses (prone_variants, squat_variants): an input
// text through the validated loader, as the command line reads it, simulated with its trace kept.
#pragma once

#include "core/generate.h"
#include "core/input_json.h"

#include <cstdio>
#include <optional>

namespace bench {

struct VariantRun {
  rise::RiseSpec spec;
  rise::GeneratedClip clip;
};

// Prints the loader's message and returns nothing when the text is not a valid input.
inline std::optional<VariantRun> RunVariant(int index, const char* text, const char* fileName) {
  const auto spec = rise::ParseRiseSpec(text, fileName);
  if (!spec) {
    std::printf("%2d: %s\n", index, spec.Error().Format().c_str());
    return std::nullopt;
  }
  rise::GenerateSettings settings;
  settings.keepTrace = true;
  return VariantRun{spec.Value(), rise::GenerateClip(spec.Value(), settings)};
}

}  // namespace bench
