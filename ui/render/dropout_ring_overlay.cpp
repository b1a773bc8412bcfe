#include "ui/render/dropout_ring_overlay.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include <imgui.h>

#include "ui/render/im_vec.h"
#include "ui/view/geometry/view_frame.h"

namespace ydscope::ui {
namespace {

// Screen point `px` pixels from the lidar towards its angle `deg`, through its pose.
Vec2 ring_point(const ViewTransform& view, const Pose& pose, float deg, float px) {
  const float mm = px / std::max(view.px_per_mm(), 1e-6f);
  return view.world_to_screen(posed_in_view(pose, polar_to_world(deg, mm)));
}

// Amber at the first tint, red when (nearly) nothing comes back.
ImU32 tint(float share) {
  const float t = std::clamp((share - kDropoutTintFrom) / (0.95f - kDropoutTintFrom), 0.0f, 1.0f);
  const auto g = static_cast<int>(170.0f - 130.0f * t);
  const auto a = static_cast<int>(110.0f + 120.0f * t);
  return IM_COL32(235, g, 40, a);
}

void band_segment(ImDrawList* draw, const ViewTransform& view, const Pose& pose, float from_deg, float to_deg,
                  float inner_px, float outer_px, ImU32 colour) {
  const Vec2 a = ring_point(view, pose, from_deg, inner_px);
  const Vec2 b = ring_point(view, pose, from_deg, outer_px);
  const Vec2 c = ring_point(view, pose, to_deg, outer_px);
  const Vec2 d = ring_point(view, pose, to_deg, inner_px);
  draw->AddQuadFilled(im(a), im(b), im(c), im(d), colour);
}

}  // namespace

void draw_dropout_ring(ImDrawList* draw, const ViewTransform& view, const DropoutRingShape& ring) {
  const float step = 360.0f / static_cast<float>(kDropoutBins);
  for (std::size_t b = 0; b < kDropoutBins; ++b) {
    const float share = ring.no_return_share[b];
    if (share < kDropoutTintFrom) continue;
    const float from = static_cast<float>(b) * step;
    band_segment(draw, view, ring.pose, from, from + step, kDropoutRingInnerPx, kDropoutRingOuterPx, tint(share));
  }
  const ImU32 red = IM_COL32(240, 50, 40, 255);
  for (const BlockedSector& s : ring.blocked) {
    const float from = static_cast<float>(s.from_deg);
    const float width = static_cast<float>(s.width_deg());
    const int steps = std::max(1, static_cast<int>(std::ceil(width / 2.0f)));
    // A solid red rim just outside the band, the sector's whole width: one thick line, so no
    // seams show between its pieces.
    std::vector<ImVec2> rim;
    for (int i = 0; i <= steps; ++i)
      rim.push_back(im(ring_point(view, ring.pose, from + width * static_cast<float>(i) / static_cast<float>(steps),
                                  kDropoutRimPx)));
    draw->AddPolyline(rim.data(), static_cast<int>(rim.size()), red, ImDrawFlags_None, 5.0f);
    const std::string text = describe_blocked_sector(s);
    const Vec2 at = ring_point(view, ring.pose, static_cast<float>(s.centre_deg()), kDropoutRimPx + 45.0f);
    const ImVec2 size = ImGui::CalcTextSize(text.c_str());
    const ImVec2 p{at.x - size.x * 0.5f, at.y - size.y * 0.5f};
    draw->AddRectFilled({p.x - 4.0f, p.y - 1.0f}, {p.x + size.x + 4.0f, p.y + size.y + 1.0f}, IM_COL32(11, 13, 18, 210),
                        4.0f);
    draw->AddText(p, IM_COL32(255, 120, 110, 255), text.c_str());
  }
}

}  // namespace ydscope::ui
