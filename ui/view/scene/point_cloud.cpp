#include "ui/view/scene/point_cloud.h"

#include <algorithm>
#include <cstdint>

namespace ydscope::ui {
namespace {

// Adds vertex `index` to the run it continues, or starts one: a run is one lap, of one kind.
void extend_runs(std::vector<FadeRun>& runs, std::uint32_t index, const FadeRun& kind) {
  if (!runs.empty()) {
    FadeRun& last = runs.back();
    if (last.end == index && last.age == kind.age && last.ghost == kind.ghost) {
      ++last.end;
      return;
    }
  }
  FadeRun run = kind;
  run.begin = index;
  run.end = index + 1;
  runs.push_back(run);
}

}  // namespace

PointCloudStats build_point_cloud(const LapHistory& history, const ColourParams& colours,
                                  const InterferenceSettings& filter, FadingCloud& cloud,
                                  const MotionBackground* motion) {
  cloud.clear();
  const bool by_motion = colours.mode == ColourMode::Motion && motion != nullptr;
  PointCloudStats stats;
  const std::size_t laps = history.size();
  const InterferenceFilter interference = filter.filter();
  const bool full = colours.fade_old_laps && laps > 1 && laps == history.depth();
  // Oldest first so the newest lap is drawn last, on top.
  for (std::size_t age = laps; age-- > 0;) {
    const bool newest = age == 0;
    FadeRun kind;
    kind.age = static_cast<std::uint32_t>(age);
    kind.laps = static_cast<std::uint32_t>(laps);
    kind.leaving = full && age == laps - 1;
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
      // Ghosts only for the newest lap: older ghosts would just smear.
      if (removed && !(filter.show_ghosts && newest)) continue;
      const Vec2 w = polar_to_world(p.angle_deg, p.range_mm);
      kind.ghost = removed;
      extend_runs(cloud.runs, static_cast<std::uint32_t>(cloud.vertices.size()), kind);
      if (removed) {
        cloud.vertices.push_back({w.x, w.y, ghost_colour(p.flag)});
        ++stats.ghosts;
      } else {
        cloud.vertices.push_back({w.x, w.y, point_colour(colours, p, 0.0f, by_motion && motion->is_moving(p))});
        ++stats.drawn;
      }
    }
  }
  return stats;
}

void fade_cloud(FadingCloud& cloud, const ColourParams& colours, float phase) {
  phase = std::clamp(phase, 0.0f, 1.0f);
  const bool hue_by_age = colours.mode == ColourMode::LapAge;
  for (const FadeRun& run : cloud.runs) {
    if (run.ghost) continue;  // faint already, and never older than the newest lap
    const float age =
        run.laps > 1 ? std::min((static_cast<float>(run.age) + phase) / static_cast<float>(run.laps - 1), 1.0f) : 0.0f;
    Rgba8 look = lap_look(colours, age);
    look.a = scale_byte(scale_byte(look.a, run.leaving ? 1.0f - phase : 1.0f), run.strength);
    if (hue_by_age) {
      for (std::uint8_t* channel : {&look.r, &look.g, &look.b}) *channel = scale_byte(*channel, run.strength);
      for (std::uint32_t i = run.begin; i < run.end; ++i) cloud.vertices[i].colour = look;
    } else {
      for (std::uint32_t i = run.begin; i < run.end; ++i) cloud.vertices[i].colour.a = look.a;
    }
  }
}

}  // namespace ydscope::ui
