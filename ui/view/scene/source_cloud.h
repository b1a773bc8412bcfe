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
// built again: its laps (the history's generation), pose, colour and dimming.
struct SourceLayerKey {
  const LapHistory* history = nullptr;
  std::uint64_t generation = 0;
  Pose pose;
  Rgba8 colour;
  bool dim = false;
  const MotionBackground* motion = nullptr;
  explicit SourceLayerKey(const SourceLayer& layer)
      : history(layer.history),
        generation(layer.history ? layer.history->generation() : 0),
        pose(layer.pose),
        colour(layer.colour),
        dim(layer.dim),
        motion(layer.motion) {}
  friend bool operator==(const SourceLayerKey&, const SourceLayerKey&) = default;
  // The same but for the laps: a lap built for one is the lap built for the other.
  bool same_but_laps(const SourceLayerKey& other) const {
    return history == other.history && pose == other.pose && colour == other.colour && dim == other.dim &&
           motion == other.motion;
  }
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
