// Several lidars over one view: a line per source in its colour, saying whether it scans or how
// long it has been silent and why, so one unplugged unit is plain while the others draw on.
#include <algorithm>

#include <imgui.h>

#include "ui/panels/panels.h"

namespace ydscope::ui {
namespace {

float legend_pad() { return ImGui::GetFontSize() * 0.6f; }
float swatch_size() { return ImGui::GetFontSize() * 0.8f; }

// Swatch and words of one line whose top-left is `at` (inside a plate already drawn).
void legend_line(ImDrawList* draw, const SourceRow& row, ImVec2 at, bool selected) {
  const float line = ImGui::GetTextLineHeightWithSpacing();
  const float box = swatch_size();
  const Rgba8 c = row.look.colour;
  const ImU32 colour = IM_COL32(c.r, c.g, c.b, row.dim || row.look.hidden ? 110 : 255);
  const ImVec2 swatch{at.x, at.y + (line - box) * 0.5f};
  draw->AddRectFilled(swatch, {swatch.x + box, swatch.y + box}, colour, 2.0f);
  if (selected)
    draw->AddRect({swatch.x - 2.0f, swatch.y - 2.0f}, {swatch.x + box + 2.0f, swatch.y + box + 2.0f},
                  IM_COL32(255, 255, 255, 200), 2.0f);
  // A silent source's words in amber: the news of the view.
  const ImU32 ink = row.dim           ? IM_COL32(255, 190, 80, 255)
                    : row.look.hidden ? IM_COL32(140, 145, 155, 255)
                                      : IM_COL32(230, 235, 245, 255);
  draw->AddText({swatch.x + box + legend_pad(), at.y}, ink, row.legend.c_str());
}

}  // namespace

float source_legend_bottom(const UiModel& m) {
  if (m.sources.size() < 2) return 0.0f;
  return legend_pad() * 2.0f + ImGui::GetTextLineHeightWithSpacing() * static_cast<float>(m.sources.size());
}

void draw_source_legend(const UiModel& m, float view_left, float view_width) {
  ImDrawList* draw = ImGui::GetBackgroundDrawList();
  const float line = ImGui::GetTextLineHeightWithSpacing();
  const float pad = legend_pad();
  float widest = 0.0f;
  for (const SourceRow& row : m.sources) widest = std::max(widest, ImGui::CalcTextSize(row.legend.c_str()).x);
  const ImVec2 lo{view_left + pad, pad};
  const ImVec2 hi{std::min(lo.x + widest + swatch_size() + 3.0f * pad, view_left + view_width - pad),
                  source_legend_bottom(m)};
  draw->AddRectFilled(lo, hi, IM_COL32(15, 20, 30, 200), pad * 0.5f);
  for (std::size_t i = 0; i < m.sources.size(); ++i)
    legend_line(draw, m.sources[i], {lo.x + pad, lo.y + pad * 0.5f + line * static_cast<float>(i)},
                i == m.selected_source);
}

void draw_source_label(const SourceRow& row, ImVec2 top_left, bool selected) {
  ImDrawList* draw = ImGui::GetBackgroundDrawList();
  const float pad = legend_pad();
  const ImVec2 lo{top_left.x + pad, top_left.y + pad};
  const ImVec2 hi{lo.x + ImGui::CalcTextSize(row.legend.c_str()).x + swatch_size() + 3.0f * pad,
                  lo.y + ImGui::GetTextLineHeightWithSpacing() + pad};
  draw->AddRectFilled(lo, hi, IM_COL32(15, 20, 30, 200), pad * 0.5f);
  legend_line(draw, row, {lo.x + pad, lo.y + pad * 0.5f}, selected);
}

}  // namespace ydscope::ui
