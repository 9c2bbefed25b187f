// SPDX-License-Identifier: MIT
// Command-line overrides through the input loader; see spec_overrides.h.
#include "core/spec_overrides.h"

#include <nlohmann/json.hpp>

#include "core/input_json.h"

namespace rise {

Result<RiseSpec> ApplyOverrides(const SpecOverrides& overrides, const RiseSpec& spec) {
  using Json = nlohmann::json;
  struct Override {
    const char* option;
    bool present;
    Json patch;
  };
  const Override all[] = {
      {"--fps", overrides.fps.has_value(), Json{{"fps", overrides.fps.value_or(0.0)}}},
      {"--seed", overrides.seed.has_value(), Json{{"seed", overrides.seed.value_or(0)}}},
      {"--names", overrides.names.has_value(), Json{{"output", {{"names", overrides.names.value_or("")}}}}},
      {"--in-place", overrides.inPlace, Json{{"output", {{"root_motion", false}}}}},
      {"--max-duration", overrides.maxDurationS.has_value(),
       Json{{"max_duration_s", overrides.maxDurationS.value_or(0.0)}}},
  };
  RiseSpec result = spec;
  for (const Override& o : all) {
    if (!o.present) continue;
    Result<RiseSpec> applied = RiseSpecFromJson(o.patch, "command line", "", result);
    if (!applied) {
      InputError error = applied.Error();
      // A consistency error (e.g. a disturbance after a shortened max duration) keeps its path.
      const std::string key = o.patch.begin().key();
      if (error.jsonPath.compare(0, key.size(), key) == 0) error.jsonPath = o.option;
      return error;
    }
    result = applied.Value();
  }
  return result;
}

}  // namespace rise
