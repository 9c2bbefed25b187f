// SPDX-License-Identifier: MIT
// `rise-gen [generate] input.json -o clip.glb [-o clip.bvh]`: one clip from one input file.
#include <cstdio>
#include <iostream>
#include <memory>

#include "cli/commands.h"
#include "cli/console.h"
#include "core/clip_check.h"
#include "core/clip_output.h"
#include "core/generate.h"
#include "core/input_json.h"
#include "core/spec_overrides.h"
#include "export/atomic_file.h"
#include "export/preview_sheet.h"

namespace rise::cli {
namespace {

struct GenerateArgs {
  std::string input;
  std::vector<std::string> outputs;
  SpecOverrides overrides;
  std::string rootMotion;
  std::string bvhUnits = "m";
  std::string bvhUp = "y";
  std::string trace;
  std::string preview;
  bool quiet = false;
  bool json = false;
};

std::string Join(const std::vector<std::string>& items) {
  std::string text;
  for (const std::string& item : items) text += (text.empty() ? "" : ", ") + item;
  return text;
}

int Run(const GenerateArgs& args) {
  Result<RiseSpec> loaded = LoadRiseSpec(args.input);
  if (!loaded) return ReportError(loaded.Error());
  Result<RiseSpec> spec = ApplyOverrides(args.overrides, loaded.Value());
  if (!spec) return ReportError(spec.Error());

  ClipOutputOptions output = ClipOutputOptionsOf(spec.Value());
  if (!args.rootMotion.empty()) output.rootMotion = *ParseRootMotion(args.rootMotion);
  output.bvh = BvhFormat{*ParseBvhUnits(args.bvhUnits), *ParseBvhUp(args.bvhUp)};
  // Every path is checked before the simulation runs, so a typo costs no time and leaves no file.
  for (const std::string& path : args.outputs) {
    const std::string problem = CheckClipOutputPath(path);
    if (!problem.empty()) return ReportError(problem);
  }
  if (const std::string problem = CheckOutputsSpareInput(args.outputs, args.input); !problem.empty()) {
    return ReportError(problem);
  }
  for (const std::string* path : {&args.trace, &args.preview}) {
    const std::string problem = path->empty() ? "" : CheckOutputFolder(*path);
    if (!problem.empty()) return ReportError(problem);
  }

  ProgressBar bar(args.quiet || args.json);
  GenerateSettings settings;
  settings.keepTrace = !args.trace.empty();
  settings.onProgress = [&bar](double simulated, double maxDuration) {
    char text[64];
    std::snprintf(text, sizeof text, "simulated %.1f of at most %.0f s", simulated, maxDuration);
    bar.Draw(simulated / maxDuration, text);
  };
  const GeneratedClip generated = GenerateClip(spec.Value(), settings);
  bar.Clear();
  if (!generated.health.ok) {
    std::cerr << "rise-gen: error: " << args.input << ": " << generated.outcome << " (no file written)\n";
    return kExitFailed;
  }

  std::string error = WriteClipFiles(generated.clip, args.outputs, output);
  std::vector<std::string> written = ClipOutputFiles(args.outputs);
  if (error.empty() && !args.trace.empty()) {
    error = WriteFileAtomically(args.trace, TraceToJsonLines(generated.trace, generated.clip.skeleton));
    written.push_back(args.trace);
  }
  if (error.empty() && !args.preview.empty()) {
    error = WritePreviewSheet(generated.clip, PreviewOptionsFor(generated.clip, args.input), args.preview);
    written.push_back(args.preview);
  }
  if (!error.empty()) {
    RemoveOutputFiles(written);
    return ReportError(error);
  }

  const QualityReport quality = MeasureClip(generated.clip, QualityOptionsFor(generated.clip));
  const bool passed = generated.stood && quality.passed;
  if (args.json) {
    nlohmann::ordered_json json;
    json["input"] = args.input;
    json["files"] = written;
    json["stood"] = generated.stood;
    json["outcome"] = generated.outcome;
    json["time_to_stand_s"] = generated.timeToStand;
    json["duration_s"] = generated.clip.Duration();
    json["frames"] = generated.clip.FrameCount();
    json["fps"] = generated.clip.fps;
    json["retries"] = generated.retries;
    json["quality"] = quality.ToJson();
    json["passed"] = passed;
    std::cout << json.dump(2) << "\n";
  } else if (!args.quiet) {
    std::printf("%s -> %s: %s; %.2f s, %d frames at %g fps; quality %s\n", args.input.c_str(),
                Join(args.outputs).c_str(), generated.outcome.c_str(), generated.clip.Duration(),
                generated.clip.FrameCount(), generated.clip.fps,
                quality.passed ? "PASS" : ("FAIL (" + MissedBars(quality) + ")").c_str());
  }
  return passed ? kExitOk : kExitFailed;
}

}  // namespace

void AddSimulationOptions(CLI::App& command, SpecOverrides& overrides) {
  command.add_option("--fps", overrides.fps, "Frames per second of the clip, 1 to 240 (overrides fps)");
  command.add_option("--seed", overrides.seed, "Random seed, a whole number from 0 to 2^53 (overrides seed)");
  command.add_option("--max-duration", overrides.maxDurationS,
                     "Longest clip in seconds, 1 to 120; the simulation stops there (overrides max_duration_s)");
}

Command AddGenerateCommand(CLI::App& app) {
  auto args = std::make_shared<GenerateArgs>();
  CLI::App* sub =
      app.add_subcommand("generate", "Simulate one clip from an input file and write it (the default command)");
  sub->footer(
      "Examples:\n"
      "  rise-gen samples/supine.json -o clip.glb\n"
      "  rise-gen generate samples/prone.json -o out/prone.glb -o out/prone.bvh --names mixamo --bvh-units cm\n"
      "Prints one line: outcome (time to stand), duration, frames and the quality verdict of `rise-gen check`;\n"
      "a progress bar on a terminal.\n"
      "Exit codes: 0 stood and every quality bar holds; 1 written but a bar missed, or the simulation failed\n"
      "(then nothing is written); 2 bad input, option or output path (nothing written).\n");
  sub->add_option("input", args->input, "Input file (JSON; `rise-gen schema` prints its format)")->required();
  sub->add_option("-o,--output", args->outputs,
                  "Output file, by extension: .glb or .gltf (glTF 2.0), .bvh. Repeat for several; each also gets "
                  "the metadata sidecar <stem>.meta.json. The folder must exist.")
      ->required();
  AddSimulationOptions(*sub, args->overrides);
  sub->add_option("--names", args->overrides.names,
                  "Joint naming preset: default, mixamo or ue (overrides output.names)");
  sub->add_flag("--in-place", args->overrides.inPlace,
                "Remove the travel over the ground from the clip (sets output.root_motion to false)");
  sub->add_option("--root-motion", args->rootMotion,
                  "Where travel over the ground goes: bake (the pelvis moves), in-place (removed), extract (a ground "
                  "joint `root` carries it). Overrides output.root_motion")
      ->check(CLI::IsMember({"bake", "in-place", "extract"}))
      ->excludes("--in-place");
  sub->add_option("--bvh-units", args->bvhUnits, "BVH length unit: m or cm (default m)")
      ->check(CLI::IsMember({"m", "cm"}));
  sub->add_option("--bvh-up", args->bvhUp, "BVH up axis: y or z (default y)")->check(CLI::IsMember({"y", "z"}));
  sub->add_option("--trace", args->trace, "Also write the controller's debug trace (JSON lines, one per control step)");
  sub->add_option("--preview", args->preview, "Also write a contact sheet of key frames (.png)");
  sub->add_flag("-q,--quiet", args->quiet, "Print nothing but errors");
  sub->add_flag("--json", args->json, "Print the result as JSON (outcome, files, quality figures) instead of a line");
  return {sub, [args]() { return Run(*args); }};
}

}  // namespace rise::cli
