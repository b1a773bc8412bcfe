#pragma once
// The range rings and angle spokes as thin antialiased triangles: each line is a quad a little
// wider than the line, and the fragment shader fades it by the distance to its centre line. Only
// pixels near lines cost anything, which matters on software OpenGL.
#include <vector>

#include "ui/view/geometry/grid_layout.h"

namespace ydscope::ui {

struct LineVertex {
  float x, y;     // world mm
  float edge_px;  // signed distance from the line's centre, in pixels
  Rgba8 colour;
};
static_assert(sizeof(LineVertex) == 16, "the line shader's vertex layout expects 16 bytes");

struct GridStyle {
  float line_width_px = 1.2f;
  Rgba8 ring{140, 165, 205, 80};
  Rgba8 major_ring{150, 180, 225, 130};  // every fifth ring
  Rgba8 spoke{140, 165, 205, 40};
  float spoke_start_px = 24.0f;  // keep the lidar marker clear
};

// Half the quad width in pixels: half the line plus a pixel of fade.
float line_quad_half_px(const GridStyle& style);

void build_grid_geometry(const ViewTransform& view, const GridLayout& grid, const GridStyle& style,
                         std::vector<LineVertex>& out);

}  // namespace ydscope::ui
