#pragma once
// Where the range rings and angle spokes go and where their labels fit: ring spacing follows the
// zoom on a 1-2-5 ladder, labels stay inside the viewport.
#include <array>
#include <cstddef>
#include <span>
#include <string>
#include <vector>

#include "core/protocol/lap.h"
#include "ui/view/geometry/view_transform.h"

namespace ydscope::ui {

// Smallest 1-2-5 x 10^k step in mm whose rings are at least `min_px` apart at this zoom.
float nice_ring_step_mm(float px_per_mm, float min_px);

// "250 mm", "50 cm", "1 m", "2.5 m", "12 m".
std::string format_distance(float mm);

struct GridLabel {
  Vec2 screen;  // anchor in pixels
  std::string text;
};

struct GridLayout {
  float ring_step_mm = 1000.0f;
  std::vector<float> ring_radii_mm;    // every ring to draw, inside the visible radius
  std::vector<GridLabel> ring_labels;  // only where the text fits inside the (inset) viewport
  std::vector<float> spoke_angles_deg;
  std::vector<GridLabel> spoke_labels;  // where each spoke leaves the (inset) viewport
};

// The least spacing of rings for a view of this size: a handful of rings across the shorter side
// whatever the screen (a 1080p full-screen view once drew fourteen), never closer than 70 px.
float ring_spacing_px(Vec2 viewport_size);

// `label_angle_deg` is the device angle along which ring labels are written (225: up and to the
// right, as polar_to_world draws the unit's angles). No label goes into the
// bottom `status_band_px` of the view, where the status line is written.
GridLayout layout_grid(const ViewTransform& view, float min_ring_px = 70.0f, float spoke_step_deg = 30.0f,
                       float label_angle_deg = 225.0f, float edge_margin_px = 18.0f, float status_band_px = 0.0f);

// Room a label needs around its anchor: ring labels are written right of and above theirs, spoke
// labels centred on theirs (the overlay draws each on a small dark plate this size).
inline constexpr float kRingLabelWidthPx = 56.0f;
inline constexpr float kLabelHeightPx = 22.0f;

// A range that holds most of the scan (the `fraction` quantile of non-zero ranges), for auto-range:
// the far outliers of a window or a mirror do not shrink the view. 0 when there is no return.
float robust_max_range_mm(std::span<const LapPoint> points, float fraction = 0.98f);

}  // namespace ydscope::ui
