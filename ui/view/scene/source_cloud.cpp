#include "ui/view/scene/source_cloud.h"

#include <algorithm>
#include <cmath>

#include "ui/view/geometry/grid_layout.h"
#include "ui/view/geometry/view_frame.h"

namespace ydscope::ui {

void build_layer_lap(const SourceLayer& layer, const HistoryLap& lap, const ColourParams& colours,
                     const InterferenceSettings& filter, LapCloud& out) {
  build_lap_cloud(lap, colours, filter, out, layer.motion);
  const bool by_source = colours.mode == ColourMode::Source;
  // Darkened as well as made transparent: alpha alone let a dead lidar's overlapping laps
  // add back up to nearly full brightness (255 fell only to 221). The fade dims the alpha.
  const float strength = layer.dim ? kDimmedSourceAlpha : 1.0f;
  const auto dimmed = [strength](std::uint8_t channel) { return scale_byte(channel, strength); };
  const PosedFrame frame(layer.pose);
  for (FadeRun& run : out.cloud.runs) {
    run.strength = strength;
    for (std::uint32_t i = run.begin; i < run.end; ++i) {
      PointVertex& v = out.cloud.vertices[i];
      const Vec2 posed = posed_in_view(frame, {v.x, v.y});
      v.x = posed.x;
      v.y = posed.y;
      // The lap's fade stays in the alpha; the hue says whose point it is.
      if (by_source) v.colour = {layer.colour.r, layer.colour.g, layer.colour.b, v.colour.a};
      v.colour = {dimmed(v.colour.r), dimmed(v.colour.g), dimmed(v.colour.b),
                  run.ghost ? dimmed(v.colour.a) : v.colour.a};  // a ghost does not fade
    }
  }
}

float robust_extent_mm(std::span<const SourceLayer> layers, float share) {
  float extent = 0.0f;
  for (const SourceLayer& layer : layers) {
    if (!layer.history || layer.history->empty()) continue;
    const double from_origin = std::hypot(layer.pose.x_m, layer.pose.y_m) * 1000.0;
    extent =
        std::max(extent, static_cast<float>(from_origin) + robust_max_range_mm(layer.history->newest().points, share));
  }
  return extent;
}

}  // namespace ydscope::ui
