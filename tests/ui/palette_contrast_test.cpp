// Every colour of both range palettes stands out from the view's background (WCAG contrast ratio
// of at least 3 : 1, the level for graphics), so the nearest points never vanish. Viridis's dark
// purple end was 1.3 : 1.
#include <gtest/gtest.h>

#include <cmath>

#include "ui/render/theme.h"
#include "ui/view/scene/colour_map.h"

namespace ydscope::ui {
namespace {

double linear(double c) { return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4); }
double luminance(double r, double g, double b) { return 0.2126 * linear(r) + 0.7152 * linear(g) + 0.0722 * linear(b); }
double contrast(double a, double b) { return (std::max(a, b) + 0.05) / (std::min(a, b) + 0.05); }

TEST(PaletteContrast, EveryRangeColourStandsOutFromTheBackground) {
  const double background = luminance(kBackground[0], kBackground[1], kBackground[2]);
  for (const Palette palette : {Palette::Turbo, Palette::Viridis}) {
    for (int i = 0; i <= 100; ++i) {
      const Rgba8 c = sample_palette(palette, static_cast<float>(i) / 100.0f);
      const double ratio = contrast(luminance(c.r / 255.0, c.g / 255.0, c.b / 255.0), background);
      EXPECT_GE(ratio, 3.0) << palette_name(palette) << " at " << i << " %";
    }
  }
}

TEST(PaletteContrast, ViridisStillRunsFromBlueToYellowGettingLighter) {
  double previous = 0.0;
  for (int i = 0; i <= 10; ++i) {
    const Rgba8 c = sample_palette(Palette::Viridis, static_cast<float>(i) / 10.0f);
    const double l = luminance(c.r / 255.0, c.g / 255.0, c.b / 255.0);
    EXPECT_GT(l, previous) << "lightness must grow along viridis, at " << i * 10 << " %";
    previous = l;
  }
  const Rgba8 near = sample_palette(Palette::Viridis, 0.0f);
  const Rgba8 far = sample_palette(Palette::Viridis, 1.0f);
  EXPECT_GT(near.b, near.r) << "starts blue";
  EXPECT_GT(far.r, far.b) << "ends yellow";
}

}  // namespace
}  // namespace ydscope::ui
