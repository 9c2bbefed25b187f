// SPDX-License-Identifier: MIT
// Stress runner (issue 8 §1): clips from seeded random inputs over the whole documented input range.
//
// Each run draws a custom lying pose (random root orientation, every joint angle uniform within
// its limits, drawn again while limbs pass through each other deeper than the loader allows,
// dropped from 0-1 m), a body of 1.4-2.1 m and 40-130 kg, a slope of 0-15 deg, friction
// 0.3-1.2 and every style value uniform in its range; writes it as input-file JSON and loads it
// through the CLI's validated loader, then runs GenerateClip on it. The clip is recorded at 240 fps,
// the engine's own rate, so every simulated step is measured. Health asserted per run:
//   - the simulation stayed healthy (the engine's non-finite / exploded-speed flags never set);
//   - every recorded joint position and rotation is finite;
//   - a clip that can be measured (MeasureClip, as `rise-gen check`);
//   - a result: stood, or a "did not stand" outcome (its last phase, or the falls after the last
//     retry), at or before max_duration_s.
// and the two physical bounds:
//   - no body (box centre) moves faster than kMaxBodySpeed between two steps;
//   - no box vertex goes deeper than kMaxPenetration below the ground (the slope plane).
// Standing is reported (stand rate, seeds that did not stand, outcomes histogram, the phases the
// tries before the stand ended in: a fall, or a roll or crawl that could not go on, the mean
// time per phase of the runs that stood and of those that did not, the stand rate over ranges
// of each input drawn, and on slopes the stand rate by which way the body faced once it was up
// on its hands and feet: where in the input range the controller is weak), not asserted.
//
//   stress_runner [--count N] [--first-seed S] [--jobs J] [--max-duration SECONDS (default: left out)] [--seeds a,b,c]
//                 [--bounds assert|report] [--runs FILE]
// Exit 0 when every run is healthy, 1 when any run is not (listed with its seed and input); the
// two physical bounds (body speed, box depth) count too unless `--bounds report`. 2 for bad
// arguments. --runs writes one JSON line per run (seed, stood, outcome, the phases its tries ended
// in, seconds per phase, facing, input) for analysis.
// Runs are a pure function of their seed, so a failing seed reproduces with
// `--seeds <seed>`.
#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <mutex>
#include <nlohmann/json.hpp>
#include <random>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "core/biped.h"
#include "core/clip_check.h"
#include "core/clip_quality.h"
#include "core/generate.h"
#include "core/input_json.h"

