// Where a view's points reach, as the few boxes a frame of points draws again: every tile a
// sprite's box reaches is inside a box, the boxes do not overlap, and there are no more of them
// than asked for.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "ui/render/tile_cover.h"

namespace ydscope::ui {
namespace {

const DisplayBox kView{430.0f, 0.0f, 1280.0f, 800.0f};  // the app's view beside its sidebar

// Whether `boxes` (which do not overlap) hold all of `box` between them; whether no two share a pixel.
bool covered(const std::vector<DisplayBox>& boxes, const DisplayBox& box) {
  float inside = 0.0f;
  for (const DisplayBox& b : boxes) inside += b.intersected(box).area();
  return std::fabs(inside - box.area()) < 1e-3f * box.area();
}
bool none_overlap(const std::vector<DisplayBox>& boxes) {
  for (std::size_t i = 0; i < boxes.size(); ++i)
    for (std::size_t j = i + 1; j < boxes.size(); ++j)
      if (boxes[i].overlaps(boxes[j])) return false;
  return true;
}

TEST(TileCover, ASpriteMarksTheTilesItsBoxReachesAndNoneItEndsOnTheEdgeOf) {
  TileCover cover(kView, 16.0f);
  cover.mark({446.0f, 16.0f, 462.0f, 32.0f});  // exactly the second tile of the second row
  EXPECT_EQ(cover.marked(), 1u);
  ASSERT_EQ(cover.boxes().size(), 1u);
  EXPECT_EQ(cover.boxes().front(), (DisplayBox{446.0f, 16.0f, 462.0f, 32.0f}));
  cover.mark({461.0f, 40.0f, 464.0f, 43.0f});  // a 3 px sprite across a tile's edge: two tiles
  EXPECT_EQ(cover.marked(), 3u);
  cover.mark({0.0f, 0.0f, 400.0f, 800.0f});  // over the sidebar: outside the view, nothing
  EXPECT_EQ(cover.marked(), 3u);
}

TEST(TileCover, AWallIsOneBoxAndACornerTwo) {
  TileCover wall(kView, 16.0f);
  for (float x = 500.0f; x < 900.0f; x += 2.0f) wall.mark({x - 2.5f, 300.0f, x + 2.5f, 305.0f});
  ASSERT_EQ(wall.boxes().size(), 1u);
  EXPECT_EQ(wall.boxes().front(), (DisplayBox{494.0f, 288.0f, 910.0f, 320.0f}));

  TileCover corner = wall;
  for (float y = 300.0f; y < 600.0f; y += 2.0f) corner.mark({895.0f, y - 2.5f, 900.0f, y + 2.5f});
  const std::vector<DisplayBox> boxes = corner.boxes();
  EXPECT_EQ(boxes.size(), 2u);
  EXPECT_TRUE(none_overlap(boxes));
}

TEST(TileCover, TheLastColumnAndRowAreCutToTheView) {
  TileCover cover({0.0f, 0.0f, 100.0f, 50.0f}, 16.0f);
  cover.mark({95.0f, 45.0f, 99.0f, 49.0f});
  ASSERT_EQ(cover.boxes().size(), 1u);
  EXPECT_EQ(cover.boxes().front(), (DisplayBox{80.0f, 32.0f, 100.0f, 50.0f}));
}

TEST(TileCover, CoversJoinOnlyOverTheSameTiles) {
  TileCover was(kView, 16.0f), now(kView, 16.0f);
  was.mark({500.0f, 100.0f, 505.0f, 105.0f});
  now.mark({702.0f, 500.0f, 705.0f, 505.0f});
  TileCover both = now;
  ASSERT_TRUE(both.unite(was));
  EXPECT_EQ(both.marked(), 2u);
  EXPECT_FALSE(both.unite(TileCover({400.0f, 0.0f, 1280.0f, 800.0f}, 16.0f))) << "another view";
  EXPECT_FALSE(both.unite(TileCover(kView, 32.0f))) << "another tiling";
  EXPECT_FALSE(TileCover().unite(was)) << "a cover of nothing yet (the first frame)";
}

TEST(TileCover, ASlantedWallIsAtMostTheBoxesAskedForAndStillCoversEverySprite) {
  TileCover cover(kView, 16.0f);
  std::vector<DisplayBox> sprites;
  for (float t = 0.0f; t < 400.0f; t += 1.5f)
    sprites.push_back({500.0f + t - 2.5f, 100.0f + 0.7f * t - 2.5f, 500.0f + t + 2.5f, 100.0f + 0.7f * t + 2.5f});
  for (const DisplayBox& s : sprites) cover.mark(s);
  ASSERT_GT(cover.boxes().size(), 8u) << "a slanted wall in small tiles is a staircase of boxes";
  const std::vector<DisplayBox> boxes = covering_boxes(cover, 8);
  EXPECT_LE(boxes.size(), 8u);
  EXPECT_TRUE(none_overlap(boxes));
  for (const DisplayBox& s : sprites) EXPECT_TRUE(covered(boxes, s.intersected(kView))) << s.x0 << ", " << s.y0;
  float area = 0.0f;
  for (const DisplayBox& b : boxes) area += b.area();
  EXPECT_LT(area, 0.5f * kView.area()) << "coarser tiles, not the whole view";
  EXPECT_TRUE(covering_boxes(TileCover(kView, 16.0f), 8).empty()) << "no points, nothing to draw";
}

}  // namespace
}  // namespace ydscope::ui
