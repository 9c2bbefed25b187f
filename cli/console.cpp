// SPDX-License-Identifier: MIT
// The progress bar; see console.h.
#include "cli/console.h"

#include <unistd.h>

#include <algorithm>
#include <cstdio>

namespace rise::cli {

ProgressBar::ProgressBar(bool quiet)
    : enabled_(!quiet && isatty(STDERR_FILENO)), start_(std::chrono::steady_clock::now()) {}

ProgressBar::~ProgressBar() {
  Clear();
}

void ProgressBar::Draw(double fraction, const std::string& text) {
  if (!enabled_) return;
  constexpr int kWidth = 30;
  fraction = std::clamp(fraction, 0.0, 1.0);
  const int filled = static_cast<int>(fraction * kWidth);
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  std::string bar(filled, '#');
  bar.append(kWidth - filled, '-');
  char eta[32] = "";
  if (fraction > 0.0 && fraction < 1.0)
    std::snprintf(eta, sizeof eta, ", ETA %.0f s", elapsed * (1.0 / fraction - 1.0));
  // \r and a clear-to-end-of-line keep the bar on one line as it shrinks and grows.
  std::fprintf(stderr, "\r[%s] %3.0f%% %s%s\033[K", bar.c_str(), 100.0 * fraction, text.c_str(), eta);
  std::fflush(stderr);
  drawn_ = true;
}

void ProgressBar::Clear() {
  if (!drawn_) return;
  std::fprintf(stderr, "\r\033[K");
  std::fflush(stderr);
  drawn_ = false;
}

int ReportError(const std::string& message) {
  std::fprintf(stderr, "rise-gen: error: %s\n", message.c_str());
  return 2;
}

int ReportError(const InputError& error) {
  return ReportError(error.Format());
}

}  // namespace rise::cli
