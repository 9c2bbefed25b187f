// SPDX-License-Identifier: MIT
// Writing one generated clip to the files a user asked for, shared by `rise-gen generate` and
// the batch: the writer is chosen by extension (.glb/.gltf glTF 2.0, .bvh), the root-motion mode
// and naming preset are applied, and the metadata sidecar `<stem>.meta.json` is written beside each
// distinct file stem. All or nothing: paths are checked before any simulation runs, and when a
// later writer fails the files already written are removed again.
#pragma once

#include <string>
#include <vector>

#include "core/rise_spec.h"
#include "export/bvh_format.h"
#include "export/clip.h"
#include "export/joint_names.h"
#include "export/preview_sheet.h"
#include "export/root_motion.h"

namespace rise {

struct ClipOutputOptions {
  NamingPreset naming = NamingPreset::kDefault;
  RootMotion rootMotion = RootMotion::kBake;
  BvhFormat bvh;
};

// The options an input asks for (output.names, output.root_motion).
ClipOutputOptions ClipOutputOptionsOf(const RiseSpec& spec);

// "" when a clip can be written to `path`: its extension is .glb, .gltf or .bvh and its folder
// exists and is writable; otherwise why not.
std::string CheckClipOutputPath(const std::string& path);

// "" when `path` names a file (not a folder) in an existing folder and can be written there (see
// CheckWritable in export/atomic_file.h: a read-only folder or file is refused); otherwise why not.
std::string CheckOutputFolder(const std::string& path);

// Every file WriteClipFiles(…, paths, …) makes: the clips, a .gltf's .bin, the sidecars.
std::vector<std::string> ClipOutputFiles(const std::vector<std::string>& paths);

// "" unless one of `outputs` (with the files they bring: .bin, sidecar .json) would overwrite the
// input file (`in.meta.json -o in.glb` would replace the input with the clip's sidecar).
std::string CheckOutputsSpareInput(const std::vector<std::string>& outputs, const std::string& input);

// Writes `clip` (as simulated: root motion baked, canonical names) to every path. Returns "" on
// success, otherwise the first writer's message, with no file of this call left behind.
std::string WriteClipFiles(const Clip& clip, const std::vector<std::string>& paths, const ClipOutputOptions& options);

// Removes the regular files that exist among `files` (cleaning up after a failed write).
void RemoveOutputFiles(const std::vector<std::string>& files);

// Contact-sheet options for a clip: the ground of its resolved input (a slope when it has one)
// and `title`.
PreviewOptions PreviewOptionsFor(const Clip& clip, const std::string& title);

}  // namespace rise
