#pragma once
// Renders ImGui's draw data inside one box of the window only. Every command's clip rectangle is
// cut to the box for the call (then put back), so the backend's scissor never reaches a pixel the
// caller did not clear, and commands wholly outside are skipped. With a box of whole pixels at a
// framebuffer scale of 1 the scissors stay inside it exactly.
#include <imgui.h>

#include "ui/render/screen_boxes.h"

namespace ydscope::ui {

void render_imgui_within(ImDrawData& data, const DisplayBox& box);

}  // namespace ydscope::ui
