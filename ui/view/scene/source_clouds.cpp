#include "ui/view/scene/source_clouds.h"

#include <cstdint>
#include <utility>

namespace ydscope::ui {

LapCloud SourceClouds::take_spare() {
  if (spare_.empty()) return {};
  LapCloud spare = std::move(spare_.back());
  spare_.pop_back();
  return spare;
}

void SourceClouds::build_laps(const SourceLayer& layer, const ColourParams& colours, const InterferenceSettings& filter,
                              bool keep, std::vector<LapCloud>& laps) {
  laps_.clear();
  std::size_t kept = 0;  // laps before it are kept or let go; both lists run oldest first
  if (layer.history)
    for (std::size_t age = layer.history->size(); age-- > 0;) {
      const HistoryLap& lap = layer.history->at_age(age);
      while (keep && kept < laps.size() && laps[kept].serial < lap.serial) spare_.push_back(std::move(laps[kept++]));
      if (keep && kept < laps.size() && laps[kept].serial == lap.serial) {
        laps_.push_back(std::move(laps[kept++]));
        continue;
      }
      laps_.push_back(take_spare());
      build_layer_lap(layer, lap, colours, filter, laps_.back());
    }
  for (; kept < laps.size(); ++kept) spare_.push_back(std::move(laps[kept]));
  laps.swap(laps_);
}

bool SourceClouds::update(std::span<const SourceLayer> layers, const ColourParams& colours,
                          const InterferenceSettings& filter, bool colours_changed) {
  bool changed = colours_changed || built_.size() != layers.size();
  if (built_.size() > layers.size())
    built_.erase(built_.begin() + static_cast<std::ptrdiff_t>(layers.size()), built_.end());
  for (std::size_t i = 0; i < layers.size(); ++i) {
    const SourceLayerKey key(layers[i]);
    if (i == built_.size()) {
      built_.push_back({key, {}});
    } else if (!colours_changed && built_[i].key == key) {
      continue;
    }
    // In motion colours every lap is coloured against the room as learned now, so all are built.
    const bool keep = !colours_changed && built_[i].key.look == key.look && colours.mode != ColourMode::Motion;
    built_[i].key = key;
    build_laps(layers[i], colours, filter, keep, built_[i].laps);
    changed = true;
  }
  if (!changed) return false;
  joined_.clear();
  stats_ = {};
  for (std::size_t i = 0; i < layers.size(); ++i) {
    const std::vector<LapCloud>& laps = built_[i].laps;
    for (std::size_t k = 0; k < laps.size(); ++k)
      append_lap(laps[k], lap_place(*layers[i].history, colours, laps.size() - 1 - k), joined_, stats_);
  }
  return true;
}

}  // namespace ydscope::ui
