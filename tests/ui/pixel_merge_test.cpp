// Points sharing a pixel are merged into one sprite before drawing (ui/view/scene/pixel_merge.h):
// the merge must lay its stack as the GPU's blend would have (each point over those before it),
// keep sprites in the order their topmost points were drawn, and leave points in other pixels alone.
#include <gtest/gtest.h>

#include <vector>

#include "ui/view/scene/pixel_merge.h"

namespace ydscope::ui {
namespace {

constexpr float kCellMm = 10.0f;

TEST(PixelMerge, PointsInDifferentPixelsAreLeftAsTheyWere) {
  std::vector<PointVertex> points{
      {5.0f, 5.0f, {200, 10, 10, 255}}, {15.0f, 5.0f, {10, 200, 10, 128}}, {-5.0f, 5.0f, {10, 10, 200, 40}}};
  const std::vector<PointVertex> before = points;
  PixelMerger merger;
  merger.merge(points, kCellMm);
  ASSERT_EQ(points.size(), 3u);
  for (std::size_t i = 0; i < points.size(); ++i) {
    EXPECT_EQ(points[i].x, before[i].x);
    EXPECT_EQ(points[i].y, before[i].y);
    EXPECT_EQ(points[i].colour, before[i].colour) << "point " << i;
    EXPECT_LT(points[i].half_clear, 0.0f) << "a lone point keeps a lone point's rim";
  }
}

TEST(PixelMerge, AStackBlendsAsEachPointOverThoseBeforeIt) {
  // Red at half alpha, then blue at half alpha over it: the blend gives 0.75 alpha, of which red
  // 0.25 and blue 0.5, so the colour is (85, 0, 170). Where each covers half, each lets 0.75
  // through, so the stack lets 0.5625 through.
  std::vector<PointVertex> points{{2.0f, 3.0f, {255, 0, 0, 128}}, {7.0f, 8.0f, {0, 0, 255, 128}}};
  PixelMerger merger;
  merger.merge(points, kCellMm);
  ASSERT_EQ(points.size(), 1u);
  EXPECT_EQ(points[0].x, 7.0f) << "the sprite sits where its topmost point was";
  EXPECT_EQ(points[0].y, 8.0f);
  EXPECT_NEAR(points[0].colour.r, 85, 1);
  EXPECT_EQ(points[0].colour.g, 0);
  EXPECT_NEAR(points[0].colour.b, 170, 1);
  EXPECT_NEAR(points[0].colour.a, 191, 1);
  EXPECT_NEAR(points[0].half_clear, (1.0f - 64.0f / 255.0f) * (1.0f - 64.0f / 255.0f), 1e-4f);
}

TEST(PixelMerge, AnOpaquePointHidesWhatLiesUnderIt) {
  std::vector<PointVertex> points{
      {1.0f, 1.0f, {255, 0, 0, 200}}, {2.0f, 1.0f, {0, 255, 0, 90}}, {3.0f, 1.0f, {0, 0, 255, 255}}};
  PixelMerger merger;
  merger.merge(points, kCellMm);
  ASSERT_EQ(points.size(), 1u);
  EXPECT_EQ(points[0].colour, (Rgba8{0, 0, 255, 255}));
}

TEST(PixelMerge, SpritesKeepTheOrderOfTheirTopmostPoints) {
  // A and C share a pixel, B has its own: B was drawn under C, so the merged A+C comes after B.
  std::vector<PointVertex> points{{1.0f, 1.0f, {255, 0, 0, 100}},   // A
                                  {25.0f, 1.0f, {0, 255, 0, 255}},  // B
                                  {4.0f, 2.0f, {0, 0, 255, 100}}};  // C
  PixelMerger merger;
  merger.merge(points, kCellMm);
  ASSERT_EQ(points.size(), 2u);
  EXPECT_EQ(points[0].x, 25.0f);
  EXPECT_EQ(points[1].x, 4.0f);
  EXPECT_GE(points[1].half_clear, 0.0f) << "A and C are one sprite";
}

TEST(PixelMerge, NegativeCoordinatesFallInTheirOwnPixels) {
  // -1 and -2 mm share the cell left of zero, 1 and 2 mm the one right of it; cells rounded
  // towards zero would have put all four in one.
  std::vector<PointVertex> points{{-1.0f, 1.0f, {255, 0, 0, 255}},
                                  {-2.0f, 1.0f, {255, 0, 0, 255}},
                                  {1.0f, 1.0f, {0, 255, 0, 255}},
                                  {2.0f, 1.0f, {0, 255, 0, 255}}};
  PixelMerger merger;
  merger.merge(points, kCellMm);
  ASSERT_EQ(points.size(), 2u);
  EXPECT_EQ(points[0].colour, (Rgba8{255, 0, 0, 255}));
  EXPECT_EQ(points[1].colour, (Rgba8{0, 255, 0, 255}));
}

TEST(PixelMerge, FewPointsSharingPixelsAreDrawnAsTheyAre) {
  // Five points in four pixels: merging would leave 80 % of the sprites, not worth its cost.
  std::vector<PointVertex> points{{1.0f, 1.0f, {255, 0, 0, 100}},
                                  {2.0f, 1.0f, {0, 255, 0, 100}},
                                  {11.0f, 1.0f, {0, 0, 255, 100}},
                                  {21.0f, 1.0f, {0, 0, 255, 100}},
                                  {31.0f, 1.0f, {0, 0, 255, 100}}};
  const std::vector<PointVertex> before = points;
  PixelMerger merger;
  merger.merge(points, kCellMm);
  ASSERT_EQ(points.size(), before.size());
  for (std::size_t i = 0; i < points.size(); ++i) EXPECT_EQ(points[i].colour, before[i].colour) << i;
}

// Ten laps of the same 100 points, 10 mm apart along a wall, each lap 0.5 mm off the last (noise):
// every lap lands in the same pixels as the others.
std::vector<PointVertex> static_wall() {
  std::vector<PointVertex> points;
  for (int lap = 0; lap < 10; ++lap)
    for (int i = 0; i < 100; ++i)
      points.push_back({10.0f * static_cast<float>(i) + 2.0f + 0.5f * static_cast<float>(lap),
                        3003.0f,
                        {40, 200, 120, static_cast<std::uint8_t>(40 + 20 * lap)}});
  return points;
}

TEST(PixelMerge, AfterAMovingSceneAStillOneIsMergedAgainWithinAWhile) {
  PixelMerger merger;
  std::vector<PointVertex> moving{{1.0f, 1.0f, {255, 0, 0, 100}}, {11.0f, 1.0f, {0, 255, 0, 100}}};
  merger.merge(moving, kCellMm);
  ASSERT_EQ(moving.size(), 2u);
  int clouds = 0;
  std::vector<PointVertex> wall = static_wall();
  for (; clouds <= PixelMerger::kCloudsBetweenLooks && wall.size() == 1000u; ++clouds) {
    wall = static_wall();
    merger.merge(wall, kCellMm);
  }
  EXPECT_EQ(wall.size(), 100u) << "still not merged after " << clouds << " clouds";
  EXPECT_GT(clouds, 1) << "a moving scene should be left alone for a while before looking again";
}

TEST(PixelMerge, AStaticWallOfTenLapsBecomesOneSpritePerPixel) {
  // The merger is kept from cloud to cloud, as the app keeps it.
  PixelMerger merger;
  for (int frame = 0; frame < 3; ++frame) {
    std::vector<PointVertex> points = static_wall();
    merger.merge(points, kCellMm);
    ASSERT_EQ(points.size(), 100u) << "frame " << frame;
    float half_clear = 1.0f;  // what the ten laps' points let through at half coverage
    for (int lap = 0; lap < 10; ++lap) half_clear *= 1.0f - 0.5f * static_cast<float>(40 + 20 * lap) / 255.0f;
    for (const PointVertex& p : points) EXPECT_NEAR(p.half_clear, half_clear, 1e-4f);
  }
}

}  // namespace
}  // namespace ydscope::ui
