#include "ui/view/scene/source_clouds.h"

#include <cstdint>

namespace ydscope::ui {

bool SourceClouds::update(std::span<const SourceLayer> layers, const ColourParams& colours,
                          const InterferenceSettings& filter, bool colours_changed) {
  bool changed = colours_changed || built_.size() != layers.size();
  if (built_.size() > layers.size())
    built_.erase(built_.begin() + static_cast<std::ptrdiff_t>(layers.size()), built_.end());
  for (std::size_t i = 0; i < layers.size(); ++i) {
    const SourceLayerKey key(layers[i]);
    if (i == built_.size()) {
      built_.push_back({key, {}, {}});
    } else if (!colours_changed && built_[i].key == key) {
      continue;
    }
    built_[i].key = key;
    built_[i].stats = build_layer_cloud(layers[i], colours, filter, built_[i].cloud);
    changed = true;
  }
  if (!changed) return false;
  joined_.clear();
  stats_ = {};
  for (const Built& layer : built_) {
    // The layer's runs move to where its vertices land in the joined cloud.
    const auto offset = static_cast<std::uint32_t>(joined_.vertices.size());
    joined_.vertices.insert(joined_.vertices.end(), layer.cloud.vertices.begin(), layer.cloud.vertices.end());
    for (FadeRun run : layer.cloud.runs) {
      run.begin += offset;
      run.end += offset;
      joined_.runs.push_back(run);
    }
    stats_.add(layer.stats);
  }
  return true;
}

}  // namespace ydscope::ui
