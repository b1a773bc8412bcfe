#pragma once
// One lidar's cloud as the view draws it at `phase`: built, then faded (point_cloud.h).
#include <vector>

#include "ui/view/scene/point_cloud.h"

namespace ydscope::ui {

struct FadedCloud {
  PointCloudStats stats;
  std::vector<PointVertex> vertices;
};

inline FadedCloud faded_cloud(const LapHistory& history, const ColourParams& colours,
                              const InterferenceSettings& filter = {}, const MotionBackground* motion = nullptr,
                              float phase = 0.0f) {
  FadingCloud cloud;
  FadedCloud faded;
  faded.stats = build_point_cloud(history, colours, filter, cloud, motion);
  fade_cloud(cloud, colours, phase);
  faded.vertices = std::move(cloud.vertices);
  return faded;
}

}  // namespace ydscope::ui
