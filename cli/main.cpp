// SPDX-License-Identifier: MIT
// rise-gen: options -> command -> exit code. Every command's work lives in the libraries.
#include <CLI/CLI.hpp>
#include <algorithm>
#include <iostream>
#include <string>
#include <vector>

#include "cli/commands.h"

namespace {

// `rise-gen input.json -o clip.glb` means `rise-gen generate input.json -o clip.glb`: a first
// argument that is neither an option nor a command name is an input file.
std::vector<std::string> WithDefaultCommand(int argc, char** argv, const CLI::App& app) {
  std::vector<std::string> args(argv + 1, argv + argc);
  if (!args.empty() && args[0][0] != '-') {
    bool isCommand = false;
    for (const CLI::App* sub : app.get_subcommands({})) isCommand = isCommand || sub->check_name(args[0]);
    if (!isCommand) args.insert(args.begin(), "generate");
  }
  std::reverse(args.begin(), args.end());  // CLI11 takes the arguments in reverse order
  return args;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace rise::cli;
  CLI::App app{"rise-gen " RISE_VERSION
               ": physically simulated get-up animation clips.\n"
               "A character lies on the ground; rise-gen simulates it getting up with its own joint\n"
               "torques and writes the motion as glTF 2.0 (.glb/.gltf) and/or BVH.",
               "rise-gen"};
  app.set_version_flag("--version", RISE_VERSION);
  app.require_subcommand(0, 1);
  app.footer(
      "A first argument that is an input file runs `generate`:\n"
      "  rise-gen samples/supine.json -o clip.glb -o clip.bvh\n"
      "Run `rise-gen <command> --help` for a command's options.\n"
      "Exit codes: 0 success; 1 a clip failed its quality bars (or a batch had failures);\n"
      "2 bad input or I/O error (nothing written).\n");
  const std::vector<Command> commands{AddGenerateCommand(app), AddBatchCommand(app), AddCheckCommand(app),
                                      AddPreviewCommand(app), AddSchemaCommand(app)};
  std::vector<std::string> args = WithDefaultCommand(argc, argv, app);
  try {
    app.parse(args);
  } catch (const CLI::ParseError& e) {
    // --help and --version are "errors" with exit code 0; real parse errors are bad input.
    const int code = app.exit(e);
    return code == 0 ? kExitOk : kExitBadInput;
  }
  for (const Command& command : commands) {
    if (command.app->parsed()) return command.run();
  }
  std::cerr << app.help();
  return kExitBadInput;
}
