#pragma once
// Several lidars' laps as the one vertex array the point shader draws: each source's cloud built
// as a single lidar's is (point_cloud.h), then posed into the common frame and, in the by-source
// colour mode, painted its source's colour. A source whose data stopped is dimmed, not dropped,
// so its last picture stays in sight while the others draw normally.
#include <cstdint>
#include <span>
#include <vector>

#include "core/frame/pose.h"
#include "ui/view/scene/point_cloud.h"

namespace ydscope::ui {

struct SourceLayer {
  const LapHistory* history = nullptr;
  Pose pose;
  Rgba8 colour;                              // used in ColourMode::Source
  bool dim = false;                          // its data stopped
  const MotionBackground* motion = nullptr;  // its own room, for ColourMode::Motion
};

// What a layer's cloud is built from besides the colours and the filter, to tell when it must be
// built again: its laps (the history's generation) and how each lap of it is built.
struct SourceLayerKey {
  // How a lap of the layer is built: its history's, posed, coloured and dimmed so. A lap built
  // under one look is the lap built under an equal one.
  struct Look {
    const LapHistory* history = nullptr;
    Pose pose;
    Rgba8 colour;
    bool dim = false;
    const MotionBackground* motion = nullptr;
    friend bool operator==(const Look&, const Look&) = default;
  };
  Look look;
  std::uint64_t generation = 0;
  explicit SourceLayerKey(const SourceLayer& layer)
      : look{layer.history, layer.pose, layer.colour, layer.dim, layer.motion},
        generation(layer.history ? layer.history->generation() : 0) {}
  friend bool operator==(const SourceLayerKey&, const SourceLayerKey&) = default;
};

// How much of its strength (each colour channel and its opacity) a dimmed source keeps.
inline constexpr float kDimmedSourceAlpha = 0.3f;

// Builds one of the layer's laps (build_lap_cloud) into `out`, posed and dimmed.
void build_layer_lap(const SourceLayer& layer, const HistoryLap& lap, const ColourParams& colours,
                     const InterferenceSettings& filter, LapCloud& out);

// The farthest a robust share of each source's newest returns reaches from the common origin
// (its distance from the origin plus its own robust range): what auto-range fits.
float robust_extent_mm(std::span<const SourceLayer> layers, float share);

}  // namespace ydscope::ui
