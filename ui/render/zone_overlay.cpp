#include "ui/render/zone_overlay.h"

#include <algorithm>
#include <cmath>

#include <imgui.h>

#include "ui/render/im_vec.h"
#include "ui/view/geometry/view_frame.h"

namespace ydscope::ui {
namespace {

struct ZoneColours {
  ImU32 fill, edge, text;
};

ZoneColours colours_of(bool raised) {
  if (raised) return {IM_COL32(235, 60, 50, 70), IM_COL32(245, 70, 60, 240), IM_COL32(255, 140, 130, 255)};
  return {IM_COL32(60, 200, 190, 18), IM_COL32(70, 210, 200, 170), IM_COL32(150, 230, 225, 230)};
}

// Screen outline of a sector zone: the outer arc one way, the inner arc (or the lidar) back.
std::vector<ImVec2> sector_outline(const ViewTransform& view, const Pose& pose, const Sector& s) {
  const float reach = view.visible_radius_mm() * 2.0f + length(view.centre_world());
  const float outer = s.max_mm ? static_cast<float>(*s.max_mm) : reach;
  const float inner = s.min_mm ? static_cast<float>(*s.min_mm) : 0.0f;
  const auto width = static_cast<float>(s.width_deg());
  const int steps = std::max(2, static_cast<int>(std::ceil(width / 2.0f)));
  std::vector<ImVec2> out;
  const auto at = [&](float deg, float mm) {
    return im(view.world_to_screen(posed_in_view(pose, polar_to_world(deg, mm))));
  };
  for (int i = 0; i <= steps; ++i)
    out.push_back(
        at(static_cast<float>(s.from_deg) + width * static_cast<float>(i) / static_cast<float>(steps), outer));
  if (inner <= 0.0f) {
    out.push_back(at(0.0f, 0.0f));
  } else {
    for (int i = steps; i >= 0; --i)
      out.push_back(
          at(static_cast<float>(s.from_deg) + width * static_cast<float>(i) / static_cast<float>(steps), inner));
  }
  return out;
}

}  // namespace

void draw_zones(ImDrawList* draw, const ViewTransform& view, const ZoneShapes& shapes) {
  for (std::size_t z = 0; z < shapes.zones.size(); ++z) {
    const Zone& zone = shapes.zones[z];
    const bool raised = z < shapes.states.size() && shapes.states[z].raised;
    const ZoneColours c = colours_of(raised);
    std::vector<ImVec2> outline;
    if (zone.sector) {
      outline = sector_outline(view, shapes.pose, *zone.sector);
    } else {
      for (const CommonPoint& p : zone.polygon) outline.push_back(im(view.world_to_screen(view_of(p))));
    }
    if (outline.size() < 3) continue;
    // The fill as a fan from the outline's centroid: right for the convex shapes zones mostly are.
    ImVec2 centre{0.0f, 0.0f};
    for (const ImVec2& p : outline) centre = {centre.x + p.x, centre.y + p.y};
    centre = {centre.x / static_cast<float>(outline.size()), centre.y / static_cast<float>(outline.size())};
    for (std::size_t i = 0; i < outline.size(); ++i)
      draw->AddTriangleFilled(centre, outline[i], outline[(i + 1) % outline.size()], c.fill);
    draw->AddPolyline(outline.data(), static_cast<int>(outline.size()), c.edge, ImDrawFlags_Closed,
                      raised ? 2.5f : 1.5f);
    const ImVec2 size = ImGui::CalcTextSize(zone.name.c_str());
    const ImVec2 p{centre.x - size.x * 0.5f, centre.y - size.y * 0.5f};
    draw->AddRectFilled({p.x - 3.0f, p.y - 1.0f}, {p.x + size.x + 3.0f, p.y + size.y + 1.0f}, IM_COL32(11, 13, 18, 190),
                        3.0f);
    draw->AddText(p, c.text, zone.name.c_str());
  }
}

}  // namespace ydscope::ui
