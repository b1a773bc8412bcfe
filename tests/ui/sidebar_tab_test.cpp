// The sidebar opens on the tab it was left on: the open tab goes into the view settings, which
// settings.ini keeps, and the next run asks the sidebar for it.
#include <gtest/gtest.h>

#include <imgui.h>

#include "ui/panels/panels.h"
#include "ui/view/settings/settings.h"
#include "tests/ui/headless_imgui.h"

namespace ydscope::ui {
namespace {

// Draws the sidebar for a few frames, asking for `asked` (-1: nothing) in the first.
void draw_frames(UiModel& m, ViewSettings& settings, int asked) {
  PanelEdits edits;
  for (int frame = 0; frame < 3; ++frame) {
    ImGui::GetIO().DeltaTime = 1.0f / 60.0f;
    ImGui::NewFrame();
    if (frame == 0) m.show_sidebar_tab = asked;
    draw_sidebar(m, edits, settings);
    ImGui::Render();
  }
}

TEST(SidebarTab, TheOpenTabIsWhatTheSettingsKeep) {
  HeadlessImGui imgui(1280.0f, 800.0f);
  UiModel m;
  ViewSettings settings;
  settings.sidebar_tab = SidebarTab::View;  // as if read from a file; the first tab is what opens
  draw_frames(m, settings, -1);
  EXPECT_EQ(settings.sidebar_tab, SidebarTab::Lidar);
  for (const SidebarTab tab : {SidebarTab::Statistics, SidebarTab::Sources, SidebarTab::View}) {
    draw_frames(m, settings, static_cast<int>(tab));
    EXPECT_EQ(settings.sidebar_tab, tab) << sidebar_tab_word(tab);
  }
}

TEST(SidebarTab, SettingsIniKeepsItsWordAndAnUnknownWordOpensTheFirstTab) {
  ViewSettings settings;
  settings.sidebar_tab = SidebarTab::Statistics;
  const std::string text = format_settings(settings);
  EXPECT_NE(text.find("sidebar_tab = statistics\n"), std::string::npos) << text;
  EXPECT_EQ(parse_settings(text).sidebar_tab, SidebarTab::Statistics);
  EXPECT_EQ(parse_settings("sidebar_tab = sources\n").sidebar_tab, SidebarTab::Sources);
  std::vector<std::string> notes;
  EXPECT_EQ(parse_settings("sidebar_tab = plots\n", &notes).sidebar_tab, SidebarTab::Lidar);
  ASSERT_EQ(notes.size(), 1u) << "a word it does not know is said, as other settings' are";
  EXPECT_NE(notes[0].find("sidebar_tab = plots"), std::string::npos) << notes[0];
}

}  // namespace
}  // namespace ydscope::ui
