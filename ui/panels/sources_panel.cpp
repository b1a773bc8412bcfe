// Several lidars: which one the panels show, and the Sources tab that lists, places, hides,
// pauses, adds and removes them. Every change is a request the app carries out after the frame.
#include <cstdio>
#include <string>

#include <imgui.h>

#include "core/protocol/model_profile.h"
#include "ui/panels/panels.h"

namespace ydscope::ui {
namespace {

ImVec4 swatch_colour(Rgba8 c) { return {c.r / 255.0f, c.g / 255.0f, c.b / 255.0f, 1.0f}; }

void swatch(Rgba8 colour) {
  ImGui::ColorButton("##colour", swatch_colour(colour), ImGuiColorEditFlags_NoTooltip | ImGuiColorEditFlags_NoDragDrop,
                     {ImGui::GetFontSize(), ImGui::GetFontSize()});
}

// Position in metres and yaw in degrees, as --pose spells them (REP-103: x forward, y left, yaw
// counter-clockwise); each edit is sent at once.
void pose_fields(UiModel& m, PanelEdits& e, std::size_t index, const SourceLook& look) {
  SourceLook edited = look;
  float xy[2] = {static_cast<float>(look.pose.x_m), static_cast<float>(look.pose.y_m)};
  float yaw = static_cast<float>(look.pose.yaw_deg);
  float offset = static_cast<float>(look.pose.angle_offset_deg);
  bool changed = ImGui::DragFloat2("x fwd, y left m", xy, 0.01f, -static_cast<float>(kMaxPoseOffsetM),
                                   static_cast<float>(kMaxPoseOffsetM), "%.2f");
  changed |= ImGui::DragFloat("yaw deg ccw", &yaw, 0.5f, -360.0f, 360.0f, "%.1f");
  changed |= ImGui::Checkbox("upside down", &edited.pose.upside_down);
  changed |= ImGui::DragFloat("angle offset deg", &offset, 0.1f, -360.0f, 360.0f, "%.1f");
  help_marker(
      "Added to the unit's own angles (clockwise, as they run): where its 0 really points. The view marks "
      "each unit's 0 and the way it sweeps.");
  if (ImGui::Button(e.forward_click_armed ? "click the view: straight ahead..." : "set straight ahead by click"))
    e.forward_click_armed = !e.forward_click_armed;
  help_marker(
      "Then click a point of this lidar's cloud that lies straight ahead of the robot (a wall you know is "
      "ahead): its yaw turns so that point lies on the robot's forward axis. Click the button again to cancel.");
  help_marker(
      "Where the lidar sits on the robot, as ROS says it (REP-103): x forward, y to the left, yaw "
      "counter-clockwise from forward. At yaw 0 the unit's 180 degrees points forward, as the ROS "
      "driver's laser frame has it; the view draws forward up.");
  if (!changed) return;
  edited.pose.x_m = xy[0];
  edited.pose.y_m = xy[1];
  edited.pose.yaw_deg = yaw;
  edited.pose.angle_offset_deg = offset;
  m.requests.push_back(SetSourceLook{index, edited});
}

// Align, and its answer waiting for the user's word: nothing moves until Apply.
void alignment_controls(UiModel& m) {
  if (!m.several_sources()) return;
  section("align");
  if (!m.alignment) {
    if (ImGui::Button("Align")) m.requests.push_back(AlignSources{});
    help_marker(
        "Finds where each lidar sits relative to the first in the list, from the walls they both see "
        "(their last 10 laps, searched within 45 degrees and 1 m of each one's pose now). "
        "Nothing moves until you apply it.");
    return;
  }
  for (const AlignedSource& row : m.alignment->rows) ImGui::TextWrapped("%s", row.text.c_str());
  if (!m.alignment->any_found()) ImGui::BeginDisabled();
  if (ImGui::Button("Apply")) m.requests.push_back(AnswerAlignment{true});
  if (!m.alignment->any_found()) ImGui::EndDisabled();
  ImGui::SameLine();
  if (ImGui::Button("Discard")) m.requests.push_back(AnswerAlignment{false});
}

void add_source_controls(UiModel& m, PanelEdits& e) {
  static constexpr const char* kScenes[] = {"room", "demo", "booth"};
  section("add a source");
  ImGui::RadioButton("virtual lidar", &e.add_source_kind, 0);
  ImGui::SameLine();
  ImGui::RadioButton("port", &e.add_source_kind, 1);
  ImGui::SameLine();
  ImGui::RadioButton("recording", &e.add_source_kind, 2);
  AddSource add;
  if (e.add_source_kind == 0) {
    model_combo("model##add", e.add_source_model_choice, nullptr);
    ImGui::Combo("scene##add", &e.add_source_scene_choice, kScenes, IM_ARRAYSIZE(kScenes));
    add.request.kind = ConnectRequest::Kind::Sim;
    add.request.model = std::string(all_profiles()[static_cast<std::size_t>(e.add_source_model_choice - 1)].name);
    add.request.scene = kScenes[e.add_source_scene_choice];
  } else {
    // A port path or tcp://host:port, or a .ydrec to play round and round.
    ImGui::InputText(e.add_source_kind == 1 ? "address##add" : "file##add", e.add_source_address,
                     sizeof e.add_source_address);
    add.request.kind = e.add_source_kind == 1 ? ConnectRequest::Kind::Port : ConnectRequest::Kind::Replay;
    add.request.address = e.add_source_address;
  }
  const bool ready = e.add_source_kind == 0 || e.add_source_address[0] != '\0';
  if (!ready) ImGui::BeginDisabled();
  if (ImGui::Button("Add")) m.requests.push_back(add);
  if (!ready) ImGui::EndDisabled();
}

}  // namespace

void draw_source_selector(UiModel& m) {
  if (!m.several_sources() || m.selected_source >= m.sources.size()) return;
  const SourceRow& current = m.sources[m.selected_source];
  swatch(current.look.colour);
  ImGui::SameLine();
  if (ImGui::BeginCombo("panels show", current.look.name.c_str())) {
    for (std::size_t i = 0; i < m.sources.size(); ++i) {
      ImGui::PushID(static_cast<int>(i));
      swatch(m.sources[i].look.colour);
      ImGui::SameLine();
      if (ImGui::Selectable(m.sources[i].legend.c_str(), i == m.selected_source)) m.requests.push_back(SelectSource{i});
      ImGui::PopID();
    }
    ImGui::EndCombo();
  }
  help_marker("The Lidar, View and Statistics panels show this source, and their commands go to it only.");
}

void draw_sources_panel(UiModel& m, PanelEdits& e) {
  for (std::size_t i = 0; i < m.sources.size(); ++i) {
    const SourceRow& row = m.sources[i];
    ImGui::PushID(static_cast<int>(i));
    swatch(row.look.colour);
    ImGui::SameLine();
    if (ImGui::Selectable(row.legend.c_str(), i == m.selected_source)) m.requests.push_back(SelectSource{i});
    SourceLook look = row.look;
    if (ImGui::Checkbox("hide", &look.hidden)) m.requests.push_back(SetSourceLook{i, look});
    ImGui::SameLine();
    if (ImGui::Checkbox("pause", &look.paused)) m.requests.push_back(SetSourceLook{i, look});
    if (m.several_sources()) {
      ImGui::SameLine();
      if (ImGui::SmallButton("remove")) m.requests.push_back(RemoveSource{i});
    }
    // The unit this name and pose belong to: they follow it to any port (docs/identity.md).
    if (!row.look.serial.empty()) ImGui::TextDisabled("unit serial %s", row.look.serial.c_str());
    if (i == m.selected_source) {
      pose_fields(m, e, i, row.look);
      ImGui::TextDisabled("Alt+drag on the view moves it, Ctrl+drag turns it");
    }
    ImGui::Separator();
    ImGui::PopID();
  }
  alignment_controls(m);
  add_source_controls(m, e);
}

}  // namespace ydscope::ui
