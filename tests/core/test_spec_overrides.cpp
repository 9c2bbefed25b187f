// SPDX-License-Identifier: MIT
#include "core/spec_overrides.h"
#include "test_support.h"

TEST_SUITE("spec_overrides") {
  TEST_CASE("overrides replace the file's values and leave the rest alone") {
    rise::RiseSpec spec;
    spec.style.speed = 1.5;
    rise::SpecOverrides overrides;
    overrides.fps = 60.0;
    overrides.seed = 42;
    overrides.names = "mixamo";
    overrides.inPlace = true;
    overrides.maxDurationS = 3.0;
    const rise::Result<rise::RiseSpec> result = rise::ApplyOverrides(overrides, spec);
    REQUIRE(result.IsOk());
    CHECK(result.Value().fps == 60.0);
    CHECK(result.Value().seed == 42u);
    CHECK(result.Value().output.names == "mixamo");
    CHECK_FALSE(result.Value().output.rootMotion);
    CHECK(result.Value().maxDurationS == 3.0);
    CHECK(result.Value().style.speed == 1.5);
    CHECK(rise::ApplyOverrides(rise::SpecOverrides{}, spec).Value().fps == spec.fps);
  }

  TEST_CASE("a refused override is labelled with its option and gets the loader's message") {
    rise::SpecOverrides overrides;
    overrides.fps = 500.0;
    rise::Result<rise::RiseSpec> result = rise::ApplyOverrides(overrides, rise::RiseSpec{});
    REQUIRE_FALSE(result.IsOk());
    CHECK(result.Error().Format() == "command line: --fps: found 500, allowed: 1 to 240 frames per second");

    overrides = {};
    overrides.names = "maya";
    result = rise::ApplyOverrides(overrides, rise::RiseSpec{});
    REQUIRE_FALSE(result.IsOk());
    CHECK(result.Error().jsonPath == "--names");

    // A shorter clip than a disturbance needs keeps the disturbance's path: that is what clashes.
    rise::RiseSpec pushed;
    pushed.disturbances.push_back({4.0, "chest", {100.0, 0.0, 0.0}, 0.2});
    overrides = {};
    overrides.maxDurationS = 2.0;
    result = rise::ApplyOverrides(overrides, pushed);
    REQUIRE_FALSE(result.IsOk());
    CHECK(result.Error().jsonPath == "disturbances[0].time_s");
  }
}
