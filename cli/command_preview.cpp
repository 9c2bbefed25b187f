// SPDX-License-Identifier: MIT
// `rise-gen preview input.json|clip.glb -o sheet.png`: a contact sheet of key frames.
#include <filesystem>
#include <iostream>
#include <memory>

#include "cli/commands.h"
#include "cli/console.h"
#include "core/clip_output.h"
#include "core/generate.h"
#include "core/input_json.h"
#include "export/gltf_reader.h"

namespace rise::cli {
namespace {

struct PreviewArgs {
  std::string input;
  std::string output;
  SpecOverrides overrides;
  int frames = 8;
  int columns = 4;
  bool quiet = false;
};

int Run(const PreviewArgs& args) {
  const std::string problem = CheckOutputFolder(args.output);
  if (!problem.empty()) return ReportError(problem);
  const std::string ext = std::filesystem::path(args.input).extension().string();
  Clip clip;
  if (ext == ".glb" || ext == ".gltf") {
    const std::string error = ReadGltf(args.input, clip);
    if (!error.empty()) return ReportError(error);
  } else {
    Result<RiseSpec> loaded = LoadRiseSpec(args.input);
    if (!loaded) return ReportError(loaded.Error());
    Result<RiseSpec> spec = ApplyOverrides(args.overrides, loaded.Value());
    if (!spec) return ReportError(spec.Error());
    ProgressBar bar(args.quiet);
    GenerateSettings settings;
    settings.onProgress = [&bar](double simulated, double maxDuration) {
      bar.Draw(simulated / maxDuration, "simulating");
    };
    GeneratedClip generated = GenerateClip(spec.Value(), settings);
    bar.Clear();
    if (!generated.health.ok) {
      std::cerr << "rise-gen: error: " << args.input << ": " << generated.outcome << " (no file written)\n";
      return kExitFailed;
    }
    clip = std::move(generated.clip);
  }
  PreviewOptions options = PreviewOptionsFor(clip, args.input);
  options.keyFrames = args.frames;
  options.columns = args.columns;
  const std::string error = WritePreviewSheet(clip, options, args.output);
  if (!error.empty()) return ReportError(error);
  if (!args.quiet) std::cout << args.input << " -> " << args.output << "\n";
  return kExitOk;
}

}  // namespace

Command AddPreviewCommand(CLI::App& app) {
  auto args = std::make_shared<PreviewArgs>();
  CLI::App* sub = app.add_subcommand("preview", "Draw a contact sheet (.png) of a clip's key frames");
  sub->footer(
      "Key frames of the motion as boxes on a ground grid from a fixed three-quarter camera, with\n"
      "time, frame and phase under each. From an input file (simulated first; --fps, --seed and\n"
      "--max-duration override its values) or a .glb/.gltf clip.\n"
      "Example: rise-gen preview samples/side.json -o side.png\n"
      "Exit codes: 0 written; 1 the simulation failed; 2 bad input or output path.\n");
  sub->add_option("input", args->input, "Input file (.json, simulated first) or clip (.glb/.gltf)")->required();
  sub->add_option("-o,--output", args->output, "The sheet to write (.png); the folder must exist")->required();
  sub->add_option("--frames", args->frames, "Key frames shown, first and last included (default 8)")
      ->check(CLI::Range(2, 64));
  sub->add_option("--columns", args->columns, "Frames per row (default 4)")->check(CLI::Range(1, 16));
  AddSimulationOptions(*sub, args->overrides);
  sub->add_flag("-q,--quiet", args->quiet, "Print nothing but errors");
  return {sub, [args]() { return Run(*args); }};
}

}  // namespace rise::cli
