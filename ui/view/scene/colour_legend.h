#pragma once
// What the booth view's colour legend says for the colour mode in use: a bar with range ticks in
// metres, the interference flags by name, or newest to oldest lap. Plain data, drawn by
// ui/panels/booth_overlay.cpp; the colours are the cloud's own (colour_map.h).
#include <string>
#include <vector>

#include "ui/view/scene/colour_map.h"

namespace ydscope::ui {

struct LegendTick {
  float at = 0.0f;  // along the bar, 0 (start) to 1 (end)
  std::string text;
};

struct LegendSwatch {
  Rgba8 colour;
  std::string text;
};

struct ColourLegend {
  std::string title;                   // "range", "interference flag", "lap age"
  std::vector<Rgba8> bar;              // the bar's colours from start to end; empty for swatches
  std::vector<LegendTick> ticks;       // under the bar
  std::vector<LegendSwatch> swatches;  // flag mode
};

// `colours` as the cloud uses them (near/far already following auto-range); `persistence_laps` for
// the lap-age bar's far end.
ColourLegend describe_legend(const ColourParams& colours, int persistence_laps);

// The booth view's type size for a screen `height` px tall: legible across a stand.
float booth_text_px(float height);

}  // namespace ydscope::ui
