#pragma once
// Which way a unit's own angles run on screen: its 0 degrees as a short tick from the lidar's dot
// and its sweep as an arrow along its first degrees, both turned and mirrored with its pose, so an
// upside-down unit's arrow runs the other way. Screen pixels, from the view's transform; plain math,
// tested without a display (the overlay draws them).
#include <vector>

#include "core/frame/pose.h"
#include "ui/view/geometry/view_transform.h"

namespace ydscope::ui {

struct UnitMarks {
  Vec2 centre;                           // the lidar's dot
  Vec2 zero_from, zero_to;               // the tick along the unit's 0 degrees
  Vec2 zero_label;                       // where "0°" is written
  std::vector<Vec2> sweep;               // the arrow's shaft, in the order the unit sweeps
  Vec2 head_tip, head_left, head_right;  // its arrowhead at the end of the shaft
};

// `pose`: where the view draws the lidar (the identity for a lone lidar drawn round itself).
UnitMarks unit_marks(const ViewTransform& view, const Pose& pose);

}  // namespace ydscope::ui
