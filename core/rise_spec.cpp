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
  // A prone start stands in about 10-16 s; a roll first adds 5-10 s (rolled
  // starts stood at 16-27 s, so most failed a 20 s limit); a slow style
  // stretches every move by 1 / pace.
  const double base = spec.start.posture == Posture::kProne ? 20.0 : 30.0;
  const double pace = StylePace(spec.style);
  return std::min(120.0, base / std::min(1.0, pace));
}

BipedDef MakeBipedDef(const CharacterSpec& character) {
  return MakeBipedDef(static_cast<float>(character.heightM), static_cast<float>(character.massKg), character.segments);
}

}  // namespace rise
