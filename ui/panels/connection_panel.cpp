// Connection: where the bytes come from (a port, the virtual lidar, a recording), recording, and
// sharing the source with Foxglove.
#include <algorithm>
#include <cstdio>
#include <cstring>
#include <filesystem>

#include <imgui.h>

#include "core/protocol/model_profile.h"
#include "ui/panels/panels.h"
#include "ui/view/export/file_names.h"

namespace ydscope::ui {
namespace {

constexpr const char* kBauds[] = {"model default", "115200", "128000", "230400", "512000"};
constexpr std::uint32_t kBaudValues[] = {0, 115200, 128000, 230400, 512000};
constexpr const char* kScenes[] = {"room", "demo", "booth"};
constexpr const char* kHosts[] = {"manual only", "YDLidar-SDK host"};
constexpr const char* kDeliveries[] = {"whole packets", "USB bursts", "random splits"};

// `none`: what choice 0 means ("detect"), or null when a model must be chosen.
std::string model_label(int choice, const char* none = "detect") {
  const auto profiles = all_profiles();
  if (choice <= 0 || choice > static_cast<int>(profiles.size())) return none ? none : "";
  return std::string(profiles[static_cast<std::size_t>(choice - 1)].name);
}

void port_section(UiModel& m, PanelEdits& e) {
  ImGui::TextDisabled("Serial port or tcp://host:port");
  if (ImGui::BeginCombo("##ports", e.port_text[0] ? e.port_text : "choose a port")) {
    if (m.ports.empty()) ImGui::TextDisabled("no serial ports found");
    for (const PortEntry& p : m.ports) {
      if (ImGui::Selectable(p.label.c_str(), p.path == e.port_text)) {
        std::snprintf(e.port_text, sizeof e.port_text, "%s", p.path.c_str());
      }
    }
    ImGui::EndCombo();
  }
  ImGui::SameLine();
  if (ImGui::SmallButton("rescan")) m.requests.push_back(RefreshPorts{});
  ImGui::InputText("address", e.port_text, sizeof e.port_text);
  model_combo("model", e.port_model_choice, "detect");
  ImGui::Combo("baud", &e.port_baud_choice, kBauds, IM_ARRAYSIZE(kBauds));
  const bool can_connect = e.port_text[0] != '\0';
  if (!can_connect) ImGui::BeginDisabled();
  if (ImGui::Button("Connect")) {
    ConnectRequest r;
    r.kind = ConnectRequest::Kind::Port;
    r.address = e.port_text;
    if (e.port_model_choice > 0) r.model = model_label(e.port_model_choice);
    if (e.port_baud_choice > 0) r.baud = kBaudValues[e.port_baud_choice];
    m.requests.push_back(r);
  }
  if (!can_connect) ImGui::EndDisabled();
  ImGui::SameLine();
  if (ImGui::Button("Disconnect")) m.requests.push_back(Disconnect{});
}

// For testing other host software against the virtual lidar (docs/virtual-lidar.md, "As a
// vendor-SDK test double"); applies when the virtual lidar starts.
void host_section(PanelEdits& e) {
  if (!ImGui::TreeNode("host")) return;
  ImGui::Combo("answers", &e.sim_host_choice, kHosts, IM_ARRAYSIZE(kHosts));
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "YDLidar-SDK host: also answers what YDLIDAR's SDK and ROS 2 driver ask beyond\n"
        "the manual (A5 92 on G6/TG, A5 93, ...), so they start without timeouts.");
  const bool g1 = model_label(e.sim_model_choice) == "G1";  // its CT carries major 0..3, minor 0..31
  ImGui::InputInt2("firmware", e.sim_firmware);
  e.sim_firmware[0] = std::clamp(e.sim_firmware[0], 0, g1 ? 3 : 255);
  e.sim_firmware[1] = std::clamp(e.sim_firmware[1], 0, g1 ? 31 : 255);
  if (ImGui::IsItemHovered())
    ImGui::SetTooltip(
        "major.minor in the manual's byte order; YDLidar-SDK reads it the other way round\n"
        "and picks TG's distance scale from it (1.1: S/2 mm as the manual, 1.2 and above: S mm)");
  ImGui::Combo("delivery", &e.sim_delivery_choice, kDeliveries, IM_ARRAYSIZE(kDeliveries));
  if (e.sim_delivery_choice == 1) {
    ImGui::InputInt("burst bytes", &e.sim_burst_bytes);
    ImGui::InputInt("latency timer us", &e.sim_burst_interval_us, 100, 1000);
  } else if (e.sim_delivery_choice == 2) {
    ImGui::InputInt("largest write", &e.sim_random_max);
  }
  e.sim_burst_bytes = std::clamp(e.sim_burst_bytes, 1, 4096);
  e.sim_burst_interval_us = std::clamp(e.sim_burst_interval_us, 1, 1'000'000);
  e.sim_random_max = std::clamp(e.sim_random_max, 1, 4096);
  ImGui::TextDisabled("applies when the virtual lidar starts");
  ImGui::TreePop();
}

void sim_section(UiModel& m, PanelEdits& e) {
  model_combo("sim model", e.sim_model_choice, nullptr);
  ImGui::Combo("scene", &e.sim_scene_choice, kScenes, IM_ARRAYSIZE(kScenes));
  if (ImGui::TreeNode("faults")) {
    float corrupt = static_cast<float>(e.sim_faults.corrupt_byte_rate * 1e3);
    float drop = static_cast<float>(e.sim_faults.drop_byte_rate * 1e3);
    float lost = static_cast<float>(e.sim_faults.lost_packet_rate * 1e2);
    bool changed = false;
    changed |= ImGui::SliderFloat("corrupt /1000 B", &corrupt, 0.0f, 10.0f, "%.2f");
    changed |= ImGui::SliderFloat("drop /1000 B", &drop, 0.0f, 10.0f, "%.2f");
    changed |= ImGui::SliderFloat("lost packets %", &lost, 0.0f, 20.0f, "%.1f");
    int bits = e.sim_faults.health_bits;
    changed |= ImGui::InputInt("health bits", &bits, 1, 4, ImGuiInputTextFlags_CharsHexadecimal);
    e.sim_faults.corrupt_byte_rate = corrupt * 1e-3;
    e.sim_faults.drop_byte_rate = drop * 1e-3;
    e.sim_faults.lost_packet_rate = lost * 1e-2;
    e.sim_faults.health_bits = static_cast<std::uint8_t>(bits & 0xFF);
    // Something in front of the window: no returns from..to degrees (equal ends: off).
    int blocked[2] = {static_cast<int>(e.sim_faults.blocked_from_deg),
                      static_cast<int>(e.sim_faults.blocked_from_deg + e.sim_faults.blocked_width_deg) % 360};
    changed |= ImGui::InputInt2("blocked from:to \xC2\xB0", blocked);
    for (int& end : blocked) end = ((end % 360) + 360) % 360;
    e.sim_faults.blocked_from_deg = blocked[0];
    e.sim_faults.blocked_width_deg = (blocked[1] - blocked[0] + 360) % 360;
    if (changed && m.sim_active) m.requests.push_back(SetSimFaults{e.sim_faults});
    if (m.sim_active) {
      if (ImGui::SmallButton("unplug")) m.requests.push_back(UnplugSim{});
      ImGui::SameLine();
      if (ImGui::SmallButton("replug")) m.requests.push_back(ReplugSim{});
    }
    ImGui::TreePop();
  }
  host_section(e);
  if (ImGui::Button("Start virtual lidar")) {
    ConnectRequest r;
    r.kind = ConnectRequest::Kind::Sim;
    r.model = model_label(e.sim_model_choice);
    r.scene = kScenes[e.sim_scene_choice];
    r.faults = e.sim_faults;
    r.host_compat = e.sim_host_choice == 1 ? HostCompat::YdlidarSdk : HostCompat::Manual;
    r.firmware_major = static_cast<std::uint8_t>(e.sim_firmware[0]);
    r.firmware_minor = static_cast<std::uint8_t>(e.sim_firmware[1]);
    r.delivery.kind = static_cast<DeliveryKind>(e.sim_delivery_choice);
    r.delivery.burst_bytes = static_cast<std::uint32_t>(e.sim_burst_bytes);
    r.delivery.interval_ns = static_cast<std::int64_t>(e.sim_burst_interval_us) * 1000;
    r.delivery.max_piece = static_cast<std::uint32_t>(e.sim_random_max);
    m.requests.push_back(r);
  }
}

// The recording in the field, decoded as chosen, at the speed and loop the tab shows.
ConnectRequest replay_request(const UiModel& m, const PanelEdits& e) {
  ConnectRequest r;
  r.kind = ConnectRequest::Kind::Replay;
  r.address = e.replay_text;
  if (e.replay_model_choice > 0) r.model = model_label(e.replay_model_choice);
  r.replay_speed = m.replay.speed;
  r.replay_loop = m.replay.loop;
  return r;
}

void replay_section(UiModel& m, PanelEdits& e) {
  ImGui::InputText("recording", e.replay_text, sizeof e.replay_text);
  // For a recording that names no model (or one this ydscope does not know), as --model does.
  model_combo("decode as", e.replay_model_choice, "as recorded");
  if (ImGui::Button("Open recording") && e.replay_text[0]) m.requests.push_back(replay_request(m, e));
  if (m.replay.available && m.replay.ended) {
    // The link is closed at its end: playing again opens the recording anew, as it was set.
    ImGui::SameLine();
    if (ImGui::Button("Play again") && e.replay_text[0]) m.requests.push_back(replay_request(m, e));
    ImGui::TextDisabled("played to the end at %.2fx (loop off)", static_cast<double>(m.replay.speed));
  } else if (m.replay.available) {
    ImGui::SameLine();
    bool changed = false;
    if (ImGui::Button(m.replay.paused ? "Play" : "Pause")) {
      m.replay.paused = !m.replay.paused;
      changed = true;
    }
    changed |= ImGui::SliderFloat("speed", &m.replay.speed, kMinReplaySpeedShown, kMaxReplaySpeedShown, "%.2fx",
                                  ImGuiSliderFlags_Logarithmic);
    changed |= ImGui::Checkbox("loop", &m.replay.loop);
    if (changed)
      m.requests.push_back(ControlReplay{m.replay.paused, static_cast<double>(m.replay.speed), m.replay.loop});
    const float fraction =
        m.replay.duration_s > 0.0 ? static_cast<float>(m.replay.position_s / m.replay.duration_s) : 0.0f;
    char text[48];
    std::snprintf(text, sizeof text, "%.1f / %.1f s", m.replay.position_s, m.replay.duration_s);
    ImGui::ProgressBar(fraction, {-1.0f, 0.0f}, text);
  }
}

// One line per file being written: its size and where it is.
void recording_file_line(const std::string& path) {
  std::error_code ec;
  const auto bytes = std::filesystem::file_size(path, ec);
  ImGui::TextDisabled("%.2f MB", ec ? 0.0 : static_cast<double>(bytes) / 1e6);
  ImGui::SameLine();
  wrapped_text(path.c_str());
}

void record_section(UiModel& m, PanelEdits& e, const SessionSnapshot& s) {
  if (m.recording()) {
    ImGui::TextColored({1.0f, 0.35f, 0.35f, 1.0f}, "\xE2\x80\xA2 REC");
    ImGui::SameLine();
    ImGui::Text("%.1f s", m.now_s - m.record_started_s);
    if (s.recording) recording_file_line(s.recording_path);
    if (m.ydrec_recording.active) recording_file_line(m.ydrec_recording.path);
    if (m.mcap_recording.active) recording_file_line(m.mcap_recording.path);
    if (ImGui::Button("Stop recording")) m.requests.push_back(StopRecording{});
    command_feedback_line(m, CommandControl::Recording);
  } else {
    constexpr const char* kFormats[] = {".ydrec (every byte)", ".mcap (ROS 2 topics)", ".ydrec + .mcap"};
    constexpr const char* kHints[] = {"ydscope-<date>-<time>.ydrec", "ydscope-<date>-<time>.mcap",
                                      "ydscope-<date>-<time>.ydrec"};
    e.record_format = std::clamp(e.record_format, 0, 2);
    ImGui::Combo("format", &e.record_format, kFormats, IM_ARRAYSIZE(kFormats));
    // Empty means a new timestamped name at each start, so no recording overwrites another.
    ImGui::InputTextWithHint("file", kHints[e.record_format], e.record_text, sizeof e.record_text);
    const bool connected = link_state_connected(s.state);
    if (!connected) ImGui::BeginDisabled();
    if (ImGui::Button("Start recording")) {
      const RecordingPaths paths = recording_paths(static_cast<RecordFormat>(e.record_format), e.record_text);
      std::error_code ec;
      std::string taken;
      for (const std::string* path : {&paths.ydrec, &paths.mcap})
        if (!path->empty() && taken.empty() && std::filesystem::exists(*path, ec)) taken = *path;
      if (!taken.empty()) {
        const std::uint64_t ticket = m.feedback->issued(CommandControl::Recording);
        m.feedback->finished(CommandControl::Recording, ticket, false,
                             taken + " already exists; choose another name, or clear the field for a timestamped one.");
      } else {
        m.requests.push_back(StartRecording{paths.ydrec, paths.mcap});
      }
      m.record_started_s = m.now_s;
    }
    if (!connected) ImGui::EndDisabled();
    command_feedback_line(m, CommandControl::Recording);
    help_marker(
        ".ydrec: every byte in both directions, with timestamps, written by the I/O thread; replay it from the "
        "Replay tab. .mcap: /scan, /points, /diagnostics and the link bytes as ROS 2 messages, for Foxglove "
        "and ros2 bag (chunks flushed every second).");
  }
}

// The current source, live to Foxglove: the same topics and parameters as `ydscope-cli serve`.
void share_section(UiModel& m) {
  bool on = m.share.on;
  if (ImGui::Checkbox("share with Foxglove (W)", &on)) m.requests.push_back(SetShare{on});
  if (m.share.on) {
    ImGui::TextColored({0.45f, 0.75f, 1.0f, 1.0f}, "serving");
    ImGui::SameLine();
    ImGui::TextUnformatted(m.share.address.c_str());
    ImGui::TextDisabled("%zu client%s connected", m.share.clients, m.share.clients == 1 ? "" : "s");
  } else if (!m.share.error.empty()) {
    ImGui::PushStyleColor(ImGuiCol_Text, ImVec4{1.0f, 0.6f, 0.35f, 1.0f});
    wrapped_text(m.share.error.c_str());
    ImGui::PopStyleColor();
  }
  help_marker(
      "In Foxglove: Open connection > Foxglove WebSocket > the address above. Serves /scan, /points, "
      "/diagnostics and the link bytes, follows a change of source, and lets the Parameters panel set "
      "scan_hz, ranging_khz, power_down_protection and the G1 filters through the same commands as this "
      "window. Only this machine can connect (127.0.0.1); --share-port picks the port.");
}

}  // namespace

