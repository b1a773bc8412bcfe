// An unchanged frame is recognised, so the app skips rendering it; any visible change is not
// mistaken for one. The real sidebar panels lay out in a headless ImGui context.
#include <gtest/gtest.h>

#include <imgui.h>

#include "tests/ui/headless_imgui.h"
#include "ui/panels/panels.h"
#include "ui/render/draw_signature.h"

namespace ydscope::ui {
namespace {

// The signature of the sidebar's frame for `m` (after a frame that settles the layout).
std::uint64_t sidebar_signature(UiModel& m, ViewSettings& settings) {
  std::uint64_t signature = 0;
  PanelEdits edits;
  for (int frame = 0; frame < 2; ++frame) {
    ImGui::GetIO().DeltaTime = 1.0f / 60.0f;
    ImGui::NewFrame();
    draw_sidebar(m, edits, settings);
    ImGui::Render();
    signature = draw_signature(*ImGui::GetDrawData());
  }
  return signature;
}

TEST(DrawSignature, AFrameThatRepeatsTheLastHasItsSignatureAndAnyChangeChangesIt) {
  HeadlessImGui imgui(1280.0f, 800.0f);
  UiModel m;
  m.snap.state = LinkState::Reconnecting;
  m.snap.scan_hz = 8.0;
  ViewSettings settings;
  const std::uint64_t first = sidebar_signature(m, settings);
  EXPECT_EQ(sidebar_signature(m, settings), first) << "nothing changed, so the frame need not be drawn";

  m.snap.scan_hz = 8.1;  // one digit of one number in the Scan frequency panel
  const std::uint64_t new_rate = sidebar_signature(m, settings);
  EXPECT_NE(new_rate, first);

  m.snap.state = LinkState::Scanning;  // a word and its colour
  EXPECT_NE(sidebar_signature(m, settings), new_rate);
}

TEST(DrawSignature, MixingInTheGlLayerSeparatesFramesImGuiAloneWouldNot) {
  EXPECT_NE(mix_signature(1, 2), mix_signature(1, 3));
  EXPECT_NE(mix_signature(1, 2), mix_signature(2, 2));
}

}  // namespace
}  // namespace ydscope::ui
