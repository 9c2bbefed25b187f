// SPDX-License-Identifier: MIT
// Small helpers of RiseSpec that do not involve JSON.
#include "core/rise_spec.h"

#include <algorithm>

namespace rise {

const char* PostureName(Posture posture) {
  switch (posture) {
    case Posture::kSupine:
      return "supine";
    case Posture::kProne:
      return "prone";
    case Posture::kSideLeft:
      return "side_left";
    case Posture::kSideRight:
      return "side_right";
    case Posture::kCustom:
      return "custom";
  }
  return "supine";
}

double StylePace(const StyleSpec& style) { return std::max(0.25, style.speed) * (1.0 - 0.4 * style.tiredness); }

double DefaultMaxDurationS(const RiseSpec& spec) {
  // A prone start stands in about 10-16 s; a roll first adds 5-10 s; a slow
  // style stretches every move by 1 / pace. The limit leaves room for a
  // failed try and a second one (a clip ends once its body stands still, so
  // the limit lengthens only clips that fail). Stress seeds 5001-5500 /
  // 5501-6000 / 9001-9500 (custom starts) stood 243 / 247 / 216 in 30 s,
  // 304 / 292 / 274 in 45 s and 333 / 320 / 310 in 60 s.
  const double base = spec.start.posture == Posture::kProne ? 35.0 : 60.0;
  const double pace = StylePace(spec.style);
  return std::min(120.0, base / std::min(1.0, pace));
}

BipedDef MakeBipedDef(const CharacterSpec& character) {
  return MakeBipedDef(static_cast<float>(character.heightM), static_cast<float>(character.massKg), character.segments);
}

}  // namespace rise
