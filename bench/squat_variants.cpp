// SPDX-License-Identifier: MIT
// Phase 2's development harness: squats on flat feet (trunk pitch, knee and ankle bends, body and
// heading varied) run through the validated loader; each printed with its outcome, time to stand and
// how far the CoM strayed from the feet.
//
//   squat_variants [count] [only]
#include "bench/variant_run.h"
#include "core/generate.h"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <optional>
#include <string>

int main(int argc, char** argv) {
  const int count = argc > 1 ? std::atoi(argv[1]) : 24;
  const int only = argc > 2 ? std::atoi(argv[2]) : -1;
  int stood = 0;
  for (int k = 0; k < count; ++k) {
    if (only >= 0 && k != only) continue;
    const double height = 1.6 + 0.05 * (k % 6), mass = 55 + 7 * (k % 7);
    const int pitch = 25 + 5 * (k % 5), knee = 90 + 5 * (k % 4), ankle = 18 + 3 * (k % 4);
    const int hip = std::min(118, knee + pitch - ankle);
    char text[1024];
    std::snprintf(text, sizeof text,
                  "{\"character\":{\"height_m\":%.2f,\"mass_kg\":%.0f},\"start\":{\"posture\":\"custom\",\"heading_deg\":%d,"
                  "\"root_euler_deg\":[%d,0,0],\"joints_deg\":{\"thigh_l\":[%d,5],\"thigh_r\":[%d,5],\"shin_l\":[%d],"
                  "\"shin_r\":[%d],\"foot_l\":[%d,0],\"foot_r\":[%d,0],\"upper_arm_l\":[40,0],\"upper_arm_r\":[40,0]}},"
                  "\"seed\":%d,\"max_duration_s\":8}",
                  height, mass, (k * 37) % 360, pitch, hip, hip, knee, knee, ankle, ankle, k + 1);
    const std::optional<bench::VariantRun> run = bench::RunVariant(k, text, "squat.json");
    if (!run) return 2;
    const rise::GeneratedClip& clip = run->clip;
    float worst = -9.0f;
    for (const rise::TraceSample& sample : clip.trace) {
      if (sample.phase >= rise::RisePhase::kRise) worst = std::max(worst, sample.feetDistance);
    }
    stood += clip.stood;
    std::printf("%2d %.2f m %3.0f kg pitch %d hip %d knee %d ankle %d  %-50.50s retries %d  worst CoM-feet %+.3f\n", k, height,
                mass, pitch, hip, knee, ankle, clip.outcome.c_str(), clip.retries, worst);
  }
  std::printf("stood %d of %d\n", stood, only >= 0 ? 1 : count);
}
