// SPDX-License-Identifier: MIT
// Finds starts for the controller's scenario tests (tests/core/test_generate.cpp): each of those
// tests runs one stress start whose path shows a rare event (a push left on one limb, a rise
// caught on the hands, ...), and as the controller changes, a start's path changes with it. This
// reruns the inputs of a stress run (`stress_runner --runs FILE`) with their traces and lists,
// per event, the seeds that show it as its test asks, with the time of the event, so a test whose
// start no longer does can be given one that does.
//
//   scenario_scan RUNS.jsonl [--jobs J] [--limit N]
//
// Events (the test each feeds):
//   fall-off-support  a crawl that ends in a settle resting on one limb or none, fastest box < 8 m/s
//   push-fall         a push that ends in a settle; fastest box < 10 m/s; the start stands
//   one-limb-push     a push that rests on one limb or none for some steps and goes on: no push
//                     falls, no retry, the start stands
//   place-fall        a place that ends in a settle; fastest box < 10 m/s
//   rise-catch        a rise tipping forward caught on the hands (catch after rise), every push
//                     starting on both hands and at least two of them, no retry, the start stands
//   rise-topple       a rise that ends with the CoM 0.30-0.40 m past the feet; fastest box < 9 m/s
#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <vector>

#include "core/clip_quality.h"
#include "core/generate.h"
#include "core/input_json.h"

namespace {

struct Run {
  long long seed = 0;
  std::string input;  // the input file's JSON text
};

int Bearing(const rise::TraceSample& sample) {
  return static_cast<int>(std::count(sample.touching.begin(), sample.touching.end(), true));
}

// The time of each move named `from` that is followed by the settle (a fall), from the clip's phase spans.
std::vector<double> FallsFrom(const rise::GeneratedClip& result, const std::string& from) {
  std::vector<double> times;
  const std::vector<rise::PhaseSpan>& phases = result.clip.metadata.phases;
  for (size_t k = 1; k < phases.size(); ++k) {
    if (phases[k - 1].name == from && phases[k].name == "settle") times.push_back(phases[k].start);
  }
  return times;
}

// One line per event the run shows, as the scenario tests measure it.
std::vector<std::string> Events(const Run& run, const rise::GeneratedClip& result) {
  std::vector<std::string> lines;
  const std::vector<rise::TraceSample>& trace = result.trace;
  const double fastest = rise::MeasureFastestBox(result.clip).speed;
  auto add = [&](const char* event, double time, const std::string& more) {
    char text[256];
    std::snprintf(text, sizeof text, "%-17s seed %lld at %6.2f s  fastest %5.2f m/s  %s", event, run.seed, time, fastest,
                  more.c_str());
    lines.emplace_back(text);
  };
  for (size_t s = 1; s < trace.size(); ++s) {
    if (trace[s - 1].phase == rise::RisePhase::kCrawl && trace[s].phase == rise::RisePhase::kSettle && Bearing(trace[s]) <= 1 &&
        fastest < 8.0) {
      add("fall-off-support", trace[s].time, result.outcome);
      break;
    }
  }
  const std::vector<double> pushFalls = FallsFrom(result, "push");
  if (!pushFalls.empty() && fastest < 10.0 && result.stood) add("push-fall", pushFalls.front(), result.outcome);
  int unsupported = 0;
  double firstUnsupported = -1.0;
  for (const rise::TraceSample& sample : trace) {
    if (sample.phase != rise::RisePhase::kPush || Bearing(sample) > 1) continue;
    if (unsupported++ == 0) firstUnsupported = sample.time;
  }
  if (unsupported > 0 && pushFalls.empty() && result.retries == 0 && result.stood) {
    add("one-limb-push", firstUnsupported, std::to_string(unsupported) + " steps; " + result.outcome);
  }
  const std::vector<double> placeFalls = FallsFrom(result, "place");
  if (!placeFalls.empty() && fastest < 10.0) add("place-fall", placeFalls.front(), result.outcome);
  int catches = 0, pushes = 0;
  bool pushesOnBothHands = true;
  double firstCatch = -1.0;
  for (size_t s = 1; s < trace.size(); ++s) {
    if (trace[s].move == "catch" && trace[s - 1].move == "rise" && catches++ == 0) firstCatch = trace[s].time;
    if (trace[s].move == "push" && trace[s - 1].move != "push") {
      ++pushes;
      pushesOnBothHands = pushesOnBothHands && trace[s].touching[0] && trace[s].touching[1];
    }
  }
  if (catches > 0 && pushes >= 2 && pushesOnBothHands && result.retries == 0 && result.stood) {
    add("rise-catch", firstCatch, result.outcome);
  }
  for (size_t s = 1; s < trace.size(); ++s) {
    if (trace[s - 1].move != "rise" || trace[s].move == "rise") continue;
    if (trace[s].feetDistance >= 0.3f && trace[s].feetDistance < 0.4f && fastest < 9.0) {
      add("rise-topple", trace[s].time, "CoM " + std::to_string(trace[s].feetDistance) + " m past the feet");
      break;
    }
  }
  return lines;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: scenario_scan RUNS.jsonl [--jobs J] [--limit N]\n");
    return 2;
  }
  int jobs = 2;
  size_t limit = SIZE_MAX;
  for (int a = 2; a + 1 < argc; a += 2) {
    const std::string flag = argv[a];
    if (flag == "--jobs") jobs = std::max(1, std::atoi(argv[a + 1]));
    else if (flag == "--limit") limit = static_cast<size_t>(std::atoll(argv[a + 1]));
  }
  std::ifstream file(argv[1]);
  if (!file) {
    std::fprintf(stderr, "scenario_scan: cannot read %s\n", argv[1]);
    return 2;
  }
  std::vector<Run> runs;
  for (std::string line; std::getline(file, line) && runs.size() < limit;) {
    const nlohmann::json record = nlohmann::json::parse(line, nullptr, false);
    if (record.is_discarded() || !record.contains("input")) continue;
    runs.push_back({record.value("seed", 0LL), record["input"].dump()});
  }
  std::vector<std::vector<std::string>> found(runs.size());
  std::atomic<size_t> next{0};
  std::vector<std::thread> workers;
  for (int j = 0; j < jobs; ++j) {
    workers.emplace_back([&] {
      for (size_t k = next++; k < runs.size(); k = next++) {
        const auto spec = rise::ParseRiseSpec(runs[k].input, "seed " + std::to_string(runs[k].seed));
        if (!spec.IsOk()) continue;
        rise::GenerateSettings settings;
        settings.keepTrace = true;
        found[k] = Events(runs[k], rise::GenerateClip(spec.Value(), settings));
      }
    });
  }
  for (std::thread& worker : workers) worker.join();
  std::vector<std::string> lines;
  for (const std::vector<std::string>& run : found) lines.insert(lines.end(), run.begin(), run.end());
  std::stable_sort(lines.begin(), lines.end(), [](const std::string& a, const std::string& b) {
    return a.substr(0, 17) < b.substr(0, 17);
  });
  for (const std::string& line : lines) std::printf("%s\n", line.c_str());
  std::printf("%zu runs scanned, %zu events\n", runs.size(), lines.size());
  return 0;
}
