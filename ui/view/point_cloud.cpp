#include "ui/view/point_cloud.h"

namespace ydscope::ui {

PointCloudStats build_point_cloud(const LapHistory& history, const ColourParams& colours,
                                  const InterferenceSettings& filter, std::vector<PointVertex>& out,
                                  const MotionBackground* motion) {
  const bool by_motion = colours.mode == ColourMode::Motion && motion != nullptr;
  out.clear();
  PointCloudStats stats;
  const std::size_t laps = history.size();
  const InterferenceFilter interference = filter.filter();
  // Oldest first so the newest lap is drawn last, on top.
  for (std::size_t age = laps; age-- > 0;) {
    const float age_fraction = laps > 1 ? static_cast<float>(age) / static_cast<float>(laps - 1) : 0.0f;
    const bool newest = age == 0;
    for (const LapPoint& p : history.at_age(age).points) {
      if (p.range_mm <= 0.0f) {
        if (newest) ++stats.newest_no_return;
        continue;
      }
      const bool removed = interference.removes(p.flag);
      if (removed && newest) {
        if (p.flag == PointFlag::Specular) ++stats.newest_specular_removed;
        else ++stats.newest_ambient_removed;
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
      out.push_back({w.x, w.y, point_colour(colours, p, age_fraction, by_motion && motion->is_moving(p))});
      ++stats.drawn;
    }
  }
  return stats;
}

}  // namespace ydscope::ui
