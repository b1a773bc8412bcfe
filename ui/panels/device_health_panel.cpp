// Device (what the lidar says it is) and Health (what it says about itself, bit by bit).
#include <cstdio>

#include <imgui.h>

#include "core/protocol/commands.h"
#include "ui/panels/panels.h"
#include "ui/view/health_names.h"

namespace ydscope::ui {
namespace {

void row(const char* name, const char* value) {
  ImGui::TableNextRow();
  ImGui::TableSetColumnIndex(0);
  ImGui::TextDisabled("%s", name);
  ImGui::TableSetColumnIndex(1);
  ImGui::TextUnformatted(value);
}

// One lamp per G1 bit: lit red when set.
void bit_lamps(Model model, std::uint8_t bits, bool trusted) {
  for (const HealthBitInfo& info : health_bits(model)) {
    const bool set = (bits >> info.bit) & 1u;
    const ImVec4 lit = trusted ? ImVec4{1.0f, 0.35f, 0.30f, 1.0f} : ImVec4{0.85f, 0.6f, 0.3f, 1.0f};
    ImGui::TextColored(set ? lit : ImVec4{0.30f, 0.75f, 0.45f, 1.0f}, set ? "\xE2\x80\xA2" : "\xE2\x80\xA2");
    ImGui::SameLine();
    ImGui::Text("bit %u %s", static_cast<unsigned>(info.bit), std::string(info.name).c_str());
    if (set) {
      ImGui::SameLine();
      ImGui::TextColored(lit, "SET");
    }
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", std::string(info.meaning).c_str());
  }
}

}  // namespace

void draw_device_panel(UiModel& m, Session& session) {
  if (!ImGui::CollapsingHeader("Device", ImGuiTreeNodeFlags_DefaultOpen)) return;
  const SessionSnapshot& s = m.snap;
  if (!s.device) {
    ImGui::TextDisabled("no device information yet");
    return;
  }
  const DeviceDetails& d = *s.device;
  char text[96];
  if (ImGui::BeginTable("device", 2, ImGuiTableFlags_SizingStretchProp)) {
    row("model", d.profile ? std::string(d.profile->name).c_str() : "unknown");
    std::snprintf(text, sizeof text, "%u", static_cast<unsigned>(d.model_code));
    row("model code", text);
    std::snprintf(text, sizeof text, "%u.%u", static_cast<unsigned>(d.firmware.major), static_cast<unsigned>(d.firmware.minor));
    row("firmware", text);
    std::snprintf(text, sizeof text, "%u", static_cast<unsigned>(d.hardware));
    row("hardware", text);
    row("serial", d.serial.c_str());
    std::snprintf(text, sizeof text, "%g mm per count", s.distance_scale);
    row("distance scale", text);
    ImGui::EndTable();
  }
  // Some firmware uses another scale than its manual; let the user correct it live.
  if (ImGui::Checkbox("override scale", &m.distance_scale_override)) {
    if (m.distance_scale_override) {
      m.distance_scale_value = static_cast<float>(s.distance_scale > 0 ? s.distance_scale : 1.0);
      session.set_distance_scale(m.distance_scale_value);
    } else {
      session.set_distance_scale(std::nullopt);
    }
  }
  help_marker("The manuals give G6 S/4 and TG S/2 mm per count; some vendor firmware uses S/2 (G6) or S (TG above 1.2). "
              "If walls look twice too near or far, change the scale here.");
  if (m.distance_scale_override) {
    ImGui::SameLine();
    ImGui::SetNextItemWidth(110.0f);
    if (ImGui::InputFloat("##scale", &m.distance_scale_value, 0.0f, 0.0f, "%.3f", ImGuiInputTextFlags_EnterReturnsTrue) &&
        m.distance_scale_value > 0.0f) {
      session.set_distance_scale(m.distance_scale_value);
    }
  }
}

void draw_health_panel(UiModel& m, Session& session) {
  if (!ImGui::CollapsingHeader("Health", ImGuiTreeNodeFlags_DefaultOpen)) return;
  const SessionSnapshot& s = m.snap;
  const Model model = s.device && s.device->profile ? s.device->profile->model : Model::G6;

  if (reports_health_bits(model)) {
    section("live, from CT (every lap)");
    if (m.ct_health) {
      if (!m.ct_health_trusted) {
        ImGui::TextColored({1.0f, 0.7f, 0.3f, 1.0f}, "untrusted: this lap's CRC8 failed");
        help_marker("G1 spreads health over the packets of a lap; when the LastCRC byte disagrees a packet was lost, so the CT information may belong to another index.");
      }
      bit_lamps(model, *m.ct_health, m.ct_health_trusted);
    } else {
      ImGui::TextDisabled("no lap has carried health yet");
    }
  }

  section(s.health ? (s.health->command == Command::HealthStatusBits ? "A5 92 answer" : "A5 91 answer") : "health command");
  if (s.health) {
    const HealthReport& h = *s.health;
    if (reports_health_bits(model)) {
      bit_lamps(model, h.status, true);
    } else {
      const HealthStatusInfo info = health_status_info(h.status);
      ImGui::TextColored(info.is_problem ? ImVec4{1.0f, 0.4f, 0.35f, 1.0f} : ImVec4{0.35f, 0.9f, 0.55f, 1.0f}, "status %u: %s",
                         static_cast<unsigned>(h.status), std::string(info.name).c_str());
      ImGui::TextDisabled("%s", std::string(info.meaning).c_str());
      ImGui::Text("error code 0x%04X", static_cast<unsigned>(h.error_code));
    }
    if (!h.summary.empty()) ImGui::TextDisabled("device says: %s", h.summary.c_str());
  } else {
    ImGui::TextDisabled("not asked yet");
  }
  const bool connected = link_state_connected(s.state);
  if (!connected || s.busy) ImGui::BeginDisabled();
  if (ImGui::Button("Ask health now")) session.refresh_health();
  if (!connected || s.busy) ImGui::EndDisabled();

  if (ImGui::TreeNode("timeline", "timeline (%zu changes)", m.timeline.events().size())) {
    if (ImGui::BeginChild("timeline", {0.0f, 120.0f}, true)) {
      const auto& events = m.timeline.events();
      for (auto it = events.rbegin(); it != events.rend(); ++it) {
        ImGui::TextDisabled("%8.1f s", it->time_s);
        ImGui::SameLine();
        ImGui::Text("%s: %s", it->source.c_str(), it->text.c_str());
      }
    }
    ImGui::EndChild();
    ImGui::TreePop();
  }
}

}  // namespace ydscope::ui
