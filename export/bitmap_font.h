// SPDX-License-Identifier: MIT
// A 5x7 pixel font built into the program, for labels on rendered images (the
// preview sheet) without a font file or library. Upper case, digits and common
// punctuation; lower case is drawn as upper case.
#pragma once

#include <array>
#include <cstdint>

namespace rise {

constexpr int kGlyphWidth = 5;
constexpr int kGlyphHeight = 7;

// The rows of `c`, top first; bit 4 is the leftmost pixel. A space is blank and
// a character the font lacks is drawn as '?'.
std::array<uint8_t, kGlyphHeight> GlyphRows(char c);

}  // namespace rise
