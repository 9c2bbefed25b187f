// SPDX-License-Identifier: MIT
// `rise-gen batch`: generates the clips of a library manifest on a pool of threads and keeps
// outDir/index.json describing them.
//
// Guarantees:
// - Results do not depend on the number of threads: every clip is a pure function of its input,
//   and index entries are in manifest order and hold no timings, so `jobs` 1 and 2 give
//   byte-identical files.
// - One clip failing (simulation unhealthy, quality bars missed, a write error) never stops the
//   others; its index entry says what went wrong.
// - Resume: a clip whose files all exist and whose sidecar holds the same input (InputHash) and
//   names this rise-gen version as its generator is not generated again (a new version may move
//   differently from the same input, so it makes its clips anew). Index entries are measured
//   from the files on disk either way, so a resumed run writes the same index as a fresh one.
// - The index is rewritten atomically after every finished clip, so it is valid whenever the run
//   stops (Ctrl-C via `stop`, or a crash); clips not run yet are listed as "pending".
//
// Index document:
//   { "generator": "rise-gen 0.1.0", "manifest": "library.json", "shard": "0/4" (when sharded),
//     "formats": ["glb"], "summary": { "clips", "ok", "failed", "errors", "pending" },
//     "clips": [ { "name", "category", "body", "seed", "status", "error" (when not ok),
//                  "files": { "glb": "back_supine_s1.glb", "metadata": "back_supine_s1.json", ... },
//                  "input_hash", "input": {...resolved input...},
//                  "duration_s", "frames", "time_to_stand_s", "quality": {...check figures...} } ],
//     "libraries": [ { "body", "file", "clips": [names] } ] (with libraryGlb) }
// Status: "ok" (files written, every quality bar holds), "failed" (files written, a bar missed),
// "error" (no files: the simulation or a write failed), "pending" (not run).
#pragma once

#include <atomic>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/library_manifest.h"

namespace rise {

struct BatchProgress {
  int total = 0;     // clips in this run
  int finished = 0;  // generated or skipped
  int failed = 0;    // of those, status "failed" or "error"
  int skipped = 0;   // of those, found on disk (resume)
};

struct BatchOptions {
  std::string outDir;       // must exist
  int jobs = 0;             // worker threads; 0: one per hardware thread
  bool libraryGlb = false;  // also write library_<body>.glb per body
  bool previews = false;    // also write <clip>.png contact sheets
  std::string indexName = "index.json";
  std::string manifestLabel;                // recorded in the index ("library.json")
  std::string shardLabel;                   // recorded in the index when not empty ("0/4")
  const std::atomic<bool>* stop = nullptr;  // when set: finish the clips in flight, start no more
  // Called after each finished clip, from the worker thread, one call at a time.
  std::function<void(const BatchProgress&)> onProgress;
};

struct BatchReport {
  BatchProgress progress;
  int ok = 0, failed = 0, errors = 0, pending = 0;
  bool stopped = false;  // `stop` was set before every clip ran
  std::string ioError;   // the index or a library file could not be written
  nlohmann::ordered_json index;
};

// Makes outDir (and its missing parents) if it does not exist yet; "" when it is then a writable
// folder, otherwise why it cannot be used. Called once the manifest is known to be good, so a bad
// manifest leaves nothing behind.
std::string PrepareBatchOutDir(const std::string& outDir);

// Runs the clips manifest.clips[i] for i in `selection` (ascending; e.g. ShardClips).
BatchReport RunBatch(const LibraryManifest& manifest, const std::vector<size_t>& selection,
                     const BatchOptions& options);

}  // namespace rise
