#pragma once
// The layers' cloud kept between frames. A layer is built again only when its laps, pose, colour
// or dimming changed, or the colours or the filter did: with four lidars a lap of any one had
// rebuilt all four clouds, about 32 times a second.
#include <span>
#include <vector>

#include "ui/view/scene/source_cloud.h"

namespace ydscope::ui {

class SourceClouds {
 public:
  // Brings the cloud up to date with `layers`, in order (later ones on top), not yet faded
  // (fade_cloud). `colours_changed`: the colours or the filter differ from the last update's, or
  // everything must be built again. True when the cloud changed.
  bool update(std::span<const SourceLayer> layers, const ColourParams& colours, const InterferenceSettings& filter,
              bool colours_changed);
  // Every layer's cloud, joined; its fade is the caller's to set.
  FadingCloud& cloud() { return joined_; }
  // Added up over the layers.
  const PointCloudStats& stats() const { return stats_; }

 private:
  struct Built {
    SourceLayerKey key;
    FadingCloud cloud;
    PointCloudStats stats;
  };
  std::vector<Built> built_;
  FadingCloud joined_;
  PointCloudStats stats_;
};

}  // namespace ydscope::ui
