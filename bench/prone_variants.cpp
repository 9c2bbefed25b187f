// SPDX-License-Identifier: MIT
// The crawl's development harness: twelve starts (heading k*37 deg, seed k+1, height 1.60..1.85 m,
// mass 55..97 kg) run through the validated loader, as the command line runs them, each printed
// with its outcome, the furthest phase, how close the CoM came to the feet (negative: over them),
// how close the feet came to the hands, and the time spent in each move; then each hand or foot
// whose worst contact slid past the quality bar, with the moves that contact spans (where a
// slide comes from), and at the end how many starts pass every bar.
//
//   prone_variants [count] [only] [posture]
//   env: DUR (max_duration_s, 20), SPEED (style.speed, 1), FRIC (terrain.friction, 0.8), SLOPE (terrain.slope_deg, 0),
//        TIRED (style.tiredness, 0), TRACE=file (JSON lines of `only`),
//        OUT=dir (dir/v.glb of `only`)
#include "bench/variant_run.h"
#include "core/clip_output.h"
#include "core/clip_check.h"
#include "core/clip_quality.h"
#include "core/generate.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <optional>
#include <string>

int main(int argc, char** argv) {
  const int count = argc > 1 ? std::atoi(argv[1]) : 12;
  const int only = argc > 2 ? std::atoi(argv[2]) : -1;
  const std::string posture = argc > 3 ? argv[3] : "prone";
  int stood = 0, rose = 0, passed = 0;
  for (int k = 0; k < count; ++k) {
    if (only >= 0 && k != only) continue;
    const double height = 1.6 + 0.05 * (k % 6), mass = 55 + 7 * (k % 7);
    char text[512];
    std::snprintf(text, sizeof text,
                  "{\"character\":{\"height_m\":%.2f,\"mass_kg\":%.0f},\"start\":{\"posture\":\"%s\",\"heading_deg\":%d},"
                  "\"seed\":%d,\"max_duration_s\":%s,\"style\":{\"speed\":%s,\"tiredness\":%s},\"terrain\":{\"friction\":%s,\"slope_deg\":%s}}",
                  height, mass, posture.c_str(), (k * 37) % 360, k + 1, std::getenv("DUR") ? std::getenv("DUR") : "20",
                  std::getenv("SPEED") ? std::getenv("SPEED") : "1", std::getenv("TIRED") ? std::getenv("TIRED") : "0",
                  std::getenv("FRIC") ? std::getenv("FRIC") : "0.8", std::getenv("SLOPE") ? std::getenv("SLOPE") : "0");
    const std::optional<bench::VariantRun> run = bench::RunVariant(k, text, "variant.json");
    if (!run) return 2;
    const rise::GeneratedClip& clip = run->clip;
    if (only >= 0 && std::getenv("TRACE")) {
      if (FILE* file = std::fopen(std::getenv("TRACE"), "w")) {
        const std::string lines = rise::TraceToJsonLines(clip.trace, clip.clip.skeleton);
        std::fwrite(lines.data(), 1, lines.size(), file);
        std::fclose(file);
      }
    }
    if (only >= 0 && std::getenv("OUT")) {
      const std::string error = rise::WriteClipFiles(clip.clip, {std::string(std::getenv("OUT")) + "/v.glb"},
                                                     rise::ClipOutputOptionsOf(run->spec));
      if (!error.empty()) std::printf("write: %s\n", error.c_str());
    }
    int furthest = 0;
    float comToFeet = 9.0f, handsToFeet = 9.0f;
    std::map<std::string, std::pair<int, double>> moves;  // name -> (runs, seconds)
    std::string previous;
    for (const rise::TraceSample& sample : clip.trace) {
      furthest = std::max(furthest, static_cast<int>(sample.phase));
      if (sample.phase == rise::RisePhase::kCrawl) {
        comToFeet = std::min(comToFeet, sample.feetDistance);
        glm::vec3 apart = 0.5f * (sample.limbTargets[0] + sample.limbTargets[1] - sample.limbTargets[2] - sample.limbTargets[3]);
        apart.y = 0.0f;
        handsToFeet = std::min(handsToFeet, glm::length(apart));
      }
      auto& move = moves[sample.move];
      if (sample.move != previous) ++move.first;
      move.second += 1.0 / 240.0;
      previous = sample.move;
    }
    stood += clip.stood;
    rose += furthest >= static_cast<int>(rise::RisePhase::kRise);
    std::printf("%2d %.2f m %3.0f kg  %-44.44s retries %d  furthest %-5s  CoM-feet %+.2f m  hands-feet %.2f m |", k, height,
                mass, clip.outcome.c_str(), clip.retries, rise::RisePhaseName(static_cast<rise::RisePhase>(furthest)),
                comToFeet, handsToFeet);
    for (const auto& [name, time] : moves) {
      if (name != "settle") std::printf(" %s %d/%.1fs", name.c_str(), time.first, time.second);
    }
    std::printf("\n");
    const rise::QualityOptions options = rise::QualityOptionsFor(clip.clip);
    const rise::QualityReport quality = rise::MeasureClip(clip.clip, options);
    passed += quality.passed;
    for (const rise::EffectorSlip& slip : quality.slips) {
      if (slip.slip < options.maxSlip) continue;
      std::string spanned, last;
      for (const rise::TraceSample& sample : clip.trace) {
        if (sample.time < slip.contactStart || sample.time > slip.contactEnd || sample.move == last) continue;
        spanned += (spanned.empty() ? "" : " > ") + sample.move;
        last = sample.move;
      }
      std::printf("     %s slid %.3f m over %.2f-%.2f s: %s\n", slip.effector.c_str(), slip.slip, slip.contactStart,
                  slip.contactEnd, spanned.c_str());
    }
  }
  std::printf("stood %d, reached the rise %d, passed every bar %d\n", stood, rose, passed);
}
