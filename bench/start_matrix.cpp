// SPDX-License-Identifier: MIT
// Issue 4 §4's table: every built-in start posture x the four bodies (default 1.75 m 70 kg,
// short 1.50 m 45 kg, tall 1.95 m 95 kg, heavy 1.75 m 110 kg) x level ground and a 10 deg slope,
// each run through the validated loader as the command line runs it and measured by the clip's
// quality bars (clip_quality.h, what `rise-gen check` reports): stood, time to stand, deepest box,
// worst contact slide and the bars missed. One Markdown table, then the counts.
//
//   start_matrix [heading_deg] [seed]      env: DUR (max_duration_s, 40)
#include "bench/variant_run.h"
#include "core/clip_check.h"
#include "core/clip_quality.h"

#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

struct Body {
  const char* name;
  double heightM, massKg;
};

constexpr Body kBodies[] = {{"default", 1.75, 70}, {"short", 1.50, 45}, {"tall", 1.95, 95}, {"heavy", 1.75, 110}};
constexpr const char* kPostures[] = {"supine", "prone", "side_left", "side_right"};
constexpr double kSlopesDeg[] = {0.0, 10.0};

}  // namespace

int main(int argc, char** argv) {
  const int heading = argc > 1 ? std::atoi(argv[1]) : 0;
  const int seed = argc > 2 ? std::atoi(argv[2]) : 1;
  const char* duration = std::getenv("DUR") ? std::getenv("DUR") : "40";
  int runs = 0, stood = 0, passed = 0;
  std::printf("| start | body | slope | stood | time to stand | max penetration | max slip | bars missed |\n");
  std::printf("|---|---|---:|---|---:|---:|---:|---|\n");
  for (const char* posture : kPostures) {
    for (const Body& body : kBodies) {
      for (const double slope : kSlopesDeg) {
        char text[384];
        std::snprintf(text, sizeof text,
                      "{\"character\":{\"height_m\":%.2f,\"mass_kg\":%.0f},\"start\":{\"posture\":\"%s\",\"heading_deg\":%d},"
                      "\"terrain\":{\"slope_deg\":%.0f},\"seed\":%d,\"max_duration_s\":%s}",
                      body.heightM, body.massKg, posture, heading, slope, seed, duration);
        const std::optional<bench::VariantRun> run = bench::RunVariant(runs, text, "matrix.json");
        if (!run) return 2;
        const rise::QualityReport quality = rise::MeasureClip(run->clip.clip, rise::QualityOptionsFor(run->clip.clip));
        ++runs;
        stood += run->clip.stood;
        passed += quality.passed;
        char time[32] = "-";
        if (quality.timeToStand >= 0.0) std::snprintf(time, sizeof time, "%.1f s", quality.timeToStand);
        const std::string missed = rise::MissedBars(quality);
        std::printf("| %s | %s | %.0f deg | %s | %s | %.1f mm | %.1f cm (%s) | %s |\n", posture, body.name, slope,
                    run->clip.stood ? "yes" : "no", time, 1000.0 * quality.maxPenetration, 100.0 * quality.maxSlip,
                    quality.maxSlipEffector.c_str(), missed.empty() ? "none" : missed.c_str());
        std::fflush(stdout);
      }
    }
  }
  std::printf("\n%d runs: stood %d, passed every bar %d\n", runs, stood, passed);
}
