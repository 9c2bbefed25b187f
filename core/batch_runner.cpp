// SPDX-License-Identifier: MIT
// The batch thread pool, resume and index; see batch_runner.h.
#include "core/batch_runner.h"

#include <algorithm>
#include <filesystem>
#include <map>
#include <mutex>
#include <system_error>
#include <thread>

#include "core/clip_check.h"
#include "core/clip_output.h"
#include "core/generate.h"
#include "core/input_json.h"
#include "core/json_text.h"
#include "export/atomic_file.h"
#include "export/clip_metadata_json.h"
#include "export/gltf_reader.h"
#include "export/gltf_writer.h"
#include "export/preview_sheet.h"

namespace rise {
namespace {

namespace fs = std::filesystem;
using Ordered = nlohmann::ordered_json;

struct ClipFiles {
  std::vector<std::string> clipPaths;  // one per manifest format, in order; the glTF one among them
  std::string gltf, bvh, sidecar, preview;
  std::vector<std::string> all;  // everything the clip leaves in outDir
};

ClipFiles FilesOf(const LibraryManifest& manifest, const ManifestClip& clip, const BatchOptions& options) {
  ClipFiles files;
  const fs::path dir(options.outDir);
  for (const std::string& format : manifest.formats) {
    const std::string path = (dir / (clip.name + "." + format)).string();
    files.clipPaths.push_back(path);
    (format == "bvh" ? files.bvh : files.gltf) = path;
  }
  files.sidecar = SidecarPath(files.gltf);
  files.all = ClipOutputFiles(files.clipPaths);
  if (options.previews) {
    files.preview = (dir / (clip.name + ".png")).string();
    files.all.push_back(files.preview);
  }
  return files;
}

// The clip's files are on disk and were made from this very input by this very version.
bool UpToDate(const ClipFiles& files, const std::string& inputHash) {
  std::error_code ec;
  for (const std::string& file : files.all) {
    if (!fs::is_regular_file(file, ec)) return false;
  }
  const Result<std::string> text = ReadInputFile(files.sidecar);
  ClipMetadata metadata;
  return text && MetadataFromJson(text.Value(), metadata).empty() && metadata.generatorVersion == RISE_VERSION &&
         InputHashOfJson(metadata.parametersJson) == inputHash;
}

std::string FileName(const std::string& path) {
  return fs::path(path).filename().string();
}

// The index entry's fixed part: who the clip is and which files it has.
Ordered EntryHead(const LibraryManifest& manifest, const ManifestClip& clip, const ClipFiles& files,
                  const std::string& inputHash) {
  Ordered entry;
  entry["name"] = clip.name;
  entry["category"] = StartCategoryName(clip.category);
  entry["body"] = clip.body;
  entry["seed"] = clip.spec.seed;
  entry["status"] = "pending";
  Ordered names = Ordered::object();
  for (size_t i = 0; i < manifest.formats.size(); ++i) names[manifest.formats[i]] = FileName(files.clipPaths[i]);
  names["metadata"] = FileName(files.sidecar);
  if (!files.preview.empty()) names["preview"] = FileName(files.preview);
  entry["files"] = names;
  entry["input_hash"] = inputHash;
  entry["input"] = RiseSpecToJson(clip.spec);
  return entry;
}

// Measures the files on disk into the entry (the same figures `rise-gen check` prints).
void MeasureEntry(const ClipFiles& files, Ordered& entry) {
  const ClipCheck check = CheckClipFiles(files.gltf, files.bvh);
  if (!check.error.empty()) {
    entry["status"] = "error";
    entry["error"] = check.error;
    return;
  }
  entry["status"] = check.passed ? "ok" : "failed";
  if (!check.passed) {
    std::string missed = MissedBars(check.quality);
    if (!check.bvhOk) missed += std::string(missed.empty() ? "" : ", ") + "BVH vs glTF";
    entry["error"] = "missed the quality bars: " + missed;
  }
  entry["duration_s"] = check.quality.duration;
  entry["frames"] = check.quality.frames;
  entry["time_to_stand_s"] = check.clip.metadata.timeToStand;
  entry["quality"] = check.ToJson();
}

// Generates (or finds) one clip and returns its complete index entry.
Ordered RunClip(const LibraryManifest& manifest, const ManifestClip& clip, const BatchOptions& options, bool& skipped) {
  const ClipFiles files = FilesOf(manifest, clip, options);
  const std::string hash = InputHash(clip.spec);
  Ordered entry = EntryHead(manifest, clip, files, hash);
  skipped = UpToDate(files, hash);
  if (!skipped) {
    // Files of an older input must not survive next to a failed new one.
    RemoveOutputFiles(files.all);
    const GeneratedClip generated = GenerateClip(clip.spec);
    if (!generated.health.ok) {
      entry["status"] = "error";
      entry["error"] = generated.outcome;
      return entry;
    }
    std::string error = WriteClipFiles(generated.clip, files.clipPaths, ClipOutputOptionsOf(clip.spec));
    if (error.empty() && options.previews) {
      Clip written;
      error = ReadGltf(files.gltf, written);
      if (error.empty()) error = WritePreviewSheet(written, PreviewOptionsFor(written, clip.name), files.preview);
    }
    if (!error.empty()) {
      RemoveOutputFiles(files.all);
      entry["status"] = "error";
      entry["error"] = error;
      return entry;
    }
  }
  MeasureEntry(files, entry);
  return entry;
}

Ordered Summary(const BatchReport& report, int total) {
  return Ordered{{"clips", total},
                 {"ok", report.ok},
                 {"failed", report.failed},
                 {"errors", report.errors},
                 {"pending", report.pending}};
}

void Count(const std::vector<Ordered>& entries, BatchReport& report) {
  report.ok = report.failed = report.errors = report.pending = 0;
  for (const Ordered& entry : entries) {
    const std::string status = entry["status"];
    if (status == "ok") ++report.ok;
    if (status == "failed") ++report.failed;
    if (status == "error") ++report.errors;
    if (status == "pending") ++report.pending;
  }
}

Ordered IndexDocument(const LibraryManifest& manifest, const BatchOptions& options, const BatchReport& report,
                      const std::vector<Ordered>& entries, const Ordered* libraries) {
  Ordered index;
  index["generator"] = std::string("rise-gen ") + RISE_VERSION;
  index["manifest"] = options.manifestLabel;
  if (!options.shardLabel.empty()) index["shard"] = options.shardLabel;
  index["formats"] = manifest.formats;
  index["summary"] = Summary(report, static_cast<int>(entries.size()));
  index["clips"] = entries;
  if (libraries) index["libraries"] = *libraries;
  return index;
}

std::string LibraryFileName(const std::string& body) { return "library_" + body + ".glb"; }

// One library_<body>.glb per body, from the clips on disk; "" or the first write error.
std::string WriteLibraries(const LibraryManifest& manifest, const std::vector<size_t>& selection,
                           const std::vector<Ordered>& entries, const BatchOptions& options, Ordered& libraries) {
  std::vector<std::string> bodies;  // in order of first appearance
  std::map<std::string, std::vector<size_t>> clipsOf;
  for (size_t k = 0; k < selection.size(); ++k) {
    const std::string status = entries[k]["status"];
    if (status != "ok" && status != "failed") continue;
    const std::string& body = manifest.clips[selection[k]].body;
    if (clipsOf[body].empty()) bodies.push_back(body);
    clipsOf[body].push_back(selection[k]);
  }
  libraries = Ordered::array();
  for (const std::string& body : bodies) {
    std::vector<Clip> clips(clipsOf[body].size());
    std::vector<NamedClip> named;
    Ordered names = Ordered::array();
    for (size_t c = 0; c < clips.size(); ++c) {
      const ManifestClip& clip = manifest.clips[clipsOf[body][c]];
      const std::string error = ReadGltf(FilesOf(manifest, clip, options).gltf, clips[c]);
      if (!error.empty()) return error;
      named.push_back({clip.name, &clips[c]});
      names.push_back(clip.name);
    }
    const std::string file = LibraryFileName(body);
    const ManifestClip& first = manifest.clips[clipsOf[body][0]];
    const GltfOptions gltf{ClipOutputOptionsOf(first.spec).naming, false};
    const std::string error = WriteGltfLibrary(named, (fs::path(options.outDir) / file).string(), gltf);
    if (!error.empty()) return error;
    libraries.push_back(Ordered{{"body", body}, {"file", file}, {"clips", names}});
  }
  return "";
}

}  // namespace

std::string PrepareBatchOutDir(const std::string& outDir) {
  std::error_code ec;
  if (outDir.empty()) return "empty output folder";
  // Shards of one library started together make the same folder at once: one of them wins, and
  // for the others it then exists, which is all that is asked.
  fs::create_directories(outDir, ec);
  std::error_code statError;
  if (!fs::is_directory(outDir, statError)) {
    return outDir + ": cannot make the output folder" + (ec ? " (" + ec.message() + ")" : std::string(" (a file is in the way)"));
  }
  return CheckWritable((fs::path(outDir) / "index.json").string());
}

BatchReport RunBatch(const LibraryManifest& manifest, const std::vector<size_t>& selection,
                     const BatchOptions& options) {
  BatchReport report;
  report.progress.total = static_cast<int>(selection.size());
  const std::string indexPath = (fs::path(options.outDir) / options.indexName).string();
  // Every file this run writes; the temporaries a killed run left of them go first.
  std::vector<std::string> outputs{indexPath};
  std::vector<Ordered> entries;
  for (size_t i : selection) {
    const ManifestClip& clip = manifest.clips[i];
    const ClipFiles files = FilesOf(manifest, clip, options);
    entries.push_back(EntryHead(manifest, clip, files, InputHash(clip.spec)));
    outputs.insert(outputs.end(), files.all.begin(), files.all.end());
    if (options.libraryGlb) outputs.push_back((fs::path(options.outDir) / LibraryFileName(clip.body)).string());
  }
  RemoveAbandonedTemporaries(outputs);
  std::mutex mutex;  // guards entries, report and the index file
  const auto writeIndex = [&](const Ordered* libraries) {
    Count(entries, report);
    report.index = IndexDocument(manifest, options, report, entries, libraries);
    const std::string error = WriteFileAtomically(indexPath, report.index.dump(2) + "\n");
    if (!error.empty() && report.ioError.empty()) report.ioError = error;
  };
  writeIndex(nullptr);

  // Clips with the longest time budget go first: the short ones left at the
  // end fill in while the last long one runs (in manifest order, a 30 s clip
  // drawn last kept one core busy alone).
  std::vector<size_t> order(selection.size());
  for (size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::stable_sort(order.begin(), order.end(), [&](size_t a, size_t b) {
    return manifest.clips[selection[a]].spec.maxDurationS > manifest.clips[selection[b]].spec.maxDurationS;
  });
  std::atomic<size_t> next{0};
  const auto worker = [&]() {
    for (;;) {
      if (options.stop && options.stop->load()) return;
      const size_t claimed = next.fetch_add(1);
      if (claimed >= order.size()) return;
      const size_t k = order[claimed];
      bool skipped = false;
      Ordered entry;
      try {
        entry = RunClip(manifest, manifest.clips[selection[k]], options, skipped);
      } catch (const std::exception& e) {
        // Only resource exhaustion gets here; the clip is reported and the others go on.
        entry = entries[k];
        entry["status"] = "error";
        entry["error"] = e.what();
      }
      const std::lock_guard<std::mutex> lock(mutex);
      entries[k] = entry;
      ++report.progress.finished;
      if (skipped) ++report.progress.skipped;
      if (entry["status"] != "ok") ++report.progress.failed;
      writeIndex(nullptr);
      if (options.onProgress) options.onProgress(report.progress);
    }
  };
  const unsigned hardware = std::max(1u, std::thread::hardware_concurrency());
  const size_t jobs =
      std::min<size_t>(options.jobs > 0 ? options.jobs : hardware, std::max<size_t>(1, selection.size()));
  std::vector<std::thread> pool;
  for (size_t t = 1; t < jobs; ++t) pool.emplace_back(worker);
  worker();
  for (std::thread& thread : pool) thread.join();

  report.stopped = report.progress.finished < report.progress.total;
  if (options.libraryGlb && !report.stopped) {
    Ordered libraries;
    const std::string error = WriteLibraries(manifest, selection, entries, options, libraries);
    if (!error.empty() && report.ioError.empty()) report.ioError = error;
    writeIndex(&libraries);
  } else {
    writeIndex(nullptr);
  }
  return report;
}

}  // namespace rise
