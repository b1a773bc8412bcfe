#include "ui/render/polar_overlay.h"

#include <algorithm>
#include <cstdio>

#include <imgui.h>

namespace ydscope::ui {
namespace {

ImVec2 im(Vec2 v) { return {v.x, v.y}; }

const char* flag_text(PointFlag flag) {
  switch (flag) {
    case PointFlag::None: return "";
    case PointFlag::Reserved: return "  flag 1";
    case PointFlag::Specular: return "  specular (flag 2)";
    case PointFlag::AmbientLight: return "  ambient light (flag 3)";
  }
  return "";
}

// `bounds` keeps the whole label inside the view (spoke labels sit at its edges).
void label(ImDrawList* draw, Vec2 at, const char* text, ImU32 colour, bool centred, const ViewTransform* bounds = nullptr) {
  const ImVec2 size = ImGui::CalcTextSize(text);
  ImVec2 p = im(at);
  if (centred) p = {p.x - size.x * 0.5f, p.y - size.y * 0.5f};
  if (bounds) {
    const Vec2 lo = bounds->viewport_origin();
    const Vec2 hi = lo + bounds->viewport_size();
    p.x = std::clamp(p.x, lo.x + 4.0f, std::max(lo.x + 4.0f, hi.x - size.x - 4.0f));
    p.y = std::clamp(p.y, lo.y + 2.0f, std::max(lo.y + 2.0f, hi.y - size.y - 2.0f));
  }
  draw->AddText({p.x + 1.0f, p.y + 1.0f}, IM_COL32(0, 0, 0, 160), text);
  draw->AddText(p, colour, text);
}

}  // namespace

void draw_polar_overlay(ImDrawList* draw, const OverlayInput& in) {
  const ViewTransform& view = *in.view;
  draw->PushClipRect(im(view.viewport_origin()), im(view.viewport_origin() + view.viewport_size()), true);

  if (in.show_grid_labels && in.grid) {
    for (const GridLabel& l : in.grid->ring_labels) label(draw, l.screen + Vec2{4.0f, -2.0f}, l.text.c_str(), IM_COL32(170, 190, 220, 200), false);
    for (const GridLabel& l : in.grid->spoke_labels) label(draw, l.screen, l.text.c_str(), IM_COL32(150, 170, 200, 170), true, &view);
  }

  // The lidar: a dot and a chevron pointing along 0 deg (the heading).
  const Vec2 o = view.world_to_screen({0.0f, 0.0f});
  const ImU32 accent = IM_COL32(255, 255, 255, 230);
  draw->AddCircleFilled(im(o), 4.0f, accent, 16);
  draw->AddCircle(im(o), 9.0f, IM_COL32(255, 255, 255, 90), 24, 1.5f);
  draw->AddTriangleFilled(im(o + Vec2{0.0f, -24.0f}), im(o + Vec2{-7.0f, -13.0f}), im(o + Vec2{7.0f, -13.0f}), accent);

  if (in.hover) {
    const Vec2 p = view.world_to_screen(in.hover->world);
    draw->AddCircle(im(p), 7.0f, IM_COL32(255, 255, 255, 220), 20, 1.5f);
    char text[96];
    std::snprintf(text, sizeof text, "%.2f\xC2\xB0  %.3f m%s", static_cast<double>(in.hover->point.angle_deg),
                  static_cast<double>(in.hover->point.range_mm) / 1000.0, flag_text(in.hover->point.flag));
    const ImVec2 size = ImGui::CalcTextSize(text);
    const ImVec2 box{p.x + 12.0f, p.y - size.y - 12.0f};
    draw->AddRectFilled({box.x - 6.0f, box.y - 4.0f}, {box.x + size.x + 6.0f, box.y + size.y + 4.0f},
                        IM_COL32(15, 20, 30, 220), 4.0f);
    draw->AddText(box, IM_COL32(235, 240, 250, 255), text);
  }

  if (in.ruler && in.ruler->first()) {
    const Vec2 a = view.world_to_screen(*in.ruler->first());
    const std::optional<Vec2> end_world = in.ruler->second() ? in.ruler->second() : in.ruler_cursor_world;
    const ImU32 ruler_colour = IM_COL32(255, 220, 90, 255);
    draw->AddCircleFilled(im(a), 4.0f, ruler_colour);
    if (end_world) {
      const Vec2 b = view.world_to_screen(*end_world);
      draw->AddLine(im(a), im(b), ruler_colour, 2.0f);
      draw->AddCircleFilled(im(b), 4.0f, ruler_colour);
      char text[48];
      std::snprintf(text, sizeof text, "%.3f m", static_cast<double>(length(*end_world - *in.ruler->first())) / 1000.0);
      label(draw, (a + b) * 0.5f + Vec2{8.0f, -18.0f}, text, ruler_colour, false);
    }
  }
  draw->PopClipRect();
}

}  // namespace ydscope::ui
