// When the picture is not live: the cloud dimmed and a large box over it saying why.
#include <algorithm>
#include <cfloat>

#include <imgui.h>

#include "ui/panels/panels.h"
#include "ui/view/status/booth_calm.h"
#include "ui/render/theme.h"

namespace ydscope::ui {

void draw_view_overlay(const UiModel& m, float view_left, float view_width, float view_height, float view_top) {
  const ViewState v = for_audience(m.view_state, m.booth);
  if (!v.dim) return;
  // Under the panels, over the cloud: the old picture stays visible but plainly not live.
  ImDrawList* draw = ImGui::GetBackgroundDrawList();
  const ImVec2 lo{view_left, view_top};
  const ImVec2 hi{view_left + view_width, view_top + view_height};
  draw->AddRectFilled(lo, hi, IM_COL32(9, 11, 15, 205));

  ImFont* font = display_font() ? display_font() : ImGui::GetFont();
  const float headline_px = std::clamp(view_height * 0.075f, 30.0f, 96.0f);
  const float body_px = std::clamp(headline_px * 0.38f, ImGui::GetFontSize(), 40.0f);
  const float wrap = view_width * 0.8f;
  const ImVec2 head = font->CalcTextSizeA(headline_px, FLT_MAX, 0.0f, v.headline.c_str());
  const ImVec2 sub = font->CalcTextSizeA(body_px, FLT_MAX, wrap, v.subtitle.c_str());
  const float detail_px = body_px * 0.8f;
  const ImVec2 det =
      v.detail.empty() ? ImVec2{0.0f, 0.0f} : font->CalcTextSizeA(detail_px, FLT_MAX, wrap, v.detail.c_str());
  const float gap = body_px * 0.5f;
  const float box_w = std::max({head.x, sub.x, det.x}) + 2.0f * body_px;
  const float box_h = head.y + gap + sub.y + (v.detail.empty() ? 0.0f : gap + det.y) + 1.6f * body_px;
  const float cx = view_left + view_width * 0.5f;
  const float top = view_top + view_height * 0.5f - box_h * 0.5f;
  draw->AddRectFilled({cx - box_w * 0.5f, top}, {cx + box_w * 0.5f, top + box_h}, IM_COL32(20, 24, 32, 235),
                      body_px * 0.6f);
  draw->AddRect({cx - box_w * 0.5f, top}, {cx + box_w * 0.5f, top + box_h}, IM_COL32(90, 100, 120, 255), body_px * 0.6f,
                0, 2.0f);
  float y = top + 0.8f * body_px;
  // White and light grey only: the words must read on any screen, and must not look like scan points.
  draw->AddText(font, headline_px, {cx - head.x * 0.5f, y}, IM_COL32(245, 245, 250, 255), v.headline.c_str());
  y += head.y + gap;
  draw->AddText(font, body_px, {cx - sub.x * 0.5f, y}, IM_COL32(215, 220, 230, 255), v.subtitle.c_str(), nullptr, wrap);
  y += sub.y + gap;
  if (!v.detail.empty())
    draw->AddText(font, detail_px, {cx - det.x * 0.5f, y}, IM_COL32(160, 168, 182, 255), v.detail.c_str(), nullptr,
                  wrap);
}

}  // namespace ydscope::ui
