// SPDX-License-Identifier: MIT
// Batch speed (issue 6 section 5: the 40-clip library on 2 cores in under 5 s wall, wall time
// close to 1/cores). Runs a manifest (default samples/library.json) with 1 worker thread and then
// with `jobs` (default 2), each into a fresh folder, and checks the two indexes are identical.
// Prints CSV: jobs,clips,wall_s,cpu_s,wall_ms_per_clip,cpu_ms_per_clip,speedup,ok,failed
// Usage: batch_bench [manifest] [jobs] [scratch folder]
#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <string>

#include "core/batch_runner.h"
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
  if (one.index != many.index) {
    std::fprintf(stderr, "the indexes of 1 and %d jobs differ\n", jobs);
    return 1;
  }
  fs::remove_all(scratch);
  return 0;
}
