// A sprite that stands for a stack of points (ui/view/scene/pixel_merge.h) must look like the stack
// did: drawn with the app's own renderer and point shader into an offscreen picture, the merged
// sprite and the points it replaced give the same pixels, antialiased rim included. And the
// sprites drawn on the CPU (ui/render/sprite_splat.h) must be the sprites GL draws. Each test runs
// with the sprites drawn both ways. Needs the display CTest gives the suite (xvfb-run); skips
// without one.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <random>
#include <vector>

#include "tests/ui/offscreen_gl.h"
#include "ui/render/backdrop_picture.h"
#include "ui/render/polar_renderer.h"
#include "ui/view/scene/pixel_merge.h"

namespace ydscope::ui {
namespace {

constexpr int kSide = 32;

// The app's renderer drawing into an offscreen picture of kSide x kSide, its sprites drawn as the
// test's parameter says.
class PointStackPicture : public testing::TestWithParam<PointDrawing> {
 protected:
  void SetUp() override {
    if (!std::getenv("DISPLAY")) GTEST_SKIP() << "no display (the suite runs under xvfb-run)";
    gl_.emplace(kSide, kSide);
    ASSERT_TRUE(*gl_) << "no GL 3.3 core context with an offscreen picture on this display";
    view_.set_viewport({0.0f, 0.0f}, {static_cast<float>(kSide), static_cast<float>(kSide)});
    view_.fit_range(1000.0f);
  }

  // The picture `renderer` draws of `points` over the view's background, bottom row first, RGBA.
  std::vector<unsigned char> picture(PolarRenderer& renderer, const std::vector<PointVertex>& points, float size_px) {
    glClearColor(9 / 255.0f, 11 / 255.0f, 15 / 255.0f, 1.0f);
    glClear(GL_COLOR_BUFFER_BIT);
    renderer.upload_points(points);
    PolarStyle style;
    style.point_size_px = size_px;
    style.show_grid = false;
    renderer.draw(view_, style, 1.0f, kSide, GlLayer::points);
    return gl_->picture();
  }

  std::vector<unsigned char> picture_as_drawn() const { return gl_->picture(); }
  float cell_mm() const { return 1.0f / view_.px_per_mm(); }

  ViewTransform view_;

