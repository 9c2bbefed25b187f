// SPDX-License-Identifier: MIT
// libFuzzer target: input file text -> validated RiseSpec, the loader `rise-gen generate` uses.
#include <cstddef>
#include <cstdint>
#include <string>

#include "core/input_json.h"

// Any text must give a spec or an InputError, never a crash, a hang or undefined behaviour. A
// spec that loads must survive the resolved-input round trip unchanged (clip metadata and the
// batch's resume hash rely on it) and must build a body.
extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  const rise::Result<rise::RiseSpec> spec = rise::ParseRiseSpec(text, "fuzz.json");
  if (!spec) {
    if (spec.Error().message.empty()) __builtin_trap();
    return 0;
  }
  const std::string resolved = rise::RiseSpecToJson(spec.Value()).dump();
  const rise::Result<rise::RiseSpec> again = rise::ParseRiseSpec(resolved, "resolved.json");
  if (!again || rise::RiseSpecToJson(again.Value()).dump() != resolved) __builtin_trap();
  (void)rise::MakeBipedDef(spec.Value().character);
  return 0;
}