bool model_combo(const char* label, int& choice, const char* none) {
  const auto profiles = all_profiles();
  bool changed = false;
  const int first = none ? 0 : 1;
  if (!none && choice < 1) choice = 1;
  if (ImGui::BeginCombo(label, model_label(choice, none).c_str())) {
    for (int i = first; i <= static_cast<int>(profiles.size()); ++i) {
      if (ImGui::Selectable(model_label(i, none).c_str(), i == choice)) {
        choice = i;
        changed = true;
      }
    }
    ImGui::EndCombo();
  }
  return changed;
}

void draw_connection_panel(UiModel& m, PanelEdits& e) {
  if (!ImGui::CollapsingHeader("Connection", ImGuiTreeNodeFlags_DefaultOpen)) return;
  const SessionSnapshot& s = m.snap;
  ImGui::TextDisabled("source");
  ImGui::SameLine();
  wrapped_text(m.source_text.empty() ? "none" : m.source_text.c_str());
  link_state_text(s.state, s.message.c_str());
  if (!s.link.empty() && s.message.empty()) {
    ImGui::SameLine();
    ImGui::TextDisabled("%s", s.link.c_str());
  } else if (!s.link.empty()) {
    ImGui::TextDisabled("%s", s.link.c_str());
  }
  if (ImGui::BeginTabBar("sources")) {
    const auto tab_flags = [&m](int tab) {
      return m.show_source_tab == tab ? ImGuiTabItemFlags_SetSelected : ImGuiTabItemFlags_None;
    };
    const int wanted = m.show_source_tab;
    if (ImGui::BeginTabItem("Port", nullptr, tab_flags(0))) {
      port_section(m, e);
      ImGui::EndTabItem();
    }
    if (ImGui::BeginTabItem("Virtual", nullptr, tab_flags(1))) {
      sim_section(m, e);
      ImGui::EndTabItem();
    }
    if (ImGui::BeginTabItem("Replay", nullptr, tab_flags(2))) {
      replay_section(m, e);
      ImGui::EndTabItem();
    }
    if (ImGui::BeginTabItem("Record", nullptr, tab_flags(static_cast<int>(SourceTab::Record)))) {
      record_section(m, e, s);
      ImGui::EndTabItem();
    }
    if (ImGui::BeginTabItem("Share", nullptr, tab_flags(static_cast<int>(SourceTab::Share)))) {
      share_section(m);
      ImGui::EndTabItem();
    }
    ImGui::EndTabBar();
    if (wanted == m.show_source_tab) m.show_source_tab = -1;
  }
}

}  // namespace ydscope::ui