 private:
  std::optional<OffscreenGl> gl_;
};

// The largest difference in a colour channel; alpha is left out, as the window shows none.
int largest_difference(const std::vector<unsigned char>& a, const std::vector<unsigned char>& b) {
  int largest = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (i % 4 != 3) largest = std::max(largest, std::abs(a[i] - b[i]));
  return largest;
}

// Nine faded laps of one point of a wall, on one spot, as the persistence draws them.
std::vector<PointVertex> faded_stack() {
  std::vector<PointVertex> stack;
  for (int age = 9; age >= 1; --age)
    stack.push_back(
        {1.0f, 1.0f, {40, 200, 120, static_cast<std::uint8_t>(255.0f * (1.0f - 0.085f * static_cast<float>(age)))}});
  return stack;
}

TEST_P(PointStackPicture, AMergedStackDrawsTheSamePixelsAsItsPoints) {
  PolarRenderer renderer(GetParam());
  // The shader's rim is exact where a sprite covers a pixel wholly, half or not at all: a 3 px
  // point (the app's size) has only such pixels; a 7 px one has rings in between, where the
  // stack's rim is matched within a couple of levels more.
  struct Case {
    float size_px;
    int tolerance;
  };
  for (const auto [size_px, tolerance] : {Case{3.0f, 3}, Case{7.0f, 5}}) {
    std::vector<PointVertex> merged = faded_stack();
    PixelMerger merger;
    merger.merge(merged, cell_mm());
    ASSERT_EQ(merged.size(), 1u);
    const auto stacked = picture(renderer, faded_stack(), size_px);
    const auto one = picture(renderer, merged, size_px);
    EXPECT_LE(largest_difference(stacked, one), tolerance) << size_px << " px points";

    // Not a vacuous match: the same colour and alpha drawn as a lone point's loses the rim the
    // stack's layers build up, and that shows.
    PointVertex plain = merged[0];
    plain.half_clear = -1.0f;
    EXPECT_GT(largest_difference(stacked, picture(renderer, {plain}, size_px)), 10) << size_px << " px points";
  }
}

// A point just outside the view's edge still shows the part of its sprite inside it, as the view
// moves past it, rather than vanishing whole because its centre left: the points are drawn in a
// viewport wider than the view by a sprite's reach, with the scissor on the view.
TEST_P(PointStackPicture, ASpriteAcrossTheViewsEdgeShowsItsPartInside) {
  PolarRenderer renderer(GetParam());
  view_.set_viewport({8.0f, 8.0f}, {16.0f, 16.0f});  // a view inside the picture, as beside the sidebar
  view_.fit_range(1000.0f);
  const Vec2 outside = view_.screen_to_world({6.5f, 16.0f});  // 1.5 px left of the view's edge
  glClearColor(0.0f, 0.0f, 0.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glEnable(GL_SCISSOR_TEST);
  glScissor(8, 8, 16, 16);
  renderer.upload_points(std::vector<PointVertex>{{outside.x, outside.y, {255, 255, 255, 255}}});
  PolarStyle style;
  style.point_size_px = 7.0f;
  style.show_grid = false;
  renderer.draw(view_, style, 1.0f, kSide, GlLayer::points);
  glDisable(GL_SCISSOR_TEST);
  const std::vector<unsigned char> pixels = picture_as_drawn();
  // Screen rows run down, the picture's up.
  const auto red = [&](int x, int y) { return pixels[(static_cast<std::size_t>(kSide - 1 - y) * kSide + x) * 4]; };
  EXPECT_GT(red(8, 16), 100) << "the sprite's part inside the view is missing";
  EXPECT_EQ(red(7, 16), 0) << "the sprite spilled out of the view";
}

// A cloud of sprites of every colour, alpha and rim, overlapping, at any fraction of a pixel: the
// picture the CPU draws of it is the one GL draws, within the rounding of a blend or two.
class SpritesOnTheCpu : public PointStackPicture {};  // draws both ways itself

// `count` sprites of every colour, alpha and rim, a little past the view's edges.
std::vector<PointVertex> random_cloud(unsigned seed, int count) {
  std::mt19937 random(seed);
  std::uniform_real_distribution<float> across(-1100.0f, 1100.0f);
  std::uniform_int_distribution<int> byte(0, 255);
  std::uniform_real_distribution<float> clear(0.0f, 1.0f);
  std::vector<PointVertex> cloud;
  for (int i = 0; i < count; ++i) {
    const auto channel = [&] { return static_cast<std::uint8_t>(byte(random)); };
    cloud.push_back({across(random),
                     across(random),
                     {channel(), channel(), channel(), channel()},
                     i % 3 == 0 ? clear(random) : -1.0f});
  }
  return cloud;
}

// The two pictures agree within the rounding of a blend or two: no channel more than 4 levels
// apart, and at most one in a thousand more than 2.
void expect_alike(const std::vector<unsigned char>& gl, const std::vector<unsigned char>& cpu, float size_px) {
  int apart = 0;
  for (std::size_t i = 0; i < gl.size(); ++i)
    if (i % 4 != 3 && std::abs(gl[i] - cpu[i]) > 2) ++apart;
  EXPECT_LE(largest_difference(gl, cpu), 4) << size_px << " px points";
  EXPECT_LE(apart, static_cast<int>(gl.size() / 1000)) << size_px << " px points: channels more than 2 apart";
}

TEST_F(SpritesOnTheCpu, AreTheSpritesGlDraws) {
  PolarRenderer on_gl(PointDrawing::gl), on_cpu(PointDrawing::cpu);
  const std::vector<PointVertex> cloud = random_cloud(7, 120);
  for (const float size_px : {3.0f, 7.0f}) {
    const auto gl = picture(on_gl, cloud, size_px);
    const auto cpu = picture(on_cpu, cloud, size_px);
    // The CPU lays its sprites over nothing and the picture over the view once, GL blends each
    // over the view: the roundings differ by a level or two where sprites pile up.
    expect_alike(gl, cpu, size_px);
    // Not a vacuous match: the sprites are there, and a cloud moved by half a pixel is not the same.
    const std::vector<unsigned char> background = picture(on_gl, {}, size_px);
    EXPECT_GT(largest_difference(gl, background), 100);
    std::vector<PointVertex> moved = cloud;
    for (PointVertex& p : moved) p.x += 0.5f * cell_mm();
    EXPECT_GT(largest_difference(picture(on_cpu, moved, size_px), gl), 20) << size_px << " px points";
  }
}

// A frame drawn in parts lays the view's backdrop into its boxes; the sprites drawn on the CPU come
// painted over it, in the same pass. That must be the backdrop with GL's sprites over it, in the
// boxes and nowhere else, and a next frame's sprites must leave nothing of the last behind.
TEST_F(SpritesOnTheCpu, LaidWithTheBackdropAreGlsSpritesOverIt) {
  PolarRenderer on_gl(PointDrawing::gl), on_cpu(PointDrawing::cpu);
  BackdropPicture backdrop;  // two colours, so a pixel taken from the wrong place shows
  backdrop.begin(kSide, kSide);
  glClearColor(9 / 255.0f, 11 / 255.0f, 15 / 255.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glEnable(GL_SCISSOR_TEST);
  glScissor(0, 0, kSide / 2, kSide);
  glClearColor(60 / 255.0f, 30 / 255.0f, 90 / 255.0f, 1.0f);
  glClear(GL_COLOR_BUFFER_BIT);
  glDisable(GL_SCISSOR_TEST);
  backdrop.end();
  const std::vector<PixelBox> whole{{0, 0, kSide, kSide}}, left_half{{0, 0, kSide / 2, kSide}};
  const auto fill = [] {
    glClearColor(1.0f, 0.0f, 1.0f, 1.0f);  // what the framebuffer held: none of it may stay in a box
    glClear(GL_COLOR_BUFFER_BIT);
  };
  const auto on_gl_picture = [&](const std::vector<PointVertex>& cloud, const PolarStyle& style) {
    fill();
    on_gl.upload_points(cloud);
    backdrop.lay(whole);
    on_gl.draw(view_, style, 1.0f, kSide, GlLayer::points);
    return picture_as_drawn();
  };
  for (const float size_px : {3.0f, 7.0f}) {
    PolarStyle style;
    style.point_size_px = size_px;
    style.show_grid = false;
    std::vector<PointVertex> cloud = random_cloud(11, 120);
    const auto gl = on_gl_picture(cloud, style);
    fill();
    on_cpu.upload_points(cloud);
    ASSERT_TRUE(on_cpu.lay_points_over(backdrop, whole, view_, style, 1.0f, kSide));
    expect_alike(gl, picture_as_drawn(), size_px);

    // The next frame's sprites, elsewhere, laid in the left half only.
    for (PointVertex& p : cloud) p.x = -p.x;
    const auto gl_next = on_gl_picture(cloud, style);
    fill();
    on_cpu.upload_points(cloud);
    ASSERT_TRUE(on_cpu.lay_points_over(backdrop, left_half, view_, style, 1.0f, kSide));
    const std::vector<unsigned char> cpu_next = picture_as_drawn();
    int outside_box_laid = 0, inside_box_apart = 0;
    for (std::size_t i = 0; i < cpu_next.size(); i += 4) {
      const bool in_box = static_cast<int>(i / 4 % kSide) < kSide / 2;
      const bool untouched = cpu_next[i] == 255 && cpu_next[i + 1] == 0 && cpu_next[i + 2] == 255;
      if (!in_box && !untouched) ++outside_box_laid;
      for (std::size_t c = 0; c < 3; ++c)
        if (in_box && std::abs(cpu_next[i + c] - gl_next[i + c]) > 4) ++inside_box_apart;
    }
    EXPECT_EQ(outside_box_laid, 0) << size_px << " px points: laid outside its boxes";
    EXPECT_EQ(inside_box_apart, 0) << size_px << " px points: the box is not the backdrop with the new sprites";
  }
  // A box past the view's pixels, or sprites drawn by GL: the caller lays the backdrop itself.
  PolarStyle style;
  EXPECT_FALSE(on_cpu.lay_points_over(backdrop, std::vector<PixelBox>{{-1, 0, 4, 4}}, view_, style, 1.0f, kSide));
  EXPECT_FALSE(on_gl.lay_points_over(backdrop, whole, view_, style, 1.0f, kSide));
}

INSTANTIATE_TEST_SUITE_P(DrawnBothWays, PointStackPicture, testing::Values(PointDrawing::gl, PointDrawing::cpu),
                         [](const testing::TestParamInfo<PointDrawing>& drawing) {
                           return drawing.param == PointDrawing::gl ? std::string("OnGl") : std::string("OnCpu");
                         });

}  // namespace
}  // namespace ydscope::ui
