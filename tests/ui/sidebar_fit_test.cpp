// The sidebar's key panels (connection, device, health, scan frequency, filter, statistics) are
// reachable without scrolling in an 800 px tall window: each tab's panels fit, laid out by the real
// panel code in a real ImGui context with the app's fonts (no display needed: nothing is drawn).
#include <gtest/gtest.h>

#include <imgui.h>

#include "core/protocol/model_profile.h"
#include "ui/panels/panels.h"
#include "tests/ui/headless_imgui.h"

namespace ydscope::ui {
namespace {

// A G6 on a port, scanning, every panel with what a real session fills in.
UiModel busy_model() {
  UiModel m;
  m.snap.state = LinkState::Scanning;
  m.snap.link = "/dev/ttyUSB0 at 512000 baud";
  m.snap.baud = 512000;
  DeviceDetails device;
  device.profile = find_profile("G6");
  device.model_code = 13;
  device.firmware = {1, 2};
  device.hardware = 1;
  device.serial = "2020091600030005";
  m.snap.device = device;
  m.snap.health = HealthReport{Command::HealthStatusCode, 0, 0, "ok"};
  m.snap.scan_hz = 8.0;
  m.snap.ranging_khz = 18;
  m.snap.distance_scale = 0.25;
  m.source_text = "/dev/ttyUSB0";
  m.show_source_tab = 0;
  return m;
}

// The sidebar's scroll range after a few frames on `tab` (a frame settles the layout).
float scroll_needed(UiModel& m, SidebarTab tab) {
  ViewSettings settings;
  PanelEdits edits;
  float scroll = 0.0f;
  for (int frame = 0; frame < 4; ++frame) {
    ImGui::GetIO().DeltaTime = 1.0f / 60.0f;
    ImGui::NewFrame();
    if (frame == 0) m.show_sidebar_tab = static_cast<int>(tab);
    draw_sidebar(m, edits, settings);
    ImGui::Begin("ydscope");  // the sidebar's window again, to read what it measured
    scroll = ImGui::GetScrollMaxY();
    ImGui::End();
    ImGui::Render();
  }
  return scroll;
}

TEST(SidebarFit, EveryTabFitsAnEightHundredPixelWindow) {
  HeadlessImGui imgui(1280.0f, 800.0f);
  UiModel m = busy_model();
  for (const SidebarTab tab : {SidebarTab::Lidar, SidebarTab::View, SidebarTab::Statistics})
    EXPECT_LE(scroll_needed(m, tab), 0.0f) << "tab " << static_cast<int>(tab) << " needs scrolling at 800 px";
}

// Several lidars: the selector over the tabs takes a line, and every tab must still fit.
TEST(SidebarFit, EveryTabFitsWithTheSourceSelectorToo) {
  HeadlessImGui imgui(1280.0f, 800.0f);
  UiModel m = busy_model();
  for (const char* name : {"G1", "G6", "TG30"}) {
    SourceRow row;
    row.look.name = name;
    row.look.colour = source_colour(m.sources.size());
    row.legend = std::string(name) + ": scanning";
    m.sources.push_back(row);
  }
  for (const SidebarTab tab : {SidebarTab::Lidar, SidebarTab::View, SidebarTab::Statistics})
    EXPECT_LE(scroll_needed(m, tab), 0.0f) << "tab " << static_cast<int>(tab) << " needs scrolling at 800 px";
}

TEST(SidebarFit, TheSidebarLeavesTheViewMostOfASmallWindow) {
  HeadlessImGui imgui(1024.0f, 568.0f);
  UiModel m = busy_model();
  ViewSettings settings;
  PanelEdits edits;
  float width = 0.0f;
  for (int frame = 0; frame < 2; ++frame) {
    ImGui::GetIO().DeltaTime = 1.0f / 60.0f;
    ImGui::NewFrame();
    width = draw_sidebar(m, edits, settings);
    ImGui::Render();
  }
  EXPECT_LE(width, 0.4f * 1024.0f + 1.0f);
  EXPECT_GE(width, 280.0f) << "still wide enough to read";
}

}  // namespace
}  // namespace ydscope::ui
