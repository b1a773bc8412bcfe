// Several lidars over one view: a line per source in its colour, saying whether it scans or how
// long it has been silent and why, so one unplugged unit is plain while the others draw on.
#include <algorithm>

#include <imgui.h>

#include "ui/panels/panels.h"

namespace ydscope::ui {

void draw_source_legend(const UiModel& m, float view_left, float view_width) {
  ImDrawList* draw = ImGui::GetBackgroundDrawList();
  const float line = ImGui::GetTextLineHeightWithSpacing();
  const float pad = ImGui::GetFontSize() * 0.6f;
  float widest = 0.0f;
  for (const SourceRow& row : m.sources) widest = std::max(widest, ImGui::CalcTextSize(row.legend.c_str()).x);
  const float box = ImGui::GetFontSize() * 0.8f;
  const ImVec2 lo{view_left + pad, pad};
  const ImVec2 hi{std::min(lo.x + widest + box + 3.0f * pad, view_left + view_width - pad),
                  lo.y + line * static_cast<float>(m.sources.size()) + pad};
  draw->AddRectFilled(lo, hi, IM_COL32(15, 20, 30, 200), pad * 0.5f);
  float y = lo.y + pad * 0.5f;
  for (std::size_t i = 0; i < m.sources.size(); ++i) {
    const SourceRow& row = m.sources[i];
    const Rgba8 c = row.look.colour;
    const ImU32 colour = IM_COL32(c.r, c.g, c.b, row.dim || row.look.hidden ? 110 : 255);
    const ImVec2 swatch_lo{lo.x + pad, y + (line - box) * 0.5f};
    draw->AddRectFilled(swatch_lo, {swatch_lo.x + box, swatch_lo.y + box}, colour, 2.0f);
    if (i == m.selected_source) draw->AddRect({swatch_lo.x - 2.0f, swatch_lo.y - 2.0f}, {swatch_lo.x + box + 2.0f, swatch_lo.y + box + 2.0f}, IM_COL32(255, 255, 255, 200), 2.0f);
    // A silent source's words in amber: the news of the view.
    const ImU32 ink = row.dim ? IM_COL32(255, 190, 80, 255) : row.look.hidden ? IM_COL32(140, 145, 155, 255) : IM_COL32(230, 235, 245, 255);
    draw->AddText({swatch_lo.x + box + pad, y}, ink, row.legend.c_str());
    y += line;
  }
}

}  // namespace ydscope::ui
