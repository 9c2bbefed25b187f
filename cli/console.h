// SPDX-License-Identifier: MIT
// Terminal output of the CLI: a one-line progress bar that is drawn only when stderr is a
// terminal (so logs and pipes never fill with carriage returns).
#pragma once

#include <chrono>
#include <string>

#include "core/result.h"

namespace rise::cli {

class ProgressBar {
 public:
  // quiet, or stderr not a terminal: the bar draws nothing.
  explicit ProgressBar(bool quiet);
  ~ProgressBar();

  // fraction in [0, 1]; `text` follows the bar. An ETA from the elapsed time is added.
  void Draw(double fraction, const std::string& text);
  // Clears the bar's line.
  void Clear();

 private:
  bool enabled_;
  bool drawn_ = false;
  std::chrono::steady_clock::time_point start_;
};

// Prints `rise-gen: error: <message>` on stderr and returns 2 (bad input or I/O error).
int ReportError(const std::string& message);
int ReportError(const InputError& error);

}  // namespace rise::cli
