#pragma once
// The Unicode ranges the app's fonts are built with: every character the UI writes must be in
// them, or ImGui draws "?" in its place (tests/ui/glyph_coverage_test.cpp checks the sources).
#include <cstdint>

namespace ydscope::ui {

// Pairs of first and last code point, ending with 0 (ImGui's glyph-range format). Latin-1 holds
// the degree and plus-minus signs; dashes, bullet and ellipsis come from general punctuation,
// then the arrows.
inline constexpr std::uint16_t kGlyphRanges[] = {0x0020, 0x00FF, 0x2013, 0x2026, 0x2190, 0x2193, 0};

constexpr bool has_glyph(char32_t c) {
  for (int i = 0; kGlyphRanges[i] != 0; i += 2)
    if (c >= kGlyphRanges[i] && c <= kGlyphRanges[i + 1]) return true;
  return false;
}

}  // namespace ydscope::ui
