// SPDX-License-Identifier: MIT
// Small helpers of RiseSpec that do not involve JSON.
#include "core/rise_spec.h"

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

BipedDef MakeBipedDef(const CharacterSpec& character) {
  return MakeBipedDef(static_cast<float>(character.heightM), static_cast<float>(character.massKg), character.segments);
}

}  // namespace rise
