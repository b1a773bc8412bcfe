// Fuzzes the app's settings.ini parser with arbitrary text (a hand-edited or damaged file).
// Every value it returns must be inside the range the app uses, and what it writes back must read
// back the same: parse(format(s)) == s for any s the parser produced.
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "fuzz/fuzz_input.h"
#include "ui/view/settings/settings.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using namespace ydscope::ui;
  const std::string text(reinterpret_cast<const char*>(data), size);
  std::vector<std::string> notes;
  const ViewSettings parsed = parse_settings(text, &notes);
  for (const std::string& note : notes) FUZZ_CHECK(!note.empty(), "an empty note about a rejected value");
  FUZZ_CHECK(parsed.persistence_laps >= 1 && parsed.persistence_laps <= kMaxPersistenceLaps,
             "persistence_laps out of range");
  FUZZ_CHECK(std::isfinite(parsed.point_size_px) && parsed.point_size_px >= kMinPointSizePx &&
                 parsed.point_size_px <= kMaxPointSizePx,
             "point_size_px out of range");
  FUZZ_CHECK(std::isfinite(parsed.colours.near_mm) && parsed.colours.near_mm >= 0.0f &&
                 parsed.colours.near_mm <= kMaxColourRangeMm,
             "near_mm out of range");
  FUZZ_CHECK(std::isfinite(parsed.colours.far_mm) && parsed.colours.far_mm >= 1.0f &&
                 parsed.colours.far_mm <= kMaxColourRangeMm,
             "far_mm out of range");
  // The first write may round floats to the printed precision; from then on it must be stable.
  const ViewSettings once = parse_settings(format_settings(parsed));
  const ViewSettings twice = parse_settings(format_settings(once));
  FUZZ_CHECK(once == twice, "settings change each time they are saved and loaded");
  return 0;
}
