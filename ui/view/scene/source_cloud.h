#pragma once
// Several lidars' laps as the one vertex array the point shader draws: each source's cloud built
// as a single lidar's is (point_cloud.h), then posed into the common frame and, in the by-source
// colour mode, painted its source's colour. A source whose data stopped is dimmed, not dropped,
// so its last picture stays in sight while the others draw normally.
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

// How much of its strength (each colour channel and its opacity) a dimmed source keeps.
inline constexpr float kDimmedSourceAlpha = 0.3f;

// Clears `out` and fills it, layers in order (later ones on top). `scratch` holds one source's
// cloud at a time (its capacity is reused). The statistics add up over the layers.
PointCloudStats build_source_clouds(std::span<const SourceLayer> layers, const ColourParams& colours,
                                    const InterferenceSettings& filter, std::vector<PointVertex>& out,
                                    std::vector<PointVertex>& scratch, float phase = 0.0f);

// The farthest a robust share of each source's newest returns reaches from the common origin
// (its distance from the origin plus its own robust range): what auto-range fits.
float robust_extent_mm(std::span<const SourceLayer> layers, float share);

}  // namespace ydscope::ui
