#pragma once
// Renders ImGui's draw data inside some boxes of the window only. For the call each command is
// repeated once a box, its clip rectangle cut to that box (then the lists are put back), so the
// backend's scissor never reaches a pixel the caller did not clear, parts outside every box are
// skipped, and the draw data is uploaded once however many boxes there are. With boxes of whole
// pixels at a framebuffer scale of 1 the scissors stay inside them exactly. The boxes must not
// overlap: a pixel in two would be drawn twice.
#include <span>

#include <imgui.h>

#include "ui/render/screen_boxes.h"

namespace ydscope::ui {

void render_imgui_within(ImDrawData& data, std::span<const DisplayBox> boxes);
inline void render_imgui_within(ImDrawData& data, const DisplayBox& box) { render_imgui_within(data, {&box, 1}); }

}  // namespace ydscope::ui
