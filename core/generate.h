// SPDX-License-Identifier: MIT
// GenerateClip: the whole job for one clip. Builds the world and the biped in
// its start pose, runs the loop (controller reads state -> writes servo
// targets -> World::Step, as MuJoCo's mj_step1/mj_step2), records the
// simulated body at the engine's rate and resamples it into a Clip with its
// metadata (phases, contacts, peak torques, the resolved input).
#pragma once

#include "core/rise_controller.h"
#include "core/rise_spec.h"
#include "export/clip.h"

#include <functional>
#include <string>
#include <vector>

namespace rise {

struct GenerateSettings {
  bool keepTrace = false;  // keep one TraceSample per control step (debug trace)
  // Called now and then with the simulated time and the spec's max duration.
  std::function<void(double simulated, double maxDuration)> onProgress;
};

// Tier 3 errors: the simulation itself went wrong (never the user's input).
struct SimulationHealth {
  bool ok = true;
  std::string message;  // what failed, at what time, in which body
};

struct GeneratedClip {
  Clip clip;
  bool stood = false;          // the controller reached a still stand
  double timeToStand = -1.0;   // s from the start of the clip; < 0 when it never stood
  std::string outcome;         // one line: "stood at 6.2 s" or why it did not
  int retries = 0;             // falls the controller recovered from
  double simulatedSeconds = 0.0;
  SimulationHealth health;
  std::vector<TraceSample> trace;  // per control step, when keepTrace
};

// Runs one clip. The spec must come from the validated loader (ParseRiseSpec);
// the result is a pure function of it (bit-identical across runs).
GeneratedClip GenerateClip(const RiseSpec& spec, const GenerateSettings& settings = {});

// The debug trace as JSON lines (one object per control step).
std::string TraceToJsonLines(const std::vector<TraceSample>& trace, const Skeleton& skeleton);

}  // namespace rise
