#pragma once
// What the polar view draws with ImGui's draw lists on top of the GL layer: ring and spoke labels,
// the lidar's origin and heading, watched sectors, the hovered point and the ruler. A few dozen items per frame,
// never one per scan point.
#include <optional>
#include <string>
#include <vector>

#include "core/frame/pose.h"
#include "ui/render/dropout_ring_overlay.h"
#include "ui/render/zone_overlay.h"
#include "ui/view/geometry/geometry.h"
#include "ui/view/geometry/grid_layout.h"
#include "ui/view/geometry/hit_test.h"

struct ImDrawList;

namespace ydscope::ui {

// A watched sector as the view outlines it: clockwise from from_deg over width_deg.
struct SectorShape {
  float from_deg = 0.0f;
  float width_deg = 0.0f;
  std::string label;  // "S1"
};

// Where one of several lidars sits: its position and heading, in its colour.
struct SourceMark {
  Pose pose;
  Rgba8 colour;
  bool selected = false;  // the one the panels show: ringed
};

struct OverlayInput {
  const ViewTransform* view = nullptr;
  const GridLayout* grid = nullptr;
  bool show_grid_labels = true;
  std::optional<PointHit> hover;
  const Ruler* ruler = nullptr;
  std::optional<Vec2> ruler_cursor_world;  // rubber band from the first end to the cursor
  std::vector<SectorShape> sectors;
  std::optional<SectorShape> sweep;          // the sector a Shift+drag is sweeping out
  std::vector<SourceMark> marks;             // several sources; empty: the lone lidar at the origin
  std::optional<ZoneShapes> zones;           // the selected source's zones and their states
  std::optional<DropoutRingShape> dropouts;  // the selected lidar's no-return ring and blocked sectors
};

void draw_polar_overlay(ImDrawList* draw, const OverlayInput& input);

}  // namespace ydscope::ui
