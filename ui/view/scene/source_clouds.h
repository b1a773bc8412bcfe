#pragma once
// The layers' cloud kept between frames. A layer is built again only when its laps, pose, colour
// or dimming changed, or the colours or the filter did: with four lidars a lap of any one had
// rebuilt all four clouds, about 32 times a second. And when only its laps changed, only its new
// lap is built: the others are kept as built (each layer had built its ten laps again at each of
// its laps), and the cloud is put together from them.
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
    std::vector<LapCloud> laps;  // its history's, oldest first
  };
  // `built`'s laps made its history's: those built before kept when `keep` says they still hold,
  // the rest built.
  void build_laps(const SourceLayer& layer, const ColourParams& colours, const InterferenceSettings& filter, bool keep,
                  std::vector<LapCloud>& laps);
  LapCloud take_spare();

  std::vector<Built> built_;
  std::vector<LapCloud> spare_;  // laps let go, their buffers kept for the next ones built
  std::vector<LapCloud> laps_;   // reused while building a layer's laps
  FadingCloud joined_;
  PointCloudStats stats_;
};

}  // namespace ydscope::ui
