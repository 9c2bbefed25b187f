// SPDX-License-Identifier: MIT
// glTF 2.0 output: `.glb` (one binary file) or `.gltf` + `.bin`, by extension.
//
// What the file holds, and why each importer is happy with it:
// - one node per joint, named by the naming preset, in a single hierarchy
//   with exactly one root joint (Unreal rejects several); node rest TRS is the
//   bind pose (translation = rest offset, no rotation), so importers that
//   rebuild the bind pose from inverseBindMatrices and those that take the
//   node rest pose get the same skeleton;
// - a skin (joints = all joints, inverseBindMatrices = inverse bind-pose world
//   transforms) and a skinned mesh node at the scene root with one box per
//   bone (24 vertices per box with normals, JOINTS_0/WEIGHTS_0 weight 1.0 to
//   its bone) and one material, so it shades correctly;
// - leaf end joints (head top, finger tips, toes) so Blender's bone-length
//   heuristic gives bones their true length;
// - one animation per clip: translation of the root (and of any joint with a
//   translation track), rotation of every joint, LINEAR, times from 0, unit
//   quaternions kept in one hemisphere (rotation_track.h);
// - the clip metadata (clip_metadata_json.h) in the animation's `extras`, and
//   asset.generator = "rise-gen <version>".
#pragma once

#include <string>
#include <vector>

#include "export/clip.h"
#include "export/joint_names.h"

namespace rise {

struct GltfOptions {
  NamingPreset naming = NamingPreset::kDefault;
  // Also write the metadata sidecar `<clip>.meta.json` (clip_metadata_json.h).
  bool writeSidecar = true;
};

// Writes `clip` (valid) to `path` (*.glb or *.gltf; a .gltf gets its buffer in
// `<stem>.bin` beside it). The animation is named after the file's stem.
// Returns an empty string on success, otherwise a message; on failure no
// partial file is left (atomic_file.h).
std::string WriteGltf(const Clip& clip, const std::string& path, const GltfOptions& options = {});

// One animation of a library file.
struct NamedClip {
  std::string name;  // the glTF animation name
  const Clip* clip;  // not null; valid
};

// Several clips of one skeleton as named animations of a single file (the
// batch `--library-glb`). Every clip must have the same skeleton (names,
// parents, rest offsets, boxes); the mesh and skin come from the first. Each
// animation carries its own metadata in `extras`; no sidecar is written.
std::string WriteGltfLibrary(const std::vector<NamedClip>& clips, const std::string& path,
                             const GltfOptions& options = {});

}  // namespace rise
