#include "ui/view/scene/point_cloud.h"

#include <algorithm>
#include <cstdint>

namespace ydscope::ui {

PointCloudStats build_point_cloud(const LapHistory& history, const ColourParams& colours,
                                  const InterferenceSettings& filter, std::vector<PointVertex>& out,
                                  const MotionBackground* motion, float phase) {
  const bool by_motion = colours.mode == ColourMode::Motion && motion != nullptr;
  out.clear();
  PointCloudStats stats;
  const std::size_t laps = history.size();
  const InterferenceFilter interference = filter.filter();
  phase = std::clamp(phase, 0.0f, 1.0f);
  const bool oldest_leaves = colours.fade_old_laps && laps > 1 && laps == history.depth();
  // Oldest first so the newest lap is drawn last, on top.
  for (std::size_t age = laps; age-- > 0;) {
    const float age_fraction =
        laps > 1 ? std::min((static_cast<float>(age) + phase) / static_cast<float>(laps - 1), 1.0f) : 0.0f;
    const float leaving = oldest_leaves && age == laps - 1 ? 1.0f - phase : 1.0f;
    const bool newest = age == 0;
    for (const LapPoint& p : history.at_age(age).points) {
      if (p.range_mm <= 0.0f) {
        if (newest) ++stats.newest_no_return;
        continue;
      }
      const bool removed = interference.removes(p.flag);
      if (removed && newest) {
        if (p.flag == PointFlag::Specular)
          ++stats.newest_specular_removed;
        else
          ++stats.newest_ambient_removed;
      }
      const Vec2 w = polar_to_world(p.angle_deg, p.range_mm);
      if (removed) {
        // Ghosts only for the newest lap: older ghosts would just smear.
        if (filter.show_ghosts && newest) {
          out.push_back({w.x, w.y, ghost_colour(p.flag)});
          ++stats.ghosts;
        }
        continue;
      }
      Rgba8 colour = point_colour(colours, p, age_fraction, by_motion && motion->is_moving(p));
      colour.a = static_cast<std::uint8_t>(static_cast<float>(colour.a) * leaving + 0.5f);
      out.push_back({w.x, w.y, colour});
      ++stats.drawn;
    }
  }
  return stats;
}

}  // namespace ydscope::ui
