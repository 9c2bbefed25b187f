// SPDX-License-Identifier: MIT
// Command-line overrides of an input file's values (`--fps 60 --seed 3 --names mixamo ...`).
// They pass through the input loader's own checks, so `--fps 500` is refused with the same
// "found ..., allowed ..." message a file would get, labelled with the option instead of a path.
#pragma once

#include <cstdint>
#include <optional>
#include <string>

#include "core/result.h"
#include "core/rise_spec.h"

namespace rise {

struct SpecOverrides {
  std::optional<double> fps;           // --fps          -> fps
  std::optional<uint64_t> seed;        // --seed         -> seed
  std::optional<std::string> names;    // --names        -> output.names
  bool inPlace = false;                // --in-place     -> output.root_motion = false
  std::optional<double> maxDurationS;  // --max-duration -> max_duration_s
};

// `spec` with the overrides applied, or the first one that is not allowed (InputError::file is
// "command line", InputError::jsonPath the option, e.g. "--fps").
Result<RiseSpec> ApplyOverrides(const SpecOverrides& overrides, const RiseSpec& spec);

}  // namespace rise
