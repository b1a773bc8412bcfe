#pragma once
// Turns the lap history into the vertex array the point shader draws in one call: positions in
// world millimetres plus a colour, newest lap last so it is drawn on top.
#include <cstddef>
#include <vector>

#include "core/protocol/interference_filter.h"
#include "ui/view/scene/colour_map.h"
#include "ui/view/scene/lap_history.h"
#include "ui/view/scene/motion_background.h"

namespace ydscope::ui {

struct PointVertex {
  float x, y;    // world mm
  Rgba8 colour;  // premultiplied by nothing; the shader blends with alpha
  // How much of what lies under shows through where the sprite covers half a pixel, for a sprite
  // standing for several points (pixel_merge.h); below 0, a lone point's: 1 - alpha / 2.
  float half_clear = -1.0f;
};
static_assert(sizeof(PointVertex) == 16, "the shader's vertex layout expects 16 bytes");

struct InterferenceSettings {
  bool drop_specular = false;  // G1 flag 2
  bool drop_ambient = false;   // G1 flag 3
  bool show_ghosts = true;     // draw removed points faintly instead of hiding them
  // The protocol's filter (shared with the CLI) decides which points go.
  InterferenceFilter filter() const { return {drop_specular, drop_ambient}; }
  friend bool operator==(const InterferenceSettings&, const InterferenceSettings&) = default;
};

struct PointCloudStats {
  std::size_t drawn = 0;
  std::size_t ghosts = 0;
  std::size_t newest_specular_removed = 0;  // in the newest lap
  std::size_t newest_ambient_removed = 0;
  std::size_t newest_no_return = 0;  // range 0: no echo, never drawn
};

// Clears `out` (keeping its capacity) and fills it. Points with range 0 are not drawn. `motion`
// tells moving points from the room in Motion mode (without it every point is the room's).
// `phase` (LapPhase, 0..1) is how far the view is towards the next lap: every lap ages by that
// fraction of a lap, and when the history is full the oldest lap, which the next one will push
// out, fades away with it, so nothing pops.
PointCloudStats build_point_cloud(const LapHistory& history, const ColourParams& colours,
                                  const InterferenceSettings& filter, std::vector<PointVertex>& out,
                                  const MotionBackground* motion = nullptr, float phase = 0.0f);

}  // namespace ydscope::ui
