#include "ui/view/scene/booth_figure.h"

#include <algorithm>
#include <cstdio>

namespace ydscope::ui {

std::string_view booth_figure_word(BoothFigureKind kind) {
  switch (kind) {
    case BoothFigureKind::None: return "none";
    case BoothFigureKind::Visitors: return "visitors";
    case BoothFigureKind::Nearest: return "nearest";
  }
  return "none";
}

std::optional<BoothFigureKind> booth_figure_from_word(std::string_view word) {
  for (const BoothFigureKind kind : {BoothFigureKind::None, BoothFigureKind::Visitors, BoothFigureKind::Nearest})
    if (word == booth_figure_word(kind)) return kind;
  return std::nullopt;
}

VisitorCount count_visitors(const Lap& lap, const MotionBackground& room) {
  VisitorCount out;
  struct Run {
    int size = 0;
    float nearest_mm = 0.0f;
  };
  const auto count = [&out](const Run& r) {
    if (r.size < kVisitorPoints) return;
    ++out.visitors;
    out.nearest_mm = std::min(out.nearest_mm.value_or(r.nearest_mm), r.nearest_mm);
  };
  // Points arrive in angle order within a lap; a run ends at a gap wider than kVisitorGapDeg. The
  // first run is held back: someone standing across 0 degrees is the lap's first and last run.
  Run first, current;
  bool first_closed = false;
  float first_angle = -1.0f, last_angle = 0.0f;
  for (const LapPoint& p : lap.points) {
    if (!room.is_moving(p)) continue;
    if (first_angle < 0.0f) first_angle = p.angle_deg;
    if (current.size > 0 && p.angle_deg - last_angle > kVisitorGapDeg) {
      if (first_closed)
        count(current);
      else
        first = current, first_closed = true;
      current = {};
    }
    current.nearest_mm = current.size == 0 ? p.range_mm : std::min(current.nearest_mm, p.range_mm);
    ++current.size;
    last_angle = p.angle_deg;
  }
  if (!first_closed) {
    count(current);
    return out;
  }
  if (current.size > 0 && first_angle + 360.0f - last_angle <= kVisitorGapDeg)
    first = {first.size + current.size, std::min(first.nearest_mm, current.nearest_mm)};
  else
    count(current);
  count(first);
  return out;
}

std::string booth_figure_text(BoothFigureKind kind, const VisitorCount& count) {
  char text[48] = "";
  switch (kind) {
    case BoothFigureKind::None: break;
    case BoothFigureKind::Visitors:
      std::snprintf(text, sizeof text, count.visitors == 1 ? "%d visitor" : "%d visitors", count.visitors);
      break;
    case BoothFigureKind::Nearest:
      if (count.nearest_mm)
        std::snprintf(text, sizeof text, "nearest %.1f m", static_cast<double>(*count.nearest_mm) / 1000.0);
      else
        std::snprintf(text, sizeof text, "no one near");
      break;
  }
  return text;
}

}  // namespace ydscope::ui
