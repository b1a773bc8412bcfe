// The window icon drawn from the SVG's shapes: transparent corners, the dark square, the white
// lidar at the centre and the coloured sweep above it, at every size the window asks for.
#include <cstdint>

#include <gtest/gtest.h>

#include "ui/view/window/app_icon.h"

namespace ydscope::ui {
namespace {

struct Pixel {
  std::uint8_t r, g, b, a;
};

Pixel at(const std::vector<std::uint8_t>& rgba, int size, float fx, float fy) {
  const int x = static_cast<int>(fx * static_cast<float>(size));
  const int y = static_cast<int>(fy * static_cast<float>(size));
  const std::uint8_t* p = &rgba[(static_cast<std::size_t>(y) * size + x) * 4];
  return {p[0], p[1], p[2], p[3]};
}

TEST(AppIcon, HasTheSvgsShapesAtEverySize) {
  for (const int size : {16, 32, 48, 64, 128}) {
    SCOPED_TRACE(size);
    const auto rgba = app_icon_rgba(size);
    ASSERT_EQ(rgba.size(), static_cast<std::size_t>(size) * size * 4);
    EXPECT_EQ(at(rgba, size, 0.0f, 0.0f).a, 0);  // outside the rounded corner
    const Pixel background = at(rgba, size, 0.2f, 0.8f);
    EXPECT_EQ(background.a, 255);
    EXPECT_LT(background.r + background.g + background.b, 90);
    const Pixel lidar = at(rgba, size, 0.5f, 0.5f);
    EXPECT_GT(lidar.r + lidar.g + lidar.b, size >= 32 ? 600 : 200);  // at 16 px the dot is half a pixel
    // The sweep crosses straight above the lidar at ~75 of 256 units out: bright and green-blue.
    const Pixel sweep = at(rgba, size, 0.5f, (128.0f - 75.0f) / 256.0f);
    EXPECT_GT(sweep.g, 150);
    EXPECT_GT(sweep.g, sweep.r);
  }
}

TEST(AppIcon, NoSizeNoPixels) { EXPECT_TRUE(app_icon_rgba(0).empty()); }

}  // namespace
}  // namespace ydscope::ui
