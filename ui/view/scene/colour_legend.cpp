#include "ui/view/scene/colour_legend.h"

#include <algorithm>
#include <cmath>

#include "ui/view/geometry/grid_layout.h"

namespace ydscope::ui {
namespace {

constexpr int kBarSamples = 32;

// Ticks on the 1-2-5 ladder, three to six of them across near..far.
std::vector<LegendTick> range_ticks(float near_mm, float far_mm) {
  const float span = std::max(far_mm - near_mm, 1.0f);
  const float step = nice_ring_step_mm(1.0f, span / 5.0f);  // at 1 px/mm "px" are mm
  std::vector<LegendTick> ticks;
  for (float mm = std::ceil(near_mm / step) * step; mm <= far_mm + 0.5f; mm += step)
    ticks.push_back({(mm - near_mm) / span, mm <= 0.0f ? "0 m" : format_distance(mm)});
  return ticks;
}

}  // namespace

ColourLegend describe_legend(const ColourParams& colours, int persistence_laps) {
  ColourLegend legend;
  ColourParams solid = colours;
  solid.fade_old_laps = false;  // the legend shows each colour at full strength
  switch (colours.mode) {
    case ColourMode::Range:
      legend.title = "range";
      for (int i = 0; i < kBarSamples; ++i)
        legend.bar.push_back(sample_palette(colours.palette, static_cast<float>(i) / (kBarSamples - 1)));
      legend.ticks = range_ticks(colours.near_mm, colours.far_mm);
      break;
    case ColourMode::LapAge: {
      legend.title = "lap age";
      for (int i = 0; i < kBarSamples; ++i)
        legend.bar.push_back(point_colour(solid, {}, static_cast<float>(i) / (kBarSamples - 1)));
      const int oldest = std::max(persistence_laps - 1, 0);
      legend.ticks = {{0.0f, "newest"}, {1.0f, oldest == 1 ? "1 lap ago" : std::to_string(oldest) + " laps ago"}};
      break;
    }
    case ColourMode::Motion:
      legend.title = "motion";
      legend.swatches = {{motion_colour(true), "moving (closer than the room)"}, {motion_colour(false), "the room"}};
      break;
    case ColourMode::Source:
      legend.title = "source";  // the app adds a swatch per source: only it knows them
      break;
    case ColourMode::Flag:
      legend.title = "interference flag";
      legend.swatches = {{flag_colour(PointFlag::None), "no flag"},
                         {flag_colour(PointFlag::Specular), "specular (2)"},
                         {flag_colour(PointFlag::AmbientLight), "ambient light (3)"}};
      break;
  }
  return legend;
}

float booth_text_px(float height) { return std::clamp(height * 0.04f, 24.0f, 96.0f); }

}  // namespace ydscope::ui
