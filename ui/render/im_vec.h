#pragma once
// The view's maths works in Vec2 (ui/view/geometry); ImGui's draw list takes ImVec2.
#include <imgui.h>

#include "ui/view/geometry/geometry.h"

namespace ydscope::ui {

inline ImVec2 im(Vec2 v) { return {v.x, v.y}; }

}  // namespace ydscope::ui
