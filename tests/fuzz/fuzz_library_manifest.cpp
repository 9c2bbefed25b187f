// SPDX-License-Identifier: MIT
// libFuzzer target: batch manifest text -> resolved clip library, the loader `rise-gen batch` uses.
#include <cstddef>
#include <cstdint>
#include <set>
#include <string>

#include "core/library_manifest.h"

// Any text must give a library or an InputError, never a crash, a hang or undefined behaviour.
// A library that loads has unique clip names (they are file stems in one folder).
extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const rise::Result<rise::LibraryManifest> manifest = rise::ParseLibraryManifest(text, "fuzz.json");
  if (!manifest) {
    if (manifest.Error().message.empty()) __builtin_trap();
    return 0;
  }
  std::set<std::string> names;
  for (const rise::ManifestClip& clip : manifest.Value().clips) {
    if (clip.name.empty() || !names.insert(clip.name).second) __builtin_trap();
  }
  return 0;
}
