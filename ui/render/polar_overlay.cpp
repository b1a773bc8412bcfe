#include "ui/render/polar_overlay.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

#include <imgui.h>

#include "ui/render/im_vec.h"
#include "ui/view/geometry/unit_marks.h"
#include "ui/view/geometry/view_frame.h"

namespace ydscope::ui {
namespace {

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
void label(ImDrawList* draw, Vec2 at, const char* text, ImU32 colour, bool centred,
           const ViewTransform* bounds = nullptr) {
  const ImVec2 size = ImGui::CalcTextSize(text);
  ImVec2 p = im(at);
  if (centred) p = {p.x - size.x * 0.5f, p.y - size.y * 0.5f};
  if (bounds) {
    const Vec2 lo = bounds->viewport_origin();
    const Vec2 hi = lo + bounds->viewport_size();
    p.x = std::clamp(p.x, lo.x + 4.0f, std::max(lo.x + 4.0f, hi.x - size.x - 4.0f));
    p.y = std::clamp(p.y, lo.y + 2.0f, std::max(lo.y + 2.0f, hi.y - size.y - 2.0f));
  }
  // A dark plate under the words: they stay legible over scan points and grid lines alike.
  draw->AddRectFilled({p.x - 4.0f, p.y - 1.0f}, {p.x + size.x + 4.0f, p.y + size.y + 1.0f}, IM_COL32(11, 13, 18, 200),
                      4.0f);
  draw->AddText(p, colour, text);
}

// A translucent wedge from the origin out past the view's edge, in steps of at most 2 degrees.
void sector_wedge(ImDrawList* draw, const ViewTransform& view, const SectorShape& sector, ImU32 fill, ImU32 edge) {
  const float reach_mm = view.visible_radius_mm() * 2.0f + length(view.centre_world());
  const Vec2 o = view.world_to_screen({0.0f, 0.0f});
  const int steps = std::max(1, static_cast<int>(std::ceil(sector.width_deg / 2.0f)));
  Vec2 previous = view.world_to_screen(polar_to_world(sector.from_deg, reach_mm));
  draw->AddLine(im(o), im(previous), edge, 1.5f);
  for (int i = 1; i <= steps; ++i) {
    const Vec2 next = view.world_to_screen(polar_to_world(
        sector.from_deg + sector.width_deg * static_cast<float>(i) / static_cast<float>(steps), reach_mm));
    draw->AddTriangleFilled(im(o), im(previous), im(next), fill);
    previous = next;
  }
  draw->AddLine(im(o), im(previous), edge, 1.5f);
  // The name sits on the bisector, a little out from the lidar.
  const float at_mm = 40.0f / std::max(view.px_per_mm(), 1e-6f);
  label(draw, view.world_to_screen(polar_to_world(sector.from_deg + sector.width_deg * 0.5f, at_mm * 2.5f)),
        sector.label.c_str(), edge, true);
}

// A lidar: a dot and a chevron pointing along its laser frame's forward (+x, the unit's 180 deg),
// turned with its pose.
void lidar_mark(ImDrawList* draw, const ViewTransform& view, const Pose& pose, ImU32 accent, bool selected) {
  const Vec2 o = view.world_to_screen(view_of(pose.to_common(CommonPoint{0.0f, 0.0f})));
  Vec2 forward = view.world_to_screen(view_of(pose.to_common(CommonPoint{1000.0f, 0.0f}))) - o;
  forward = forward * (1.0f / std::max(length(forward), 1e-3f));
  const Vec2 side{-forward.y, forward.x};
  draw->AddCircleFilled(im(o), 4.0f, accent, 16);
  draw->AddCircle(im(o), 9.0f, IM_COL32(255, 255, 255, 90), 24, 1.5f);
  if (selected) draw->AddCircle(im(o), 15.0f, accent, 32, 2.0f);
  draw->AddTriangleFilled(im(o + forward * 24.0f), im(o + forward * 13.0f - side * 7.0f),
                          im(o + forward * 13.0f + side * 7.0f), accent);
  // The unit's own 0 and the way it sweeps, so a rotated or mirrored mount shows at a glance.
  const UnitMarks unit = unit_marks(view, pose);
  // Pale steel, not white (the lidar's own dot stays the one white disc) and too grey to share a
  // hue with any source's colour or the range colours: these are marks on the view, not returns.
  const ImU32 pale = IM_COL32(190, 200, 228, 235);
  draw->AddLine(im(unit.zero_from), im(unit.zero_to), pale, 2.0f);
  label(draw, unit.zero_label, "0\xC2\xB0", pale, true);
  for (std::size_t i = 1; i < unit.sweep.size(); ++i)
    draw->AddLine(im(unit.sweep[i - 1]), im(unit.sweep[i]), pale, 1.5f);
  draw->AddTriangleFilled(im(unit.head_tip), im(unit.head_left), im(unit.head_right), pale);
}

}  // namespace

void draw_polar_overlay(ImDrawList* draw, const OverlayInput& in) {
  const ViewTransform& view = *in.view;
  draw->PushClipRect(im(view.viewport_origin()), im(view.viewport_origin() + view.viewport_size()), true);

  if (in.show_grid_labels && in.grid) {
    for (const GridLabel& l : in.grid->ring_labels)
      label(draw, l.screen + Vec2{4.0f, -2.0f}, l.text.c_str(), IM_COL32(170, 190, 220, 200), false);
    for (const GridLabel& l : in.grid->spoke_labels)
      label(draw, l.screen, l.text.c_str(), IM_COL32(150, 170, 200, 170), true, &view);
  }

  for (const SectorShape& sector : in.sectors)
    sector_wedge(draw, view, sector, IM_COL32(249, 168, 37, 38), IM_COL32(249, 168, 37, 200));
  if (in.sweep) sector_wedge(draw, view, *in.sweep, IM_COL32(120, 200, 255, 45), IM_COL32(120, 200, 255, 230));

  if (in.zones) draw_zones(draw, view, *in.zones);
  if (in.dropouts) draw_dropout_ring(draw, view, *in.dropouts);
  if (in.marks.empty()) {
    lidar_mark(draw, view, {}, IM_COL32(255, 255, 255, 230), false);
  } else {
    for (const SourceMark& mark : in.marks)
      lidar_mark(draw, view, mark.pose, IM_COL32(mark.colour.r, mark.colour.g, mark.colour.b, 230), mark.selected);
  }

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
