// SPDX-License-Identifier: MIT
// `rise-gen check clip.glb [--bvh clip.bvh] [--json]`: the quality bars, measured from the files.
#include <iostream>
#include <memory>

#include "cli/commands.h"
#include "cli/console.h"
#include "core/clip_check.h"

namespace rise::cli {
namespace {

struct CheckArgs {
  std::string clip;
  std::string bvh;
  std::string bvhUnits = "m";
  std::string bvhUp = "y";
  bool json = false;
};

int Run(const CheckArgs& args) {
  const BvhFormat format{*ParseBvhUnits(args.bvhUnits), *ParseBvhUp(args.bvhUp)};
  const ClipCheck check = CheckClipFiles(args.clip, args.bvh, format);
  if (!check.error.empty()) return ReportError(check.error);
  if (args.json) {
    nlohmann::json json = check.ToJson();
    json["file"] = args.clip;
    if (!args.bvh.empty()) json["bvhFile"] = args.bvh;
    std::cout << json.dump(2) << "\n";
  } else {
    std::cout << args.clip << "\n" << check.Summary();
  }
  return check.passed ? kExitOk : kExitFailed;
}

}  // namespace

Command AddCheckCommand(CLI::App& app) {
  auto args = std::make_shared<CheckArgs>();
  CLI::App* sub = app.add_subcommand("check", "Measure a clip file (ours or another tool's) against the quality bars");
  sub->footer(
      "Bars (core/clip_quality.h): starts lying; ends standing (and time to stand); no box more than\n"
      "2 cm below ground; hands/feet slide under 5 cm per contact; no joint jumps faster than 10 m/s;\n"
      "with --bvh, BVH and glTF joints within 1 cm on every frame. A slope clip of rise-gen is\n"
      "measured against its slope (from the clip's metadata).\n"
      "Example: rise-gen check clip.glb --bvh clip.bvh\n"
      "Exit codes: 0 every bar holds; 1 a bar does not; 2 a file cannot be read.\n");
  sub->add_option("clip", args->clip, "The clip: .glb or .gltf")->required();
  sub->add_option("--bvh", args->bvh, "A BVH of the same clip, compared joint by joint (at most 0.01 m apart)");
  sub->add_option("--bvh-units", args->bvhUnits, "Length unit the BVH was written in: m or cm (default m)")
      ->check(CLI::IsMember({"m", "cm"}));
  sub->add_option("--bvh-up", args->bvhUp, "Up axis the BVH was written with: y or z (default y)")
      ->check(CLI::IsMember({"y", "z"}));
  sub->add_flag("--json", args->json, "Print every figure as JSON instead of the PASS/FAIL lines");
  return {sub, [args]() { return Run(*args); }};
}

}  // namespace rise::cli
