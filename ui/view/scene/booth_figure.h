#pragma once
// The booth view's large live figure, chosen in settings (booth_figure): how many visitors the
// lidar sees now, or how near the nearest one stands. A visitor is a run of returns closer than
// the learned room (MotionBackground), neighbours in angle, enough of them to be a body and not
// noise. Counted on the newest lap, a few hundred points, once a frame in the booth view only.
#include <optional>
#include <string>
#include <string_view>

#include "core/protocol/lap.h"
#include "ui/view/scene/motion_background.h"

namespace ydscope::ui {

enum class BoothFigureKind { None, Visitors, Nearest };

// "none", "visitors", "nearest" (settings.ini's words), and back; nullopt for another word.
std::string_view booth_figure_word(BoothFigureKind kind);
std::optional<BoothFigureKind> booth_figure_from_word(std::string_view word);

struct VisitorCount {
  int visitors = 0;
  std::optional<float> nearest_mm;  // the nearest visitor's nearest return
};

// Returns closer than the room that lie within kVisitorGapDeg of each other are one visitor, if
// there are at least kVisitorPoints of them.
inline constexpr float kVisitorGapDeg = 2.0f;
inline constexpr int kVisitorPoints = 3;
VisitorCount count_visitors(const Lap& lap, const MotionBackground& room);

// The figure's words: "3 visitors", "1 visitor", "nearest 1.8 m"; empty for None. Nearest with
// no one in sight says "no one near".
std::string booth_figure_text(BoothFigureKind kind, const VisitorCount& count);

}  // namespace ydscope::ui
