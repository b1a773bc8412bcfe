// Device (what the lidar says it is) and Health (what it says about itself, bit by bit).
#include <cstdio>
#include <optional>

#include <imgui.h>

#include "core/protocol/commands.h"
#include "ui/panels/panels.h"
#include "ui/view/status/health_names.h"

namespace ydscope::ui {
namespace {

// A name and its value in the next two columns of the current table row.
void cell(const char* name, const char* value) {
  ImGui::TableNextColumn();
  ImGui::TextDisabled("%s", name);
  ImGui::TableNextColumn();
  ImGui::TextUnformatted(value);
}

void row(const char* name, const char* value) {
  ImGui::TableNextRow();
  cell(name, value);
}

// A round lamp in the current line: red when the bit is set (amber when untrusted), green when clear,
// grey when unknown. A stale one is a ring of its last colour: what it was, plainly not what it is.
void lamp(std::optional<bool> set, bool trusted, bool stale = false) {
  const float r = ImGui::GetTextLineHeight() * 0.32f;
  const ImVec2 p = ImGui::GetCursorScreenPos();
  const ImVec2 c{p.x + r + 2.0f, p.y + ImGui::GetTextLineHeight() * 0.5f};
  ImU32 colour = IM_COL32(90, 95, 105, 255);
  if (set)
    colour = *set ? (trusted ? IM_COL32(255, 80, 70, 255) : IM_COL32(230, 160, 60, 255)) : IM_COL32(70, 200, 110, 255);
  if (stale)
    ImGui::GetWindowDrawList()->AddCircle(c, r, colour, 16, 1.5f);
  else
    ImGui::GetWindowDrawList()->AddCircleFilled(c, r, colour, 16);
  ImGui::Dummy({2.0f * r + 4.0f, ImGui::GetTextLineHeight()});
}

// G1: one row per module bit, with the live CT value and the A5 92 answer side by side.
void bit_table(Model model, std::optional<std::uint8_t> ct, bool ct_trusted, std::optional<std::uint8_t> answer,
               bool stale) {
  if (!ImGui::BeginTable("bits", 3, ImGuiTableFlags_SizingStretchProp | ImGuiTableFlags_RowBg)) return;
  ImGui::TableSetupColumn("module");
  ImGui::TableSetupColumn("CT");
  ImGui::TableSetupColumn("A5 92");
  ImGui::TableHeadersRow();
  for (const HealthBitInfo& info : health_bits(model)) {
    ImGui::TableNextRow();
    ImGui::TableSetColumnIndex(0);
    ImGui::Text("%u %s", static_cast<unsigned>(info.bit), std::string(info.name).c_str());
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("when set: %s", std::string(info.meaning).c_str());
    ImGui::TableSetColumnIndex(1);
    lamp(ct ? std::optional<bool>(((*ct >> info.bit) & 1u) != 0) : std::nullopt, ct_trusted, stale);
    ImGui::TableSetColumnIndex(2);
    lamp(answer ? std::optional<bool>(((*answer >> info.bit) & 1u) != 0) : std::nullopt, true, stale);
  }
  ImGui::EndTable();
  // Spell out what is wrong, so nobody has to hover to find out.
  const std::uint8_t any = static_cast<std::uint8_t>(ct.value_or(0) | answer.value_or(0));
  for (const HealthBitInfo& info : health_bits(model)) {
    if ((any >> info.bit) & 1u) {
      ImGui::PushTextWrapPos(0.0f);
      ImGui::TextColored({1.0f, 0.45f, 0.4f, 1.0f}, "%s: %s", std::string(info.name).c_str(),
                         std::string(info.meaning).c_str());
      ImGui::PopTextWrapPos();
    }
  }
}

}  // namespace

void draw_device_panel(UiModel& m, PanelEdits& e) {
  if (!ImGui::CollapsingHeader("Device", ImGuiTreeNodeFlags_DefaultOpen)) return;
  const SessionSnapshot& s = m.snap;
  if (!s.device) {
    ImGui::TextDisabled("no device information yet");
    return;
  }
  const DeviceDetails& d = *s.device;
  char text[96];
  // Short values two to a row, so the Lidar tab fits an 800 px window (tests/ui/sidebar_fit_test).
  if (ImGui::BeginTable("device-short", 4, ImGuiTableFlags_SizingStretchProp)) {
    ImGui::TableNextRow();
    cell("model", d.profile ? std::string(d.profile->name).c_str() : "unknown");
    std::snprintf(text, sizeof text, "%u", static_cast<unsigned>(d.model_code));
    cell("model code", text);
    ImGui::TableNextRow();
    std::snprintf(text, sizeof text, "%u.%u", static_cast<unsigned>(d.firmware.major),
                  static_cast<unsigned>(d.firmware.minor));
    cell("firmware", text);
    std::snprintf(text, sizeof text, "%u", static_cast<unsigned>(d.hardware));
    cell("hardware", text);
    ImGui::EndTable();
  }
  if (ImGui::BeginTable("device", 2, ImGuiTableFlags_SizingStretchProp)) {
    row("serial", d.serial.c_str());
    std::snprintf(text, sizeof text, "%g mm per count", s.distance_scale);
    row("distance scale", text);
    ImGui::EndTable();
  }
  // Long enough to wrap, so it sits under the table rather than in its narrow value column.
  if (s.conventions) ImGui::TextWrapped("read as: %s", std::string(s.conventions->label).c_str());
  // Where the manual and real units differ (G6, TG), the user picks whose word counts.
  if (s.conventions && d.profile && d.profile->model != Model::G1) {
    bool manual = s.conventions->reading == Reading::Manual;
    if (ImGui::Checkbox("read as the manual says", &manual))
      m.requests.push_back(SetReading{manual ? Reading::Manual : Reading::Field});
    help_marker(
        "Off (default): read the unit as real units of its model and firmware write, as the vendor SDK reads "
        "them (G6 S/2 mm at 18 k samples/s; TG S mm without the triangulation correction). On: as its manual "
        "says (G6 S/4, TG S/2). docs/conventions.md gives every value and its source.");
  }
  // Some firmware uses another scale than its manual; let the user correct it live.
  if (ImGui::Checkbox("override scale", &e.distance_scale_override)) {
    if (e.distance_scale_override) {
      e.distance_scale_value = static_cast<float>(s.distance_scale > 0 ? s.distance_scale : 1.0);
      m.requests.push_back(SetDistanceScale{static_cast<double>(e.distance_scale_value)});
    } else {
      m.requests.push_back(SetDistanceScale{});
    }
  }
  help_marker(
      "The conventions above set the scale from the unit's model and firmware. If walls still look twice too "
      "near or far, override it here.");
  if (e.distance_scale_override) {
    ImGui::SameLine();
    ImGui::SetNextItemWidth(110.0f);
    if (ImGui::InputFloat("##scale", &e.distance_scale_value, 0.0f, 0.0f, "%.3f",
                          ImGuiInputTextFlags_EnterReturnsTrue) &&
        e.distance_scale_value > 0.0f) {
      m.requests.push_back(SetDistanceScale{static_cast<double>(e.distance_scale_value)});
    }
  }
  // Run check ends the panel's last line: the check judges the unit described above.
  ImGui::SameLine();
  draw_run_check_button(m);
}

void draw_health_panel(UiModel& m) {
  if (!draw_health_header(m)) return;
  const SessionSnapshot& s = m.snap;
  const Model model = s.device && s.device->profile ? s.device->profile->model : Model::G6;
  const StaleValues stale(m);

  if (reports_health_bits(model)) {
    std::optional<std::uint8_t> answer;
    if (s.health) answer = s.health->status;
    bit_table(model, m.ct_health, m.ct_health_trusted, answer, stale.stale());
    if (m.ct_health && !m.ct_health_trusted) {
      ImGui::TextColored({1.0f, 0.7f, 0.3f, 1.0f}, "CT health untrusted: the lap's CRC8 failed");
      help_marker(
          "G1 spreads health over the packets of a lap; when the LastCRC byte disagrees a packet was lost, so the CT "
          "information may belong to another index.");
    }
    ImGui::TextDisabled("CT: live, every lap.  A5 92: asked at connect.");
  } else if (s.health) {
    const HealthReport& h = *s.health;
    const HealthStatusInfo info = health_status_info(h.status);
    lamp(info.is_problem, true, stale.stale());
    ImGui::SameLine();
    ImGui::TextColored(
        stale.colour(info.is_problem ? ImVec4{1.0f, 0.4f, 0.35f, 1.0f} : ImVec4{0.35f, 0.9f, 0.55f, 1.0f}),
        "%s status %u: %s", h.command == Command::HealthStatusBits ? "A5 92" : "A5 91", static_cast<unsigned>(h.status),
        std::string(info.name).c_str());
    // What the status means: in the panel when it is a problem, one hover away when it is not.
    if (info.is_problem)
      wrapped_text(std::string(info.meaning).c_str());
    else if (ImGui::IsItemHovered())
      ImGui::SetTooltip("%s", std::string(info.meaning).c_str());
    ImGui::Text("error code 0x%04X", static_cast<unsigned>(h.error_code));
    if (!h.summary.empty()) {
      ImGui::SameLine();
      ImGui::TextDisabled("  device says: %s", h.summary.c_str());
    }
  } else {
    ImGui::TextDisabled("not asked yet");
  }
  if (reports_health_bits(model) && s.health && !s.health->summary.empty())
    ImGui::TextDisabled("device says: %s", s.health->summary.c_str());
  const bool can_ask = link_state_connected(s.state) && !s.busy && !m.replay.available;
  if (!can_ask) ImGui::BeginDisabled();
  if (ImGui::Button("Ask health now")) m.requests.push_back(RefreshHealth{});
  if (!can_ask) ImGui::EndDisabled();
  command_feedback_line(m, CommandControl::Health);

  if (ImGui::TreeNode("timeline", "timeline (%d changes)", static_cast<int>(m.timeline.events().size()))) {
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