namespace {

// A body falling from the highest start (a 2.1 m body upside down, its feet 2.1 m up, dropped 1 m)
// reaches sqrt(2 g 3.1 m) = 7.8 m/s; a get-up moves limbs far slower. Faster is an explosion.
constexpr double kMaxBodySpeed = 10.0;    // m/s, the centre of any box
constexpr double kMaxPenetration = 0.02;  // m, below the ground plane, any box vertex
constexpr double kRecordFps = 240.0;      // the engine's step rate (physics/settings.h)
// The slopes (deg) the stand rate by facing is reported over: steep enough for facing to matter,
// and issue 8's target range.
constexpr double kFacingSlopes[2] = {2.5, 10.0};

struct Options {
  int count = 100;
  uint64_t firstSeed = 1;
  int jobs = 0;
  double maxDuration = 0.0;  // s; 0 leaves max_duration_s out of the inputs (its default applies)
  std::vector<uint64_t> seeds;  // explicit seeds replace count/firstSeed
  bool assertBounds = true;     // false: physical bounds broken are reported, not failed
  std::string runsFile;         // JSON lines of every run; empty: none
};

struct RunResult {
  uint64_t seed = 0;
  std::string input;  // the resolved input, to reproduce with `rise-gen`
  bool stood = false;
  double timeToStand = -1.0;
  double simulated = 0.0;
  std::string outcome;
  // The phase of every try that ended before the stand (a fall, or a roll or crawl that could not
  // go on), in order: each sent the plan back to settle. The last phase alone hides a rise that
  // fell and left too little time for the next try to get past the crawl.
  std::vector<std::string> retriedFrom;
  // Seconds spent in each phase, all tries together, in the order the run first entered them:
  // where a run that did not stand spent its time.
  std::vector<std::pair<std::string, double>> phaseSeconds;
  // On a slope, the angle (deg) between uphill and the way the body faced (pelvis to head, along
  // the ground) when it first got onto its hands and feet (the first push); -1 on level ground or
  // when it never got there. The start pose is random, so this is drawn too, though not as an input.
  double facingDeg = -1.0;
  std::vector<std::string> violations;  // broken health (tier 3) or result rules; empty when healthy
  std::vector<std::string> overBounds;  // physical bounds broken (body speed, box depth)
  double maxBodySpeed = 0.0;
  double maxPenetration = 0.0;
  double wallSeconds = 0.0;
};

// One input drawn by RandomInput and the ranges its stand rate is reported over (bin edges, from
// the documented minimum to the maximum).
struct InputAxis {
  const char* label;
  const char* pointer;  // JSON pointer into the input
  std::vector<double> edges;
};

const std::vector<InputAxis>& InputAxes() {
  static const std::vector<InputAxis> axes = {
      {"slope_deg", "/terrain/slope_deg", {0.0, 2.5, 5.0, 10.0, 15.0}},
      {"friction", "/terrain/friction", {0.3, 0.45, 0.6, 0.9, 1.2}},
      {"height_m", "/character/height_m", {1.4, 1.55, 1.7, 1.85, 2.1}},
      {"mass_kg", "/character/mass_kg", {40.0, 70.0, 100.0, 130.0}},
      {"drop_height_m", "/start/drop_height_m", {0.0, 0.5, 1.0}},
      {"speed", "/style/speed", {0.25, 1.0, 2.0, 3.0}},
      {"step_height_m", "/style/step_height_m", {0.02, 0.1, 0.2, 0.3}},
      {"stance_width_m", "/style/stance_width_m", {0.1, 0.35, 0.6}},
      {"tiredness", "/style/tiredness", {0.0, 0.5, 1.0}},
  };
  return axes;
}

double Uniform(std::mt19937_64& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

// Rounded to 0.001 so the JSON input reads as a person would write it.
double Round3(double value) {
  return std::round(value * 1000.0) / 1000.0;
}

// The input file of one seed, drawn over the documented ranges of issue 8 §1.
nlohmann::ordered_json RandomInput(uint64_t seed, double maxDuration) {
  std::mt19937_64 rng(seed);
  nlohmann::ordered_json input;
  const double height = Round3(Uniform(rng, 1.4, 2.1));
  const double mass = Round3(Uniform(rng, 40.0, 130.0));
  input["character"] = {{"height_m", height}, {"mass_kg", mass}};
  nlohmann::ordered_json joints;
  const rise::BipedDef def = rise::MakeBipedDef(static_cast<float>(height), static_cast<float>(mass));
  // Drawn again while the limbs pass through each other deeper than the loader allows (about 1
  // draw in 5): a body cannot start inside itself.
  for (bool inside = true; inside;) {
    joints = nlohmann::ordered_json::object();
    rise::StartSpec start;
    start.posture = rise::Posture::kCustom;
    for (int j = 0; j < def.skeleton.JointCount(); ++j) {
      if (def.DofCount(j) == 0) continue;
      nlohmann::ordered_json angles = nlohmann::ordered_json::array();
      std::vector<double>& drawn = start.jointsDeg[def.skeleton.joints[j].name];
      for (const rise::JointDof& dof : def.bones[j].dofs) {
        drawn.push_back(Round3(Uniform(rng, dof.minDeg, dof.maxDeg)));
        angles.push_back(drawn.back());
      }
      joints[def.skeleton.joints[j].name] = angles;
    }
    const std::optional<rise::SelfOverlap> overlap = rise::DeepestSelfOverlap(def, rise::StartPose(def, start, 0.0));
    inside = overlap && overlap->depthM > rise::kMaxStartOverlapM;
  }
  input["start"] = {
      {"posture", "custom"},
      {"root_euler_deg",
       {Round3(Uniform(rng, -180, 180)), Round3(Uniform(rng, -180, 180)), Round3(Uniform(rng, -180, 180))}},
      {"joints_deg", joints},
      {"drop_height_m", Round3(Uniform(rng, 0.0, 1.0))}};
  input["terrain"] = {{"slope_deg", Round3(Uniform(rng, 0.0, 15.0))}, {"friction", Round3(Uniform(rng, 0.3, 1.2))}};
  input["style"] = {
      {"speed", Round3(Uniform(rng, 0.25, 3.0))},         {"step_height_m", Round3(Uniform(rng, 0.02, 0.3))},
      {"stance_width_m", Round3(Uniform(rng, 0.1, 0.6))}, {"sway", Round3(Uniform(rng, 0.0, 1.0))},
      {"tiredness", Round3(Uniform(rng, 0.0, 1.0))},       {"look_around", Round3(Uniform(rng, 0.0, 1.0))}};
  input["seed"] = seed;
  input["fps"] = kRecordFps;
  if (maxDuration > 0.0) input["max_duration_s"] = maxDuration;
  return input;
}

bool Finite(const glm::vec3& v) {
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

std::string Format(const char* format, double a, double b = 0.0) {
  char text[160];
  std::snprintf(text, sizeof text, format, a, b);
  return text;
}

// FacingDeg of RunResult, from the recorded clip.
double FacingFromUphill(const rise::Clip& clip, const std::vector<std::vector<glm::vec3>>& positions, double slopeDeg) {
  // The ground normal leans downhill, so its part along the ground points down the slope.
  const glm::vec3 normal = rise::GroundPlane(slopeDeg).normal;
  const glm::vec3 downhill(normal.x, 0.0f, normal.z);
  if (glm::length(downhill) < 1e-4f) return -1.0;
  const auto push = std::find_if(clip.metadata.phases.begin(), clip.metadata.phases.end(),
                                 [](const rise::PhaseSpan& span) { return span.name == "push"; });
  if (push == clip.metadata.phases.end() || positions.empty()) return -1.0;
  const size_t frame = std::min(positions.size() - 1, static_cast<size_t>(std::lround(push->start * clip.fps)));
  const glm::vec3 along = positions[frame][clip.skeleton.Find("head")] - positions[frame][clip.skeleton.Find("pelvis")];
  const glm::vec3 heading(along.x, 0.0f, along.z);
  if (glm::length(heading) < 1e-4f) return -1.0;
  const float cosine = glm::dot(glm::normalize(heading), -glm::normalize(downhill));
  return glm::degrees(std::acos(std::clamp(cosine, -1.0f, 1.0f)));
}

RunResult Run(uint64_t seed, double maxDuration) {
  const auto start = std::chrono::steady_clock::now();
  RunResult run;
  run.seed = seed;
  run.input = RandomInput(seed, maxDuration).dump();
  const rise::Result<rise::RiseSpec> spec = rise::ParseRiseSpec(run.input, "seed " + std::to_string(seed));
  if (!spec) {
    run.violations.push_back("input rejected: " + spec.Error().Format());
    return run;
  }
  const rise::GeneratedClip generated = rise::GenerateClip(spec.Value());
  run.stood = generated.stood;
  run.timeToStand = generated.timeToStand;
  run.simulated = generated.simulatedSeconds;
  run.outcome = generated.outcome;
  const std::vector<rise::PhaseSpan>& phases = generated.clip.metadata.phases;
  for (size_t k = 1; k < phases.size(); ++k) {
    if (phases[k].name == "settle" && phases[k - 1].name != "settle") run.retriedFrom.push_back(phases[k - 1].name);
  }
  for (const rise::PhaseSpan& span : phases) {
    auto entry = std::find_if(run.phaseSeconds.begin(), run.phaseSeconds.end(),
                              [&](const auto& phase) { return phase.first == span.name; });
    if (entry == run.phaseSeconds.end()) entry = run.phaseSeconds.insert(entry, {span.name, 0.0});
    entry->second += span.end - span.start;
  }
  if (!generated.health.ok) run.violations.push_back("unhealthy simulation: " + generated.health.message);

  const std::vector<std::vector<glm::vec3>> positions = rise::JointPositionSequence(generated.clip);
  bool finite = true;
  for (const auto& frame : positions) {
    for (const glm::vec3& p : frame) finite = finite && Finite(p);
  }
  for (const auto& track : generated.clip.rotations) {
    for (const glm::quat& q : track) finite = finite && std::isfinite(q.w) && Finite(glm::vec3(q.x, q.y, q.z));
  }
  if (!finite) run.violations.push_back("non-finite joint position or rotation in the clip");
  if (finite) run.facingDeg = FacingFromUphill(generated.clip, positions, spec.Value().terrain.slopeDeg);
  const rise::FastestBox fastest = finite ? rise::MeasureFastestBox(generated.clip) : rise::FastestBox{};
  run.maxBodySpeed = fastest.speed;
  if (run.maxBodySpeed > kMaxBodySpeed) {
    run.overBounds.push_back("body '" + generated.clip.skeleton.joints[fastest.body].name + "' " +
                             Format("moved at %.2f m/s at %.3f s", run.maxBodySpeed, fastest.frame / kRecordFps) +
                             Format(" (bound %.0f m/s)", kMaxBodySpeed));
  }
  if (finite) {
    const rise::QualityReport quality = rise::MeasureClip(generated.clip, rise::QualityOptionsFor(generated.clip));
    run.maxPenetration = quality.maxPenetration;
    if (!quality.error.empty()) run.violations.push_back("clip cannot be measured: " + quality.error);
    if (quality.maxPenetration > kMaxPenetration) {
      run.overBounds.push_back("box of '" + quality.penetrationJoint + "' " +
                               Format("%.1f cm below ground at %.3f s", 100.0 * quality.maxPenetration,
                                      quality.penetrationFrame / kRecordFps));
    }
  }
  // Either ran to max_duration_s ("... within T s (last phase: P)") or fell after its last retry
  // and came to rest ("...: fell N times, at rest at T s").
  const bool didNotStand = run.outcome.rfind("did not stand", 0) == 0 &&
                           (run.outcome.find("last phase") != std::string::npos || run.outcome.find("fell") != std::string::npos);
  if (generated.health.ok && (run.stood ? run.timeToStand < 0.0 : !didNotStand)) {
    run.violations.push_back("no clear result: outcome \"" + run.outcome + "\"");
  }
  if (run.simulated > spec.Value().maxDurationS + 1.0 / kRecordFps) {
    run.violations.push_back(Format("simulated %.3f s, past max_duration_s %.1f", run.simulated, spec.Value().maxDurationS));
  }
  run.wallSeconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return run;
}

nlohmann::json PhaseSecondsJson(const RunResult& run) {
  nlohmann::json seconds = nlohmann::json::object();
  for (const auto& [phase, total] : run.phaseSeconds) seconds[phase] = Round3(total);
  return seconds;
}

// The outcome with its numbers left out, so like outcomes count together.
std::string OutcomeKind(const RunResult& run) {
  if (!run.violations.empty()) return "health violation";
  if (run.stood) return "stood";
  if (run.outcome.find("fell") != std::string::npos) return "did not stand (fell after its last retry)";
  const size_t phase = run.outcome.find("(last phase:");
  return phase == std::string::npos ? run.outcome : "did not stand " + run.outcome.substr(phase);
}

bool ParseArgs(int argc, char** argv, Options& options) {
  for (int i = 1; i < argc; ++i) {
    const std::string arg = argv[i];
    if (i + 1 >= argc) return false;
    const std::string value = argv[++i];
    char* end = nullptr;
    if (arg == "--count") {
      options.count = static_cast<int>(std::strtol(value.c_str(), &end, 10));
    } else if (arg == "--first-seed") {
      options.firstSeed = std::strtoull(value.c_str(), &end, 10);
    } else if (arg == "--jobs") {
      options.jobs = static_cast<int>(std::strtol(value.c_str(), &end, 10));
    } else if (arg == "--max-duration") {
      options.maxDuration = std::strtod(value.c_str(), &end);
    } else if (arg == "--bounds") {
      if (value != "assert" && value != "report") return false;
      options.assertBounds = value == "assert";
      end = const_cast<char*>(value.c_str() + value.size());
    } else if (arg == "--runs") {
      options.runsFile = value;
      end = const_cast<char*>(value.c_str() + value.size());
    } else if (arg == "--seeds") {
      std::stringstream list(value);
      std::string item;
      while (std::getline(list, item, ',')) options.seeds.push_back(std::strtoull(item.c_str(), nullptr, 10));
      end = const_cast<char*>(value.c_str() + value.size());
    } else {
      return false;
    }
    if (end == nullptr || *end != '\0') return false;
  }
  return options.count > 0 && options.jobs >= 0 && (options.maxDuration == 0.0 || (options.maxDuration >= 1.0 && options.maxDuration <= 120.0));
}

}  // namespace

int main(int argc, char** argv) {
  Options options;
  if (!ParseArgs(argc, argv, options)) {
    std::fprintf(stderr,
                 "usage: stress_runner [--count N] [--first-seed S] [--jobs J] [--max-duration 1..120] "
                 "[--seeds a,b,c] [--bounds assert|report] [--runs FILE]\n");
    return 2;
  }
  std::vector<uint64_t> seeds = options.seeds;
  if (seeds.empty()) {
    for (int i = 0; i < options.count; ++i) seeds.push_back(options.firstSeed + i);
  }
  const int jobs = options.jobs > 0 ? options.jobs : std::max(1u, std::thread::hardware_concurrency());

  const auto start = std::chrono::steady_clock::now();
  std::vector<RunResult> results(seeds.size());
  std::atomic<size_t> next{0};
  std::mutex printing;
  std::vector<std::thread> workers;
  for (int w = 0; w < jobs; ++w) {
    workers.emplace_back([&] {
      for (size_t i = next++; i < seeds.size(); i = next++) {
        results[i] = Run(seeds[i], options.maxDuration);
        const RunResult& run = results[i];
        if (!run.violations.empty() || !run.overBounds.empty()) {
          const std::lock_guard<std::mutex> lock(printing);
          std::printf("seed %llu", static_cast<unsigned long long>(seeds[i]));
          for (const std::string& v : run.violations) std::printf(" VIOLATION: %s;", v.c_str());
          for (const std::string& v : run.overBounds) std::printf(" OVER BOUND: %s;", v.c_str());
          std::printf("\n  input: %s\n", run.input.c_str());
          std::fflush(stdout);
        }
      }
    });
  }
  for (std::thread& worker : workers) worker.join();
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  std::map<std::string, std::vector<uint64_t>> kinds;
  std::map<std::string, std::pair<int, int>> retries;  // phase -> (tries ended there, runs whose first did)
  std::vector<std::string> phaseOrder;                  // phase names as the runs first meet them
  std::map<std::string, std::pair<double, double>> phaseSeconds;  // phase -> (stood, did not stand) total s
  int stood = 0, violations = 0;
  std::vector<uint64_t> overBounds;
  double slowest = 0.0, fastestSpeed = 0.0, deepest = 0.0;
  for (const RunResult& run : results) {
    kinds[OutcomeKind(run)].push_back(run.seed);
    for (const std::string& phase : run.retriedFrom) ++retries[phase].first;
    for (const auto& [phase, seconds] : run.phaseSeconds) {
      if (std::find(phaseOrder.begin(), phaseOrder.end(), phase) == phaseOrder.end()) phaseOrder.push_back(phase);
      (run.stood ? phaseSeconds[phase].first : phaseSeconds[phase].second) += seconds;
    }
    if (!run.retriedFrom.empty()) ++retries[run.retriedFrom.front()].second;
    stood += run.stood ? 1 : 0;
    violations += run.violations.empty() ? 0 : 1;
    if (!run.overBounds.empty()) overBounds.push_back(run.seed);
    slowest = std::max(slowest, run.wallSeconds);
    fastestSpeed = std::max(fastestSpeed, run.maxBodySpeed);
    deepest = std::max(deepest, run.maxPenetration);
  }
  // Each run's input as JSON, for the runs file and the stand rate over input ranges.
  std::vector<nlohmann::json> inputs;
  for (const RunResult& run : results) inputs.push_back(nlohmann::json::parse(run.input));
  if (!options.runsFile.empty()) {
    std::ofstream runs(options.runsFile);
    for (size_t r = 0; r < results.size(); ++r) {
      const RunResult& run = results[r];
      runs << nlohmann::json{{"seed", run.seed}, {"stood", run.stood}, {"time_to_stand", run.timeToStand},
                             {"outcome", run.outcome}, {"retried_from", run.retriedFrom}, {"phase_seconds", PhaseSecondsJson(run)},
                             {"facing_deg", run.facingDeg < 0.0 ? nlohmann::json(nullptr) : nlohmann::json(Round3(run.facingDeg))},
                             {"input", inputs[r]}}.dump()
           << '\n';
    }
  }
  const size_t n = results.size();
  const std::string limit = options.maxDuration > 0.0 ? Format("%.0f s", options.maxDuration) : "its default";
  std::printf("stress: %zu random starts (seeds %llu..), max_duration_s %s, %d threads, %.1f s wall (slowest run %.1f s)\n",
              n, static_cast<unsigned long long>(seeds.front()), limit.c_str(), jobs, wall, slowest);
  std::printf("stand rate: %d / %zu (%.1f %%)\n", stood, n, 100.0 * stood / static_cast<double>(n));
  std::printf("outcomes:\n");
  for (const auto& [kind, list] : kinds) {
    std::printf("  %5zu  %s; seeds", list.size(), kind.c_str());
    for (size_t i = 0; i < list.size() && i < 12; ++i) std::printf(" %llu", static_cast<unsigned long long>(list[i]));
    std::printf(list.size() > 12 ? " ...\n" : "\n");
  }
  std::printf("tries that ended before the stand (a fall, or a roll or crawl that could not go on), by phase:\n");
  for (const auto& [phase, count] : retries) {
    std::printf("  %5d  in %s (the first of %d runs)\n", count.first, phase.c_str(), count.second);
  }
  // Mean seconds per run in each phase, runs that stood apart from the rest: a run that did not
  // stand ran out of time somewhere, and this says where the time went.
  std::printf("mean seconds per run in each phase (%d stood / %zu did not):\n", stood, n - static_cast<size_t>(stood));
  for (const std::string& phase : phaseOrder) {
    const auto& [stoodSeconds, failedSeconds] = phaseSeconds[phase];
    std::printf("  %-7s %6.1f / %6.1f\n", phase.c_str(), stood > 0 ? stoodSeconds / stood : 0.0,
                n > static_cast<size_t>(stood) ? failedSeconds / static_cast<double>(n - stood) : 0.0);
  }
  std::printf("stand rate over ranges of each input (stood / runs):\n");
  for (const InputAxis& axis : InputAxes()) {
    const nlohmann::json::json_pointer pointer(axis.pointer);
    std::vector<std::pair<int, int>> bins(axis.edges.size() - 1);
    for (size_t r = 0; r < results.size(); ++r) {
      const double value = inputs[r].at(pointer).get<double>();
      size_t bin = 0;
      while (bin + 1 < bins.size() && value >= axis.edges[bin + 1]) ++bin;
      bins[bin].first += results[r].stood ? 1 : 0;
      ++bins[bin].second;
    }
    std::printf("  %-15s", axis.label);
    for (size_t b = 0; b < bins.size(); ++b) {
      std::printf("  %g-%g: %d/%d", axis.edges[b], axis.edges[b + 1], bins[b].first, bins[b].second);
    }
    std::printf("\n");
  }
  // On a slope a body facing downhill has its hands below its feet, and the CoM must go uphill to
  // get over them; where the roll left the body facing is not an input, so it gets its own line.
  {
    const double edges[] = {0.0, 60.0, 120.0, 180.0};
    const char* names[] = {"uphill", "across", "downhill"};
    std::pair<int, int> bins[3] = {}, never = {};
    for (size_t r = 0; r < results.size(); ++r) {
      const double slope = inputs[r].at("/terrain/slope_deg"_json_pointer).get<double>();
      if (slope < kFacingSlopes[0] || slope > kFacingSlopes[1]) continue;
      const double facing = results[r].facingDeg;
      std::pair<int, int>& bin = facing < 0.0 ? never : bins[facing < edges[1] ? 0 : facing < edges[2] ? 1 : 2];
      bin.first += results[r].stood ? 1 : 0;
      ++bin.second;
    }
    std::printf("  facing on slopes of %g-%g deg (once up on hands and feet, from uphill):", kFacingSlopes[0], kFacingSlopes[1]);
    for (int b = 0; b < 3; ++b) std::printf("  %s %g-%g: %d/%d", names[b], edges[b], edges[b + 1], bins[b].first, bins[b].second);
    std::printf("  never on hands and feet: %d/%d\n", never.first, never.second);
  }
  std::printf("health: %d run(s) unhealthy or without a clear result\n", violations);
  std::printf(
      "bounds: %zu run(s) over a physical bound (%s); fastest body %.2f m/s (bound %.0f), deepest box %.2f cm "
      "(bound %.0f)",
      overBounds.size(), options.assertBounds ? "asserted" : "reported only", fastestSpeed, kMaxBodySpeed,
      100.0 * deepest, 100.0 * kMaxPenetration);
  if (!overBounds.empty()) std::printf("; seeds");
  for (uint64_t seed : overBounds) std::printf(" %llu", static_cast<unsigned long long>(seed));
  std::printf("\n");
  const bool failed = violations > 0 || (options.assertBounds && !overBounds.empty());
  return failed ? 1 : 0;
}
