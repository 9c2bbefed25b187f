// SPDX-License-Identifier: MIT
// The whole pipeline's speed (issue 7 section 1, issue 6 section 5).
// 1. One clip end to end: samples/supine.json cut to 6 s, simulated (controller + IK + physics
//    through GenerateClip) and written as .glb and .bvh (WriteClipFiles); median thread CPU time
//    of several runs, split into generate and write, and the real-time factor.
// 2. A library: a manifest (default samples/library.json, 40 clips) with 1 worker thread and then
//    with `jobs` (default 2), each into a fresh folder; checks the two indexes are identical.
// 3. Peak resident memory of the process (getrusage), which includes both batches.
// Prints CSV blocks. Usage: batch_bench [manifest] [jobs] [scratch folder]
#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <string>
#include <vector>

#include "core/batch_runner.h"
#include "core/clip_output.h"
#include "core/generate.h"
#include "core/input_json.h"
#include "core/library_manifest.h"

namespace {

namespace fs = std::filesystem;

// Wall seconds and process CPU seconds (all threads) of one run: on a shared machine the CPU
// time per clip is the steadier figure, the wall time shows the parallel speed-up.
rise::BatchReport Run(const rise::LibraryManifest& manifest, int jobs, const fs::path& dir, double& seconds,
                      double& cpu) {
  fs::remove_all(dir);
  fs::create_directories(dir);
  rise::BatchOptions options;
  options.outDir = dir.string();
  options.jobs = jobs;
  const std::clock_t cpuStart = std::clock();
  const auto start = std::chrono::steady_clock::now();
  rise::BatchReport report = rise::RunBatch(manifest, rise::ShardClips(manifest.clips.size(), rise::Shard{}), options);
  seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  cpu = static_cast<double>(std::clock() - cpuStart) / CLOCKS_PER_SEC;
  return report;
}

double ThreadSeconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

double Median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

// Section 1; returns false when the sample cannot be loaded or written.
bool SingleClip(const fs::path& dir) {
  constexpr double kClipSeconds = 6.0;
  constexpr int kRuns = 5;
  rise::Result<rise::RiseSpec> loaded = rise::LoadRiseSpec(RISE_SOURCE_DIR "/samples/supine.json");
  if (!loaded) {
    std::fprintf(stderr, "%s\n", loaded.Error().Format().c_str());
    return false;
  }
  rise::RiseSpec spec = loaded.Value();
  spec.maxDurationS = kClipSeconds;
  fs::remove_all(dir);
  fs::create_directories(dir);
  const std::vector<std::string> paths = {(dir / "supine.glb").string(), (dir / "supine.bvh").string()};
  std::vector<double> generateSeconds, writeSeconds, totalSeconds;
  rise::GeneratedClip generated;
  for (int run = 0; run < kRuns; ++run) {
    const double start = ThreadSeconds();
    generated = rise::GenerateClip(spec);
    const double simulated = ThreadSeconds();
    const std::string error = rise::WriteClipFiles(generated.clip, paths, rise::ClipOutputOptionsOf(spec));
    const double end = ThreadSeconds();
    if (!error.empty()) {
      std::fprintf(stderr, "%s\n", error.c_str());
      return false;
    }
    generateSeconds.push_back(simulated - start);
    writeSeconds.push_back(end - simulated);
    totalSeconds.push_back(end - start);
  }
  const double total = Median(totalSeconds);
  std::printf("clip,simulated_s,generate_cpu_ms,write_cpu_ms,total_cpu_ms,real_time_factor,stood\n");
  std::printf("supine_6s,%.2f,%.1f,%.1f,%.1f,%.0f,%s\n", generated.simulatedSeconds, 1000.0 * Median(generateSeconds),
              1000.0 * Median(writeSeconds), 1000.0 * total, generated.simulatedSeconds / total,
              generated.stood ? "yes" : "no");
  return true;
}

long PeakRssKilobytes() {
  rusage usage{};
  getrusage(RUSAGE_SELF, &usage);
  return usage.ru_maxrss;
}

}  // namespace

int main(int argc, char** argv) {
  const std::string path = argc > 1 ? argv[1] : RISE_SOURCE_DIR "/samples/library.json";
  const int jobs = argc > 2 ? std::stoi(argv[2]) : 2;
  const fs::path scratch = argc > 3 ? fs::path(argv[3]) : fs::temp_directory_path() / "rise_batch_bench";
  const rise::Result<rise::LibraryManifest> manifest = rise::LoadLibraryManifest(path);
  if (!manifest) {
    std::fprintf(stderr, "%s\n", manifest.Error().Format().c_str());
    return 2;
  }
  if (!SingleClip(scratch / "single")) return 2;
  const long singleRss = PeakRssKilobytes();
  std::printf("\n");

  const int clips = static_cast<int>(manifest.Value().clips.size());
  double serial = 0.0, parallel = 0.0, serialCpu = 0.0, parallelCpu = 0.0;
  const rise::BatchReport one = Run(manifest.Value(), 1, scratch / "jobs1", serial, serialCpu);
  const rise::BatchReport many =
      Run(manifest.Value(), jobs, scratch / ("jobs" + std::to_string(jobs)), parallel, parallelCpu);
  std::printf("jobs,clips,wall_s,cpu_s,wall_ms_per_clip,cpu_ms_per_clip,speedup,ok,failed\n");
  std::printf("1,%d,%.3f,%.3f,%.1f,%.1f,1.00,%d,%d\n", clips, serial, serialCpu, 1000.0 * serial / clips,
              1000.0 * serialCpu / clips, one.ok, one.failed + one.errors);
  std::printf("%d,%d,%.3f,%.3f,%.1f,%.1f,%.2f,%d,%d\n", jobs, clips, parallel, parallelCpu, 1000.0 * parallel / clips,
              1000.0 * parallelCpu / clips, serial / parallel, many.ok, many.failed + many.errors);
  std::printf("\npeak_rss_after_one_clip_mb,%.1f\npeak_rss_after_batches_mb,%.1f\n", singleRss / 1024.0,
              PeakRssKilobytes() / 1024.0);
  if (one.index != many.index) {
    std::fprintf(stderr, "the indexes of 1 and %d jobs differ\n", jobs);
    return 1;
  }
  fs::remove_all(scratch);
  return 0;
}
