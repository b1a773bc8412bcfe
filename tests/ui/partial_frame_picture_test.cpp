// A frame drawn in parts must be the frame drawn whole. The panels are drawn with ImGui's own GL
// backend into an offscreen picture; a figure changes; only the box DrawDamage names is cleared
// and drawn again (render_imgui_within), over the last frame's picture. Every pixel must then be
// the one a whole redraw gives. Needs the display CTest gives the suite (xvfb-run); skips without.
#include <gtest/gtest.h>

#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <algorithm>
#include <cstdlib>
#include <optional>
#include <vector>

#include "tests/ui/headless_imgui.h"
#include "ui/panels/panels.h"
#include "ui/render/draw_damage.h"
#include "tests/ui/offscreen_gl.h"
#include "ui/render/gl.h"
#include "ui/render/imgui_within.h"

namespace ydscope::ui {
namespace {

constexpr int kWidth = 1280;
constexpr int kHeight = 800;

class PartialFrame : public testing::Test {
 protected:
  void SetUp() override {
    if (!std::getenv("DISPLAY")) GTEST_SKIP() << "no display (the suite runs under xvfb-run)";
    gl_.emplace(kWidth, kHeight);
    ASSERT_TRUE(*gl_) << "no GL 3.3 core context with an offscreen picture on this display";
    imgui_.emplace(static_cast<float>(kWidth), static_cast<float>(kHeight));
    ASSERT_TRUE(ImGui_ImplOpenGL3_Init("#version 330 core"));
    backend_ = true;
  }
  void TearDown() override {
    if (backend_) ImGui_ImplOpenGL3_Shutdown();
    imgui_.reset();
    gl_.reset();
  }

  // Lays out the sidebar for `m`; its draw data is ImGui's until the next frame.
  void lay_out(UiModel& m) {
    ImGui_ImplOpenGL3_NewFrame();
    ImGui::GetIO().DeltaTime = 1.0f / 60.0f;
    ImGui::NewFrame();
    PanelEdits edits;
    draw_sidebar(m, edits, settings_);
    ImGui::Render();
  }
  // Clears `box` and draws the frame's panels inside it, as the app's ViewStage does.
  static void draw(const DisplayBox& box) {
    const PixelBox pixels = to_pixels(box, 1.0f, kHeight);
    glEnable(GL_SCISSOR_TEST);
    glScissor(pixels.x, pixels.y, pixels.width, pixels.height);
    glClearColor(17 / 255.0f, 20 / 255.0f, 26 / 255.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    glDisable(GL_SCISSOR_TEST);
    render_imgui_within(*ImGui::GetDrawData(), box);
  }
  std::vector<unsigned char> picture() const { return gl_->picture(); }
  static std::size_t pixels_differing(const std::vector<unsigned char>& a, const std::vector<unsigned char>& b) {
    std::size_t differ = 0;
    for (std::size_t i = 0; i < a.size(); i += 4)
      differ += a[i] != b[i] || a[i + 1] != b[i + 1] || a[i + 2] != b[i + 2];
    return differ;
  }

  ViewSettings settings_;

 private:
  std::optional<OffscreenGl> gl_;  // before the ImGui context: it goes after it
  std::optional<HeadlessImGui> imgui_;
  bool backend_ = false;
};

TEST_F(PartialFrame, ThePanelsRedrawnInTheBoxThatChangedAreThePanelsRedrawnWhole) {
  const DisplayBox window{0.0f, 0.0f, static_cast<float>(kWidth), static_cast<float>(kHeight)};
  UiModel m;
  m.snap.state = LinkState::Scanning;
  m.snap.scan_hz = 8.0;
  DrawDamage damage;
  for (int settle = 0; settle < 3; ++settle) {
    lay_out(m);
    damage.update(*ImGui::GetDrawData());
  }
  draw(window);
  const std::vector<unsigned char> before = picture();

  m.snap.scan_hz = 9.7;  // the measured rate's figure changes, nothing else
  lay_out(m);
  const auto changed = damage.update(*ImGui::GetDrawData());
  ASSERT_TRUE(changed);
  ASSERT_FALSE(changed->empty());
  float area = 0.0f;
  for (const DisplayBox& box : *changed) {
    draw(box);
    area += box.area();
  }
  const std::vector<unsigned char> in_parts = picture();
  draw(window);
  const std::vector<unsigned char> whole = picture();

  EXPECT_EQ(pixels_differing(in_parts, whole), 0u) << "a pixel left stale, or drawn twice";
  EXPECT_GT(pixels_differing(before, whole), 20u) << "the figure's change shows, so the test sees something";
  EXPECT_LT(area, 0.01f * window.area()) << "only the figure's box was drawn again";
}

// Several boxes in one call: each is given only the triangles of ImGui's commands that reach it
// (render_imgui_within). Over a picture cleared to another colour, the sidebar drawn in a grid of
// boxes that cut through its words and frames must be the sidebar drawn whole, to the pixel.
TEST_F(PartialFrame, ThePanelsDrawnInManyBoxesAtOnceAreThePanelsDrawnWhole) {
  const DisplayBox window{0.0f, 0.0f, static_cast<float>(kWidth), static_cast<float>(kHeight)};
  UiModel m;
  m.snap.state = LinkState::Scanning;
  m.snap.scan_hz = 8.0;
  lay_out(m);
  draw(window);
  const std::vector<unsigned char> whole = picture();

  glClearColor(1.0f, 0.0f, 0.0f, 1.0f);  // nothing of this may be left
  glClear(GL_COLOR_BUFFER_BIT);
  std::vector<DisplayBox> boxes;
  for (float y = 0.0f; y < kHeight; y += 37.0f)
    for (float x = 0.0f; x < kWidth; x += 61.0f)
      boxes.push_back(
          {x, y, std::min(x + 61.0f, static_cast<float>(kWidth)), std::min(y + 37.0f, static_cast<float>(kHeight))});
  glEnable(GL_SCISSOR_TEST);
  for (const DisplayBox& box : boxes) {
    const PixelBox pixels = to_pixels(box, 1.0f, kHeight);
    glScissor(pixels.x, pixels.y, pixels.width, pixels.height);
    glClearColor(17 / 255.0f, 20 / 255.0f, 26 / 255.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
  }
  glDisable(GL_SCISSOR_TEST);
  render_imgui_within(*ImGui::GetDrawData(), boxes);
  EXPECT_EQ(pixels_differing(picture(), whole), 0u) << "a triangle a box needed was left out, or one drawn twice";

  // The draw data is as ImGui made it: drawn whole once more, the same picture.
  draw(window);
  EXPECT_EQ(pixels_differing(picture(), whole), 0u);
}

}  // namespace
}  // namespace ydscope::ui
