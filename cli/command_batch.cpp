// SPDX-License-Identifier: MIT
// `rise-gen batch library.json -o outdir/ [--jobs N] [--shard I/N]`: a clip library.
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <memory>

#include "cli/commands.h"
#include "cli/console.h"
#include "core/batch_runner.h"
#include "core/library_manifest.h"

namespace rise::cli {
namespace {

struct BatchArgs {
  std::string manifest;
  std::string outDir;
  int jobs = 0;
  std::string shard;
  bool libraryGlb = false;
  bool previews = false;
  bool quiet = false;
};

std::atomic<bool> gStop{false};

// First Ctrl-C: finish the clips in flight and stop with the index valid. A second one ends
// the process at once (the default action is back).
void OnInterrupt(int) {
  gStop.store(true);
  std::signal(SIGINT, SIG_DFL);
}

int Run(const BatchArgs& args) {
  Result<LibraryManifest> manifest = LoadLibraryManifest(args.manifest);
  if (!manifest) return ReportError(manifest.Error());
  Shard shard;
  if (!args.shard.empty()) {
    Result<Shard> parsed = ParseShard(args.shard, "--shard");
    if (!parsed) return ReportError(parsed.Error());
    shard = parsed.Value();
  }
  if (args.libraryGlb && shard.count > 1) {
    return ReportError(
        "--library-glb: found with --shard, allowed: without it (run the shards first, then the same command "
        "without --shard: every clip is found up to date and the library files are written)");
  }
  const std::string problem = PrepareBatchOutDir(args.outDir);
  if (!problem.empty()) return ReportError(problem);

  BatchOptions options;
  options.outDir = args.outDir;
  options.jobs = args.jobs;
  options.libraryGlb = args.libraryGlb;
  options.previews = args.previews;
  options.manifestLabel = std::filesystem::path(args.manifest).filename().string();
  if (shard.count > 1) {
    options.shardLabel = args.shard;
    options.indexName = "index-" + std::to_string(shard.index) + "-of-" + std::to_string(shard.count) + ".json";
  }
  options.stop = &gStop;
  ProgressBar bar(args.quiet);
  options.onProgress = [&bar](const BatchProgress& p) {
    char text[96];
    std::snprintf(text, sizeof text, "%d/%d clips, %d failed, %d up to date", p.finished, p.total, p.failed, p.skipped);
    bar.Draw(static_cast<double>(p.finished) / p.total, text);
  };

  const auto start = std::chrono::steady_clock::now();
  std::signal(SIGINT, OnInterrupt);
  const BatchReport report = RunBatch(manifest.Value(), ShardClips(manifest.Value().clips.size(), shard), options);
  std::signal(SIGINT, SIG_DFL);
  bar.Clear();
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  for (const auto& entry : report.index["clips"]) {
    if (entry["status"] == "failed" || entry["status"] == "error") {
      std::fprintf(stderr, "rise-gen: %s %s: %s\n", entry["name"].get<std::string>().c_str(),
                   entry["status"].get<std::string>().c_str(), entry["error"].get<std::string>().c_str());
    }
  }
  if (!args.quiet) {
    const std::string index = (std::filesystem::path(args.outDir) / options.indexName).string();
    std::printf("%s: %d clips: %d ok, %d failed, %d errors, %d pending (%d up to date, skipped); %s; %.1f s\n",
                args.manifest.c_str(), report.progress.total, report.ok, report.failed, report.errors, report.pending,
                report.progress.skipped, index.c_str(), seconds);
  }
  if (!report.ioError.empty()) return ReportError(report.ioError);
  if (report.stopped) {
    std::fprintf(stderr, "rise-gen: stopped by Ctrl-C; run the same command again to resume\n");
    return kExitFailed;
  }
  return report.failed + report.errors > 0 ? kExitFailed : kExitOk;
}

}  // namespace

Command AddBatchCommand(CLI::App& app) {
  auto args = std::make_shared<BatchArgs>();
  CLI::App* sub = app.add_subcommand("batch", "Generate a clip library from a manifest, clips in parallel");
  sub->footer(
      "The manifest lists clips and/or a cross product of start postures x bodies x styles x seeds\n"
      "(format: core/library_manifest.h, example: samples/library.json). Clips are named by start\n"
      "category (back, stomach, side) and parameters, e.g. back_supine_tall_calm_s1.glb.\n"
      "outdir/index.json lists per clip its files, full resolved input, duration, time to stand, the\n"
      "quality figures of `check` and its status (ok, failed, error, pending); it is rewritten after\n"
      "every clip, so Ctrl-C stops cleanly with it valid. A rerun skips clips whose files exist and\n"
      "were made from the same input (resume). Results do not depend on --jobs.\n"
      "Job arrays: run `--shard $SLURM_ARRAY_TASK_ID/N` (or $JOB_COMPLETION_INDEX) into one shared\n"
      "folder, then the same command without --shard to write index.json (and --library-glb).\n"
      "Exit codes: 0 every clip ok; 1 a clip failed or errored, or Ctrl-C; 2 bad manifest, option,\n"
      "missing output folder or I/O error.\n");
  sub->add_option("manifest", args->manifest, "The library manifest (JSON; see samples/library.json)")->required();
  sub->add_option("-o,--output", args->outDir, "Output folder; made if missing")->required();
  sub->add_option("-j,--jobs", args->jobs, "Clips simulated at once (default: one per hardware thread)")
      ->check(CLI::Range(1, 1024));
  sub->add_option("--shard", args->shard,
                  "Generate only slice I of N (0 <= I < N; clips i with i % N == I), e.g. a job array's task id; "
                  "writes index-I-of-N.json");
  sub->add_flag("--library-glb", args->libraryGlb,
                "Also write library_<body>.glb per body: all its clips as named animations on one skeleton");
  sub->add_flag("--previews", args->previews, "Also write a contact sheet <clip>.png per clip");
  sub->add_flag("-q,--quiet", args->quiet, "Print nothing but errors and failed clips");
  return {sub, [args]() { return Run(*args); }};
}

}  // namespace rise::cli
