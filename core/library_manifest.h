// SPDX-License-Identifier: MIT
// A batch manifest: one JSON file that lists clips and/or a cross product of variations, resolved
// into the RiseSpecs of a clip library, each named by its start category and parameters.
//
// File format (every key optional; input keys are those of an input file, see input_json.h):
//   {
//     "formats": ["glb", "bvh"],            files per clip: "glb" or "gltf", optionally "bvh" (default ["glb"])
//     "defaults": { ...input keys... },     the base of every clip
//     "clips": [ { "name": "push_back", "body": "average", ...input keys... } ],
//     "cross": {                            the cross product starts x bodies x styles x seeds
//       "starts": [ "supine", { "name": "prone_turned", "posture": "prone", "heading_deg": 30 } ],
//       "bodies": [ { "name": "tall", "height_m": 1.95, "mass_kg": 95 },
//                   { "name": "range", "height_m": { "from": 1.5, "to": 1.9, "count": 3 } } ],
//       "styles": [ { "name": "calm", "speed": 0.8 } ],
//       "seeds": [1, 2]                     or { "from": 1, "count": 4 }
//     }
//   }
// - A start entry is a posture name or a "start" object with an optional "name" (default: the
//   posture). Body entries are "character" objects, style entries "style" objects; both need a
//   "name". A body's height_m / mass_kg may be a range { from, to, count }: the entry then
//   stands for count (x count) bodies named "<name>_h<height>" / "_m<mass>".
// - An axis left out is one entry: the defaults (it then adds nothing to clip names).
// - Cross clips are named "<category>_<start>[_<body>][_<style>]_s<seed>", e.g.
//   "back_supine_tall_calm_s1"; explicit clips carry their own "name". Names are file stems:
//   letters, digits, '_', '-', '.'; unique; not "index" (the batch writes index.json).
// - Explicit clips come first, then the cross product with starts outermost and seeds innermost.
// - Clips of one body (same "body" name) share one skeleton in a --library-glb file, so they must
//   agree on the character and on output.names / output.root_motion.
// Errors name the file and JSON path ("cross.bodies[1].height_m.count"), like the input loader.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/result.h"
#include "core/rise_spec.h"

namespace rise {

// How a clip starts, as game engines pick get-up animations: on the back, the stomach or a side.
enum class StartCategory { kBack, kStomach, kSide };

// "back", "stomach", "side".
const char* StartCategoryName(StartCategory category);

// The category of a start pose. A custom pose is classed by where the pelvis's front (+Z in the
// standing pose) points: up is back, down is stomach, sideways (within 60 deg of level) is side.
StartCategory CategoryOf(const StartSpec& start);

struct ManifestClip {
  std::string name;  // file stem, unique within the manifest
  StartCategory category = StartCategory::kBack;
  std::string body;  // body name: the --library-glb group ("default" when not named)
  RiseSpec spec;     // fully resolved input
};

struct LibraryManifest {
  std::vector<std::string> formats{"glb"};  // file extensions written per clip, in order
  std::vector<ManifestClip> clips;
};

// Parses manifest text; fileName labels error messages.
Result<LibraryManifest> ParseLibraryManifest(const std::string& text, const std::string& fileName);
Result<LibraryManifest> LoadLibraryManifest(const std::string& path);

// One slice of a library for a job array: clips whose index i satisfies i % count == index.
// Round robin keeps the slices alike in size and in mix of categories.
struct Shard {
  int index = 0;  // 0-based, as Slurm's SLURM_ARRAY_TASK_ID and Kubernetes' JOB_COMPLETION_INDEX
  int count = 1;
};

// "I/N" with 0 <= I < N; errors are labelled with `label` (e.g. "--shard").
Result<Shard> ParseShard(const std::string& text, const std::string& label);

// Indices of the clips of `shard` among clipCount clips, ascending.
std::vector<size_t> ShardClips(size_t clipCount, const Shard& shard);

// 16 hex digits (FNV-1a, 64 bit) of the resolved input with keys sorted: equal exactly when the
// inputs are equal, so a batch can tell whether a clip on disk was made from this input.
std::string InputHash(const RiseSpec& spec);

// The same hash from resolved-input JSON text (e.g. a sidecar's "parameters").
std::string InputHashOfJson(const std::string& resolvedInputJson);

}  // namespace rise
