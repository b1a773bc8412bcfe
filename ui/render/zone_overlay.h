#pragma once
// The zones on the polar view: each outlined in its state's colour (teal while its rule is quiet,
// red and filled while it is raised) with its name. A sector zone is an annulus round its lidar
// (out to the view's edge without a band); a polygon lies in the robot's frame, which is the
// view's common frame.
#include <vector>

#include "core/analysis/zone_watch.h"
#include "core/frame/pose.h"
#include "ui/view/geometry/view_transform.h"

struct ImDrawList;

namespace ydscope::ui {

struct ZoneShapes {
  Pose pose;  // the lidar whose angles the sector zones are in (a lone lidar: at the origin)
  std::vector<Zone> zones;
  std::vector<ZoneState> states;  // by zone; missing ones read as quiet
};

void draw_zones(ImDrawList* draw, const ViewTransform& view, const ZoneShapes& shapes);

}  // namespace ydscope::ui
