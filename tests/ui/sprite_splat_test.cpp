// The sprites drawn on the CPU (ui/render/sprite_splat.h) keep their picture between frames: a
// paint must leave nothing of the last one's sprites, say every tile it drew in (only those are
// uploaded and laid), and draw the part of a sprite inside the picture of one whose centre lies
// outside. How its pixels compare with GL's sprites is point_stack_picture_test's.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>
#include <vector>

#include "ui/render/sprite_splat.h"

namespace ydscope::ui {
namespace {

constexpr int kWidth = 100, kHeight = 60;

// World millimetres are the picture's pixels: x from -50 to 50, y from -30 to 30.
SplatFrame frame_of(float point_size_px = 3.0f) {
  return {2.0f / kWidth, 2.0f / kHeight, 0.0f, 0.0f, kWidth, kHeight, point_size_px};
}

// A point at pixel (x, y) of the picture (bottom-up), white and opaque.
PointVertex at_pixel(float x, float y) { return {x - kWidth / 2.0f, y - kHeight / 2.0f, {255, 255, 255, 255}}; }

int alpha_at(const SpriteSplat& splat, int x, int y) {
  return splat.pixels()[(static_cast<std::size_t>(y) * kWidth + static_cast<std::size_t>(x)) * 4 + 3];
}

bool in_drawn(const SpriteSplat& splat, int x, int y) {
  for (const PixelBox& run : splat.drawn())
    if (x >= run.x && x < run.x + run.width && y >= run.y && y < run.y + run.height) return true;
  return false;
}

int pixels_drawn(const SpriteSplat& splat) {
  int drawn = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x) drawn += alpha_at(splat, x, y) != 0 ? 1 : 0;
  return drawn;
}

TEST(SpriteSplat, ASpriteCoversItsPixelsAndItsTileIsSaidDrawn) {
  SpriteSplat splat;
  const std::vector<PointVertex> one{at_pixel(20.5f, 10.5f)};
  splat.paint(one, frame_of());
  EXPECT_EQ(alpha_at(splat, 20, 10), 255) << "an opaque sprite's centre is opaque";
  EXPECT_GT(alpha_at(splat, 21, 10), 0) << "a 3 px sprite reaches the next pixel";
  EXPECT_EQ(alpha_at(splat, 22, 10), 0) << "but not the one after";
  ASSERT_EQ(splat.drawn().size(), 1u);
  EXPECT_EQ(splat.drawn()[0], (PixelBox{16, 0, 16, 16}));
}

TEST(SpriteSplat, PaintingAgainLeavesNothingOfTheLastSprites) {
  SpriteSplat splat;
  splat.paint(std::vector<PointVertex>{at_pixel(20.5f, 10.5f), at_pixel(70.5f, 40.5f)}, frame_of());
  const int first = pixels_drawn(splat);
  ASSERT_GT(first, 0);
  splat.paint(std::vector<PointVertex>{at_pixel(70.5f, 40.5f)}, frame_of());
  EXPECT_EQ(alpha_at(splat, 20, 10), 0) << "the last paint's sprite is still there";
  EXPECT_EQ(pixels_drawn(splat) * 2, first);
  EXPECT_FALSE(in_drawn(splat, 20, 10));
  splat.paint(std::vector<PointVertex>{}, frame_of());
  EXPECT_EQ(pixels_drawn(splat), 0);
  EXPECT_TRUE(splat.drawn().empty());
}

TEST(SpriteSplat, EveryPixelDrawnLiesInTheTilesSaidDrawn) {
  std::mt19937 random(3);
  std::uniform_real_distribution<float> x_at(-4.0f, kWidth + 4.0f), y_at(-4.0f, kHeight + 4.0f);
  std::vector<PointVertex> cloud;
  for (int i = 0; i < 40; ++i) cloud.push_back(at_pixel(x_at(random), y_at(random)));
  SpriteSplat splat;
  splat.paint(cloud, frame_of(5.0f));
  int outside = 0;
  for (int y = 0; y < kHeight; ++y)
    for (int x = 0; x < kWidth; ++x)
      if (alpha_at(splat, x, y) != 0 && !in_drawn(splat, x, y)) ++outside;
  EXPECT_EQ(outside, 0);
  EXPECT_GT(pixels_drawn(splat), 200);
  // The runs lie in the picture and do not overlap.
  for (std::size_t i = 0; i < splat.drawn().size(); ++i) {
    const PixelBox& a = splat.drawn()[i];
    EXPECT_TRUE(a.x >= 0 && a.y >= 0 && a.x + a.width <= kWidth && a.y + a.height <= kHeight);
    for (std::size_t j = i + 1; j < splat.drawn().size(); ++j) {
      const PixelBox& b = splat.drawn()[j];
      EXPECT_FALSE(a.x < b.x + b.width && b.x < a.x + a.width && a.y < b.y + b.height && b.y < a.y + a.height);
    }
  }
}

TEST(SpriteSplat, ASpriteCentredOutsideDrawsItsPartInside) {
  SpriteSplat splat;
  splat.paint(std::vector<PointVertex>{at_pixel(-1.0f, 30.5f)}, frame_of(7.0f));
  EXPECT_GT(alpha_at(splat, 0, 30), 0);
  EXPECT_EQ(alpha_at(splat, 3, 30), 0);
}

TEST(SpriteSplat, PointsFarAwayOrNotANumberDrawNothing) {
  constexpr float kNan = std::numeric_limits<float>::quiet_NaN();
  SpriteSplat splat;
  splat.paint(std::vector<PointVertex>{at_pixel(kNan, 10.0f), at_pixel(10.0f, kNan), at_pixel(1e30f, 10.0f),
                                       at_pixel(-1e30f, -1e30f)},
              frame_of());
  EXPECT_EQ(pixels_drawn(splat), 0);
  EXPECT_TRUE(splat.drawn().empty());
}

// Over a ground (the view's backdrop) the picture is the ground wherever no sprite lands, a sprite
// is blended over it, and what changed since the last paint is said: the tiles either paint drew
// in, or all of them once the ground is another.
TEST(SpriteSplat, OverAGroundTheRestIsTheGroundAndWhatChangedIsSaid) {
  std::vector<std::uint8_t> ground(static_cast<std::size_t>(kWidth) * kHeight * 4);
  for (std::size_t i = 0; i < ground.size(); ++i) ground[i] = i % 4 == 3 ? 255 : static_cast<std::uint8_t>(i % 97);
  const auto ground_at = [&](int x, int y, int channel) {
    return ground[(static_cast<std::size_t>(y) * kWidth + static_cast<std::size_t>(x)) * 4 +
                  static_cast<std::size_t>(channel)];
  };
  const auto pixel_at = [](const SpriteSplat& splat, int x, int y, int channel) {
    return splat.pixels()[(static_cast<std::size_t>(y) * kWidth + static_cast<std::size_t>(x)) * 4 +
                          static_cast<std::size_t>(channel)];
  };
  const auto tiles = [](const std::vector<PixelBox>& runs) {
    int area = 0;
    for (const PixelBox& run : runs) area += run.width * run.height;
    return area;
  };
  SpriteSplat splat;
  splat.paint(std::vector<PointVertex>{at_pixel(20.5f, 10.5f)}, frame_of(), {ground, 1});
  EXPECT_EQ(pixel_at(splat, 20, 10, 0), 255) << "an opaque white sprite's centre";
  EXPECT_EQ(pixel_at(splat, 60, 40, 0), ground_at(60, 40, 0)) << "away from the sprite, the ground";
  EXPECT_EQ(pixel_at(splat, 21, 10, 3), 255) << "over an opaque ground the picture is opaque";
  EXPECT_GT(pixel_at(splat, 21, 10, 0), ground_at(21, 10, 0)) << "the sprite's rim is blended over the ground";
  EXPECT_EQ(tiles(splat.changed()), kWidth * kHeight) << "a first paint changes all of it";

  // Moved: the old sprite's tile is the ground again, and both tiles are said changed.
  splat.paint(std::vector<PointVertex>{at_pixel(70.5f, 40.5f)}, frame_of(), {ground, 1});
  for (int channel = 0; channel < 4; ++channel)
    EXPECT_EQ(pixel_at(splat, 20, 10, channel), ground_at(20, 10, channel)) << "channel " << channel;
  EXPECT_EQ(tiles(splat.changed()), 2 * 16 * 16);
  EXPECT_EQ(tiles(splat.drawn()), 16 * 16);

  // Another ground (the backdrop drawn again): everything changed, the new ground under it all.
  for (std::uint8_t& byte : ground) byte = static_cast<std::uint8_t>(byte ^ 0x55);
  splat.paint(std::vector<PointVertex>{at_pixel(70.5f, 40.5f)}, frame_of(), {ground, 2});
  EXPECT_EQ(tiles(splat.changed()), kWidth * kHeight);
  EXPECT_EQ(pixel_at(splat, 20, 10, 1), ground_at(20, 10, 1));

  // Back to nothing under: clear where no sprite is, as before.
  splat.paint(std::vector<PointVertex>{at_pixel(70.5f, 40.5f)}, frame_of());
  EXPECT_EQ(alpha_at(splat, 20, 10), 0);
  EXPECT_EQ(tiles(splat.changed()), kWidth * kHeight);
}

}  // namespace
}  // namespace ydscope::ui
