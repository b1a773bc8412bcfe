#pragma once
// The dropout ring on the polar view: a band round the selected lidar, tinted per degree by the
// share of its samples that came back with no return over the last seconds, and each blocked
// sector outlined in red with its sentence ("blocked 40°–75° for 12 s"). Drawn with ImGui's draw
// list, a few hundred quads per frame at most, never one per scan point.
#include <array>
#include <vector>

#include "core/analysis/dropout_ring.h"
#include "core/frame/pose.h"
#include "ui/view/geometry/view_transform.h"

struct ImDrawList;

namespace ydscope::ui {

struct DropoutRingShape {
  Pose pose;                                          // where the lidar sits in the view (a lone lidar: at the origin)
  std::array<float, kDropoutBins> no_return_share{};  // negative: no sample in that degree
  std::vector<BlockedSector> blocked;
};

// The band's radii in pixels, round the lidar's mark: fixed on screen, like the mark itself.
inline constexpr float kDropoutRingInnerPx = 30.0f;
inline constexpr float kDropoutRingOuterPx = 42.0f;
inline constexpr float kDropoutRimPx = 45.0f;  // a blocked sector's red rim, 5 px wide, just outside
// Degrees emptier than this are tinted; below it the band stays clear, so a healthy lidar shows
// nothing.
inline constexpr float kDropoutTintFrom = 0.25f;

void draw_dropout_ring(ImDrawList* draw, const ViewTransform& view, const DropoutRingShape& ring);

}  // namespace ydscope::ui
