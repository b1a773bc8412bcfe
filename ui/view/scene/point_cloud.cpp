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

void build_lap_cloud(const HistoryLap& lap, const ColourParams& colours, const InterferenceSettings& filter,
                     LapCloud& out, const MotionBackground* motion) {
  out.serial = lap.serial;
  out.cloud.clear();
  out.stats = {};
  const bool by_motion = colours.mode == ColourMode::Motion && motion != nullptr;
  const InterferenceFilter interference = filter.filter();
  FadeRun kind;
  for (const LapPoint& p : lap.points) {
    if (p.range_mm <= 0.0f) {
      ++out.stats.newest_no_return;
      continue;
    }
    const bool removed = interference.removes(p.flag);
    if (removed) {
      if (p.flag == PointFlag::Specular)
        ++out.stats.newest_specular_removed;
      else
        ++out.stats.newest_ambient_removed;
      if (!filter.show_ghosts) continue;
    }
    const Vec2 w = polar_to_world(p.angle_deg, p.range_mm);
    kind.ghost = removed;
    extend_runs(out.cloud.runs, static_cast<std::uint32_t>(out.cloud.vertices.size()), kind);
    if (removed) {
      out.cloud.vertices.push_back({w.x, w.y, ghost_colour(p.flag)});
      ++out.stats.ghosts;
    } else {
      out.cloud.vertices.push_back({w.x, w.y, point_colour(colours, p, 0.0f, by_motion && motion->is_moving(p))});
      ++out.stats.drawn;
    }
  }
}

FadeRun lap_place(const LapHistory& history, const ColourParams& colours, std::size_t age) {
  const std::size_t laps = history.size();
  FadeRun place;
  place.age = static_cast<std::uint32_t>(age);
  place.laps = static_cast<std::uint32_t>(laps);
  place.leaving = colours.fade_old_laps && laps > 1 && laps == history.depth() && age == laps - 1;
  return place;
}

void append_lap(const LapCloud& lap, const FadeRun& place, FadingCloud& cloud, PointCloudStats& stats) {
  const bool newest = place.age == 0;
  const std::size_t first_run = cloud.runs.size();
  for (const FadeRun& run : lap.cloud.runs) {
    if (run.ghost && !newest) continue;
    const auto begin = static_cast<std::uint32_t>(cloud.vertices.size());
    cloud.vertices.insert(cloud.vertices.end(), lap.cloud.vertices.begin() + run.begin,
                          lap.cloud.vertices.begin() + run.end);
    const auto end = static_cast<std::uint32_t>(cloud.vertices.size());
    // Two runs of the lap that a left-out ghost had parted are one again.
    if (cloud.runs.size() > first_run && cloud.runs.back().ghost == run.ghost) {
      cloud.runs.back().end = end;
      continue;
    }
    FadeRun kind = place;
    kind.begin = begin;
    kind.end = end;
    kind.ghost = run.ghost;
    kind.strength = run.strength;
    cloud.runs.push_back(kind);
  }
  if (newest)
    stats.add(lap.stats);
  else
    stats.drawn += lap.stats.drawn;
}

PointCloudStats build_point_cloud(const LapHistory& history, const ColourParams& colours,
                                  const InterferenceSettings& filter, FadingCloud& cloud,
                                  const MotionBackground* motion) {
  cloud.clear();
  PointCloudStats stats;
  LapCloud built;
  // Oldest first so the newest lap is drawn last, on top.
  for (std::size_t age = history.size(); age-- > 0;) {
    build_lap_cloud(history.at_age(age), colours, filter, built, motion);
    append_lap(built, lap_place(history, colours, age), cloud, stats);
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
