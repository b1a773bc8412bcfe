// Sectors: statistics of the points in chosen angular sectors (optionally a range band), lap by
// lap: what a bench engineer reads off a target board or a wall at a known distance.
#include <algorithm>
#include <cstdio>

#include <imgui.h>

#include "ui/panels/panels.h"

namespace ydscope::ui {
namespace {

void sector_details(const SectorWatch& w) {
  const auto& s = w.newest();
  if (!s) {
    ImGui::TextDisabled("waiting for a lap");
    return;
  }
  if (ImGui::BeginTable("sector_stats", 4, ImGuiTableFlags_SizingStretchProp)) {
    auto pair = [](const char* name, const char* format, double value) {
      ImGui::TableNextColumn();
      ImGui::TextDisabled("%s", name);
      ImGui::TableNextColumn();
      ImGui::Text(format, value);
    };
    pair("points", "%.0f", static_cast<double>(s->points));
    pair("valid", "%.1f %%", s->valid_share * 100);
    pair("mean mm", "%.1f", s->range_mm.mean);
    pair("median mm", "%.1f", s->range_mm.median);
    pair("std-dev mm", "%.1f", s->range_mm.stddev);
    pair("min mm", "%.0f", s->range_mm.min);
    pair("max mm", "%.0f", s->range_mm.max);
    ImGui::EndTable();
  }
  ImGui::PushItemWidth(-1.0f);  // ImGui 1.86's plots take their width from the item width
  const MetricHistory& mean = w.mean_mm();
  char overlay[64];
  std::snprintf(overlay, sizeof overlay, "mean over %zu laps: %.0f..%.0f mm", mean.size(), mean.min(), mean.max());
  const float pad = std::max((mean.max() - mean.min()) * 0.2f, 5.0f);
  ImGui::PlotLines("##mean", mean.data(), static_cast<int>(mean.size()), static_cast<int>(mean.offset()), overlay,
                   mean.min() - pad, mean.max() + pad, {0.0f, 48.0f});
  std::snprintf(overlay, sizeof overlay, "ranges %.0f..%.0f mm", s->histogram.lo, s->histogram.hi);
  ImGui::PlotHistogram("##histogram", w.histogram().data(), static_cast<int>(w.histogram().size()), 0, overlay, 0.0f,
                       FLT_MAX, {0.0f, 48.0f});
  std::snprintf(overlay, sizeof overlay, "valid %% per %.1f deg", s->angle_bin_deg);
  ImGui::PlotHistogram("##valid", w.valid_pct_by_angle().data(), static_cast<int>(w.valid_pct_by_angle().size()), 0,
                       overlay, 0.0f, 100.0f, {0.0f, 40.0f});
  ImGui::PopItemWidth();
}

}  // namespace

void draw_sectors_panel(UiModel& m, PanelEdits& e) {
  if (!m.sectors.empty()) ImGui::SetNextItemOpen(true, ImGuiCond_Once);  // watched from the start: show them
  if (!ImGui::CollapsingHeader("Sectors")) return;
  ImGui::TextDisabled("Shift+drag on the view sweeps a sector, or type one:");
  ImGui::SetNextItemWidth(150.0f);
  const bool entered = ImGui::InputTextWithHint("##new_sector", "260:280 [1500:2500]", e.sector_text,
                                                sizeof e.sector_text, ImGuiInputTextFlags_EnterReturnsTrue);
  ImGui::SameLine();
  help_marker(
      "FROM:TO in degrees, clockwise from straight ahead (may cross 0, e.g. 350:10); optionally a range "
      "band MIN:MAX in mm so only a target's returns count, not the wall behind it.");
  ImGui::SameLine();
  if ((ImGui::Button("Add") || entered) && e.sector_text[0]) m.requests.push_back(WatchSector{e.sector_text});
  if (!m.sector_error.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4{1.0f, 0.45f, 0.4f, 1.0f});
    wrapped_text(m.sector_error.c_str());
    ImGui::PopStyleColor();
  }
  for (std::size_t i = 0; i < m.sectors.size(); ++i) {
    const SectorWatch& w = m.sectors[i];
    ImGui::PushID(static_cast<int>(i));
    char title[128];
    std::snprintf(title, sizeof title, "S%zu  %s deg", i + 1, w.sector().name.c_str());
    const bool open = ImGui::TreeNodeEx("sector", ImGuiTreeNodeFlags_DefaultOpen, "%s", title);
    ImGui::SameLine(ImGui::GetContentRegionMax().x - 60.0f);
    if (ImGui::SmallButton("remove")) m.requests.push_back(UnwatchSector{i});
    if (open) {
      sector_details(w);
      ImGui::TreePop();
    }
    ImGui::PopID();
  }
}

}  // namespace ydscope::ui
