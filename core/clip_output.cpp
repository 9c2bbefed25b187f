// SPDX-License-Identifier: MIT
// Clip output by extension; see clip_output.h.
#include "core/clip_output.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <system_error>

#include "core/clip_check.h"
#include "export/atomic_file.h"
#include "export/bvh_writer.h"
#include "export/clip_metadata_json.h"
#include "export/gltf_writer.h"

namespace rise {
namespace {

namespace fs = std::filesystem;

std::string Extension(const std::string& path) {
  std::string ext = fs::path(path).extension().string();
  std::transform(ext.begin(), ext.end(), ext.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return ext;
}

}  // namespace

ClipOutputOptions ClipOutputOptionsOf(const RiseSpec& spec) {
  ClipOutputOptions options;
  // The loader only lets valid preset names through.
  options.naming = ParseNamingPreset(spec.output.names).value_or(NamingPreset::kDefault);
  options.rootMotion = spec.output.rootMotion ? RootMotion::kBake : RootMotion::kInPlace;
  return options;
}

std::string CheckOutputFolder(const std::string& path) {
  std::error_code ec;
  if (path.empty()) return "empty output path";
  if (fs::is_directory(path, ec)) return path + ": is a folder, allowed: a file path";
  const fs::path folder = fs::path(path).parent_path();
  if (!folder.empty() && !fs::is_directory(folder, ec)) {
    return path + ": folder '" + folder.string() + "' does not exist (rise-gen does not create folders)";
  }
  return CheckWritable(path);
}

std::string CheckClipOutputPath(const std::string& path) {
  const std::string ext = Extension(path);
  if (ext != ".glb" && ext != ".gltf" && ext != ".bvh") {
    return path + ": found the extension '" + ext + "', allowed: .glb, .gltf, .bvh";
  }
  return CheckOutputFolder(path);
}

std::vector<std::string> ClipOutputFiles(const std::vector<std::string>& paths) {
  std::vector<std::string> files;
  const auto add = [&files](const std::string& file) {
    if (std::find(files.begin(), files.end(), file) == files.end()) files.push_back(file);
  };
  for (const std::string& path : paths) {
    add(path);
    if (Extension(path) == ".gltf") add(fs::path(path).replace_extension(".bin").string());
    add(SidecarPath(path));
  }
  return files;
}

std::string CheckOutputsSpareInput(const std::vector<std::string>& outputs, const std::string& input) {
  std::error_code ec;
  const fs::path in = fs::weakly_canonical(input, ec);
  if (ec) return "";
  for (const std::string& output : outputs) {
    for (const std::string& file : ClipOutputFiles({output})) {
      std::error_code fileEc;
      if (fs::weakly_canonical(file, fileEc) != in || fileEc) continue;
      const std::string what = file == output ? "" : " (its file " + file + ")";
      return output + what + ": would overwrite the input file, allowed: outputs that leave " + input + " alone";
    }
  }
  return "";
}

std::string WriteClipFiles(const Clip& clip, const std::vector<std::string>& paths, const ClipOutputOptions& options) {
  const Clip out = ApplyRootMotion(clip, options.rootMotion);
  std::vector<std::string> sidecars, written;
  std::string error;
  for (const std::string& path : paths) {
    // One sidecar per stem: clip.glb and clip.bvh share clip.json.
    const bool sidecar = std::find(sidecars.begin(), sidecars.end(), SidecarPath(path)) == sidecars.end();
    if (Extension(path) == ".bvh") {
      error = WriteBvh(out, path, BvhOptions{options.bvh, options.naming, sidecar});
    } else {
      error = WriteGltf(out, path, GltfOptions{options.naming, sidecar});
    }
    if (!error.empty()) break;
    sidecars.push_back(SidecarPath(path));
    written.push_back(path);
  }
  if (!error.empty()) RemoveOutputFiles(ClipOutputFiles(written));
  return error;
}

void RemoveOutputFiles(const std::vector<std::string>& files) {
  std::error_code ec;
  for (const std::string& file : files) {
    // Only files: a folder that happens to carry an output's name is the user's, not ours.
    if (fs::is_regular_file(file, ec)) fs::remove(file, ec);
  }
}

PreviewOptions PreviewOptionsFor(const Clip& clip, const std::string& title) {
  PreviewOptions options;
  const QualityOptions ground = QualityOptionsFor(clip);
  options.groundPoint = ground.groundPoint;
  options.groundNormal = ground.groundNormal;
  options.title = title;
  return options;
}

}  // namespace rise
