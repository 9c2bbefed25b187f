// SPDX-License-Identifier: MIT
#include <CLI/CLI.hpp>

int main(int argc, char** argv) {
  CLI::App app{"rise-gen: physically simulated get-up animation clips"};
  app.set_version_flag("--version", RISE_VERSION);
  CLI11_PARSE(app, argc, argv);
  return 0;
}
