#pragma once
// Where ImGui's picture changed since the last frame. A streaming view changes at every frame,
// but the panels beside it change a figure or two now and then, and on a software renderer
// rasterising the unchanged panels again was about a third of a frame's CPU. Each draw list's
// triangles (resolved to their vertices, with their clip rectangle and texture) are compared with
// the last frame's: those between the longest common head and tail are what changed, and their
// bounds, old and new, clipped, are that list's damage. A frame whose lists all match the last
// frame's has none, and need not be drawn at all.
#include <optional>
#include <vector>

#include <imgui.h>

#include "ui/render/screen_boxes.h"

namespace ydscope::ui {

class DrawDamage {
 public:
  // The boxes where `data` draws otherwise than the frame last given, at most one for each draw
  // list that changed; none when the frame repeats the last. std::nullopt when the two cannot be
  // compared (the first frame, or another number of draw lists): take it all as changed.
  std::optional<std::vector<DisplayBox>> update(const ImDrawData& data);
  // The next frame is compared with nothing (after a frame drawn by other means).
  void forget() { known_ = false; }

 private:
  struct Triangle {
    ImDrawVert corner[3];
    ImVec4 clip;
    ImTextureID texture;
    bool operator==(const Triangle& other) const;
  };
  static void resolve(const ImDrawList& list, std::vector<Triangle>& out);
  static DisplayBox bounds(const std::vector<Triangle>& triangles, std::size_t from, std::size_t to);

  std::vector<std::vector<Triangle>> lists_, resolved_;  // the last frame's; this frame's, reused
  bool known_ = false;
};

}  // namespace ydscope::ui
