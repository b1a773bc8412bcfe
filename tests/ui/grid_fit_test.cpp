// The grid fits the screen it is on: a handful of labelled rings whatever the view's size (a
// 1080p full-screen view once drew fourteen), and no label in the band where the status line is.
#include <gtest/gtest.h>

#include "ui/view/geometry/grid_layout.h"

namespace ydscope::ui {
namespace {

ViewTransform fitted_view(Vec2 size, float range_mm) {
  ViewTransform v;
  v.set_viewport({0.0f, 0.0f}, size);
  v.fit_range(range_mm);
  return v;
}

TEST(GridFit, AFullHdViewShowsAHandfulOfRings) {
  for (const float range_mm : {3000.0f, 8000.0f, 12000.0f, 30000.0f}) {
    const ViewTransform v = fitted_view({1920.0f, 1080.0f}, range_mm);
    const GridLayout grid = layout_grid(v, ring_spacing_px(v.viewport_size()));
    // Rings out to the corners of a wide view; the scan's own circle holds at most five or so.
    std::size_t inside_scan = 0;
    for (const float r : grid.ring_radii_mm) inside_scan += r <= range_mm;
    EXPECT_GE(inside_scan, 2u) << range_mm << " mm";
    EXPECT_LE(inside_scan, 5u) << range_mm << " mm";
    EXPECT_LE(grid.ring_radii_mm.size(), 10u) << range_mm << " mm";
    EXPECT_GE(grid.ring_labels.size(), 2u) << range_mm << " mm";
  }
}

TEST(GridFit, RingSpacingGrowsWithTheViewAndNeverGoesBelowSeventyPixels) {
  EXPECT_FLOAT_EQ(ring_spacing_px({600.0f, 400.0f}), 70.0f);
  EXPECT_GT(ring_spacing_px({1920.0f, 1080.0f}), ring_spacing_px({1280.0f, 800.0f}));
  EXPECT_FLOAT_EQ(ring_spacing_px({3840.0f, 2160.0f}), 2.0f * ring_spacing_px({1920.0f, 1080.0f}));
}

TEST(GridFit, NoLabelEntersTheStatusBand) {
  constexpr float kBand = 34.0f;
  for (const Vec2 size : {Vec2{600.0f, 600.0f}, Vec2{1490.0f, 1080.0f}, Vec2{1920.0f, 1080.0f}}) {
    ViewTransform v = fitted_view(size, 8000.0f);
    for (int step = 0; step < 40; ++step) {
      v.zoom_about(v.viewport_centre() + Vec2{0.0f, size.y * 0.3f}, 1.05f);
      const GridLayout grid = layout_grid(v, ring_spacing_px(size), 30.0f, 225.0f, 18.0f, kBand);
      const float band_top = size.y - kBand;
      for (const GridLabel& l : grid.ring_labels)
        EXPECT_LE(l.screen.y + kLabelHeightPx, band_top) << l.text << " at zoom step " << step;
      for (const GridLabel& l : grid.spoke_labels)
        EXPECT_LE(l.screen.y + kLabelHeightPx * 0.5f, band_top) << l.text << " at zoom step " << step;
    }
  }
}

}  // namespace
}  // namespace ydscope::ui
