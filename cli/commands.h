// SPDX-License-Identifier: MIT
// The rise-gen subcommands. Each Add*Command registers its options on `app` and returns the
// function that runs it once the command line has been parsed.
#pragma once

#include <CLI/CLI.hpp>
#include <functional>
#include <string>

#include "core/spec_overrides.h"

namespace rise::cli {

// Exit codes of every command (issue 6 section 2).
constexpr int kExitOk = 0;        // success
constexpr int kExitFailed = 1;    // a clip missed its quality bars, or a batch had failures
constexpr int kExitBadInput = 2;  // bad input or an I/O error; nothing was written

struct Command {
  CLI::App* app;
  std::function<int()> run;
};

Command AddGenerateCommand(CLI::App& app);
Command AddBatchCommand(CLI::App& app);
Command AddCheckCommand(CLI::App& app);
Command AddPreviewCommand(CLI::App& app);
Command AddSchemaCommand(CLI::App& app);

// The input-file overrides of the simulation, shared by `generate` and `preview` (--fps --seed
// --max-duration).
void AddSimulationOptions(CLI::App& command, SpecOverrides& overrides);

}  // namespace rise::cli
