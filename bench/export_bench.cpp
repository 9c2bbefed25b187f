// SPDX-License-Identifier: MIT
// Writing speed of the clip writers (issue 5 §5: a 10 s clip at 60 fps in
// under 20 ms). The motion is the synthetic swing of the export tests,
// resampled from 240 Hz as a simulation's output would be.
// Prints CSV: what,frames,joints,bytes,median_ms,min_ms,max_ms (bytes: the
// main file written; 0 for the in-memory resampling row).
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <vector>

#include "export/biped_fixture.h"
#include "export/bvh_writer.h"
#include "export/gltf_writer.h"

namespace {

constexpr int kRuns = 30;

void Measure(const char* what, const rise::Clip& clip, const std::string& path,
             const std::function<std::string()>& write) {
  std::vector<double> ms;
  for (int run = 0; run < kRuns; ++run) {
    const auto start = std::chrono::steady_clock::now();
    const std::string error = write();
    const auto end = std::chrono::steady_clock::now();
    if (!error.empty()) {
      std::fprintf(stderr, "%s: %s\n", what, error.c_str());
      std::exit(1);
    }
    ms.push_back(std::chrono::duration<double, std::milli>(end - start).count());
  }
  std::sort(ms.begin(), ms.end());
  std::printf("%s,%d,%d,%ju,%.3f,%.3f,%.3f\n", what, clip.FrameCount(), clip.skeleton.JointCount(),
              static_cast<uintmax_t>(path.empty() ? 0 : std::filesystem::file_size(path)), ms[ms.size() / 2],
              ms.front(), ms.back());
}

}  // namespace

int main() {
  const rise::Skeleton skeleton = rise::test::MakeBipedSkeleton();
  const rise::MotionSamples samples = rise::test::SwingSamples(skeleton, 10.0, 240.0);
  const rise::Clip clip = rise::ResampleClip(skeleton, samples, 60.0, rise::test::SwingClip(60.0, 10.0).metadata);
  const std::filesystem::path folder = std::filesystem::temp_directory_path() / "rise_export_bench";
  std::filesystem::create_directories(folder);
  const std::string glb = (folder / "bench.glb").string();
  const std::string gltf = (folder / "bench.gltf").string();
  const std::string bvh = (folder / "bench.bvh").string();

  std::printf("what,frames,joints,bytes,median_ms,min_ms,max_ms\n");
  Measure("glb+sidecar", clip, glb, [&] { return rise::WriteGltf(clip, glb); });
  Measure("gltf+bin", clip, gltf, [&] { return rise::WriteGltf(clip, gltf, {rise::NamingPreset::kDefault, false}); });
  Measure("bvh", clip, bvh, [&] { return rise::WriteBvh(clip, bvh, {{}, rise::NamingPreset::kDefault, false}); });
  Measure("resample_240hz_to_60fps", clip, "",
          [&] { return rise::ResampleClip(skeleton, samples, 60.0, {}).Validate(); });
  std::filesystem::remove_all(folder);
  return 0;
}
