// Statistics: the session's counters and rates for the selected source.
#include <cstdio>
#include <algorithm>
#include <cstring>

#include <imgui.h>

#include "ui/panels/panels.h"

namespace ydscope::ui {

void draw_stats_panel(const UiModel& m) {
  if (!ImGui::CollapsingHeader("Statistics", ImGuiTreeNodeFlags_DefaultOpen)) return;
  const CounterSnapshot& c = m.snap.counters;
  const StaleValues stale(m);
  if (!ImGui::BeginTable("stats", 4, ImGuiTableFlags_SizingStretchProp)) return;
  // Two name/value pairs per row keeps the panel short.
  auto pair = [&stale](const char* name, const char* format, double value, bool warn) {
    ImGui::TableNextColumn();
    ImGui::TextDisabled("%s", name);
    ImGui::TableNextColumn();
    char text[48];
    std::snprintf(text, sizeof text, format, value);
    if (warn)
      ImGui::TextColored(stale.colour({1.0f, 0.6f, 0.35f, 1.0f}), "%s", text);
    else
      ImGui::TextUnformatted(text);
  };
  pair("bytes/s", "%.0f", c.bytes_per_s, false);
  pair("packets/s", "%.0f", c.packets_per_s, false);
  pair("laps/s", "%.2f", c.laps_per_s, false);
  pair("points/lap", "%.0f", static_cast<double>(m.points_in_lap), false);
  pair("checksum err", "%.0f", static_cast<double>(c.checksum_errors), c.checksum_errors > 0);
  pair("resync bytes", "%.0f", static_cast<double>(c.resync_bytes), c.resync_bytes > 0);
  pair("CRC8 fails", "%.0f", static_cast<double>(c.crc8_failures), c.crc8_failures > 0);
  // Only a stream that lost its zero packets makes a lap longer than a lap can be.
  if (c.cut_points > 0) pair("points cut", "%.0f", static_cast<double>(c.cut_points), true);
  pair("queue drops", "%.0f", static_cast<double>(m.snap.queue_dropped), m.snap.queue_dropped > 0);
  pair("laps skipped", "%.0f", static_cast<double>(m.laps_skipped), false);
  pair("reconnects", "%.0f", static_cast<double>(c.reconnects), c.reconnects > 0);
  pair("latency ms", "%.1f", m.latency_ms.mean(), false);
  pair("frame ms", "%.2f", m.frame_ms.mean(), false);
  pair("frames/s", "%.1f", m.frame_interval_ms.mean() > 0.0 ? 1000.0 / m.frame_interval_ms.mean() : 0.0, false);
  pair("points drawn", "%.0f", static_cast<double>(m.points_drawn_total), false);
  pair("laps shown", "%.0f", static_cast<double>(m.laps_shown), false);
  ImGui::EndTable();
  // Every consumer of the lap stream has its own ring; one that falls behind drops only its own.
  if (m.snap.consumers.size() > 1) {
    ImGui::TextDisabled("lap consumers (ring, delivered, dropped)");
    for (const LapConsumerStats& consumer : m.snap.consumers) {
      const ImVec4 colour =
          consumer.dropped > 0 ? ImVec4{1.0f, 0.6f, 0.35f, 1.0f} : ImGui::GetStyleColorVec4(ImGuiCol_Text);
      ImGui::TextColored(colour, "  %s: %zu, %llu, %llu", consumer.name.c_str(), consumer.capacity,
                         static_cast<unsigned long long>(consumer.delivered),
                         static_cast<unsigned long long>(consumer.dropped));
    }
  }
}

}  // namespace ydscope::ui
