// Every character the app writes is in its fonts' glyph ranges (ui/view/window/glyph_ranges.h), so none
// is drawn as "?": the string literals of ui/, app/gui/ and core/ (whose sentences the app shows)
// are read, raw UTF-8 and \xHH escapes alike, and each non-ASCII character is looked up.
#include "ui/view/window/glyph_ranges.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "test_data.h"

namespace ydscope::ui {
namespace {

// The bytes of the string literals on one line (comments skipped), escapes decoded.
std::string literal_bytes(const std::string& line) {
  std::string bytes;
  bool in_string = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (!in_string) {
      if (c == '/' && i + 1 < line.size() && line[i + 1] == '/') break;
      if (c == '\'' && i + 2 < line.size()) {  // a char literal such as '"' is not a string
        i += line[i + 1] == '\\' ? 3 : 2;
        continue;
      }
      if (c == '"') in_string = true;
      continue;
    }
    if (c == '"') {
      in_string = false;
    } else if (c == '\\' && i + 1 < line.size()) {
      if (line[i + 1] == 'x' && i + 3 < line.size()) {
        bytes += static_cast<char>(std::stoi(line.substr(i + 2, 2), nullptr, 16));
        i += 3;
      } else {
        ++i;  // \n, \", \\: ASCII
      }
    } else {
      bytes += c;
    }
  }
  return bytes;
}

// Code points of the non-ASCII UTF-8 sequences in `bytes`.
std::vector<char32_t> non_ascii(const std::string& bytes) {
  std::vector<char32_t> out;
  for (std::size_t i = 0; i < bytes.size();) {
    const auto b = static_cast<unsigned char>(bytes[i]);
    int extra = b >= 0xF0 ? 3 : b >= 0xE0 ? 2 : b >= 0xC0 ? 1 : 0;
    char32_t c = extra == 3 ? b & 0x07 : extra == 2 ? b & 0x0F : extra == 1 ? b & 0x1F : b;
    for (int k = 1; k <= extra && i + k < bytes.size(); ++k)
      c = (c << 6) | (static_cast<unsigned char>(bytes[i + k]) & 0x3F);
    if (b >= 0x80) out.push_back(c);
    i += 1 + extra;
  }
  return out;
}

TEST(GlyphCoverage, TheRangesHoldWhatTheUiUses) {
  EXPECT_TRUE(has_glyph(U'\u00B0')) << "degree sign";
  EXPECT_TRUE(has_glyph(U'\u2022')) << "bullet";
  EXPECT_TRUE(has_glyph(U'\u2026')) << "ellipsis";
  EXPECT_TRUE(has_glyph(U'\u2014')) << "em dash";
  EXPECT_FALSE(has_glyph(U'\u2713')) << "a check mark is not in the fonts' ranges";
}

TEST(GlyphCoverage, EveryCharacterInTheSourcesStringsHasAGlyph) {
  const std::filesystem::path root = test::assets_dir().parent_path();
  int literals_with_non_ascii = 0;
  for (const char* folder : {"ui", "app/gui", "core"}) {
    for (const auto& entry : std::filesystem::recursive_directory_iterator(root / folder)) {
      const auto ext = entry.path().extension();
      if (ext != ".cpp" && ext != ".h") continue;
      std::ifstream in(entry.path());
      int number = 0;
      for (std::string line; std::getline(in, line);) {
        ++number;
        const auto points = non_ascii(literal_bytes(line));
        literals_with_non_ascii += !points.empty();
        for (const char32_t c : points)
          EXPECT_TRUE(has_glyph(c)) << entry.path().string() << ":" << number << ": U+" << std::hex
                                    << static_cast<unsigned>(c) << " has no glyph in the fonts";
      }
    }
  }
  EXPECT_GT(literals_with_non_ascii, 5) << "the scan found none of the degree signs and bullets the UI writes";
}

}  // namespace
}  // namespace ydscope::ui
