// Issue 29: the app draws the dropout ring round the lidar. A virtual lidar (ydscope-cli sim, on a
// pseudo-terminal the app opens as a port) blocks 40°–75°; within seconds the ring's red rim
// covers that sector, as the view draws angles, and nowhere else.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

#include "app_test_support.h"
#include "ui/render/dropout_ring_overlay.h"
#include "ui/view/geometry/geometry.h"

namespace ydscope::test {
namespace {

#if defined(YDSCOPE_APP_PATH) && defined(YDSCOPE_CLI_PATH)

bool is_rim_red(const unsigned char* p) { return p[0] > 200 && p[1] < 100 && p[2] < 90; }

// The lidar's mark: a small solid near-white disc (4 px across its middle) near the view's
// middle, told from the heading chevron beside it and from words by its size.
std::optional<std::pair<float, float>> lidar_mark(const Image& image) {
  const int x0 = image.width / 3, x1 = image.width - 2, y0 = image.height / 4, y1 = image.height * 3 / 4;
  const int w = x1 - x0;
  std::vector<char> solid(static_cast<std::size_t>(w * (y1 - y0)), 0);
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x) {
      bool all = true;
      for (int dy = -1; dy <= 1 && all; ++dy)
        for (int dx = -1; dx <= 1 && all; ++dx) all = is_white_pixel(image.at(x + dx, y + dy));
      solid[static_cast<std::size_t>((y - y0) * w + (x - x0))] = all;
    }
  for (std::size_t start = 0; start < solid.size(); ++start) {
    if (!solid[start]) continue;
    std::vector<std::size_t> todo{start}, part;
    solid[start] = 0;
    while (!todo.empty()) {  // one connected patch
      const std::size_t i = todo.back();
      todo.pop_back();
      part.push_back(i);
      const std::size_t x = i % static_cast<std::size_t>(w);
      for (const std::size_t n : {i + 1, i - 1, i + static_cast<std::size_t>(w), i - static_cast<std::size_t>(w)})
        if (n < solid.size() && (n % static_cast<std::size_t>(w) == x || n / w == i / w) && solid[n]) {
          solid[n] = 0;
          todo.push_back(n);
        }
    }
    if (part.size() < 5 || part.size() > 30) continue;
    double sx = 0, sy = 0;
    for (const std::size_t i : part) {
      sx += static_cast<double>(i % static_cast<std::size_t>(w));
      sy += static_cast<double>(i / static_cast<std::size_t>(w));
    }
    const auto n = static_cast<double>(part.size());
    return std::pair{static_cast<float>(x0 + sx / n), static_cast<float>(y0 + sy / n)};
  }
  return std::nullopt;
}

struct RimReading {
  int inside = 0;   // degrees of 45..70 whose rim is red
  int outside = 0;  // degrees of 100..340 whose rim is red
};

RimReading read_rim(const Image& image) {
  RimReading r;
  const auto mark = lidar_mark(image);
  if (!mark) return r;
  // The rim's middle, a pixel either side: clear of the tinted band inside it.
  const auto red_at = [&](int deg) {
    for (const float radius : {ui::kDropoutRimPx - 1.0f, ui::kDropoutRimPx, ui::kDropoutRimPx + 1.0f}) {
      const ui::Vec2 w = ui::polar_to_world(static_cast<float>(deg), radius);  // world y is up the screen
      const int x = static_cast<int>(std::lround(mark->first + w.x));
      const int y = static_cast<int>(std::lround(mark->second - w.y));
      if (x >= 0 && y >= 0 && x < image.width && y < image.height && is_rim_red(image.at(x, y))) return true;
    }
    return false;
  };
  for (int deg = 45; deg <= 70; ++deg) r.inside += red_at(deg);
  for (int deg = 100; deg <= 340; ++deg) r.outside += red_at(deg);
  return r;
}

TEST(AppBlockageRing, TheBlockedSectorIsRimmedRedWhereTheViewDrawsIt) {
  if (!std::getenv("DISPLAY")) GTEST_SKIP() << "no DISPLAY: run under xvfb-run (scripts/test does)";
  const std::filesystem::path dir = fresh_temp_dir("ydscope-blockage");
  const std::string link = (dir / "lidar").string();
  const pid_t sim = spawn_in(
      dir, {YDSCOPE_CLI_PATH, "sim", "--model", "G6", "--scene", "room", "--pty", link, "--block-sector", "40:75"});
  ASSERT_TRUE(wait_for_path(link, std::chrono::seconds(20))) << "the virtual lidar made no " << link;
  const pid_t app = spawn_in(dir, {YDSCOPE_APP_PATH, "--port", link, "--baud", "512000"});
  std::set<std::string> seen;
  const RimReading rim = screenshot_until(
      app, dir, seen, read_rim, [](const RimReading& r) { return r.inside >= 22; }, std::chrono::seconds(60));
  EXPECT_GE(rim.inside, 22) << "no red rim over the blocked 40°–75° (of 26 degrees sampled)";
  EXPECT_LE(rim.outside, 5) << "red rim where nothing is blocked";
  EXPECT_EQ(stop_process(app, SIGTERM), 0);
  EXPECT_EQ(stop_process(sim, SIGTERM), 0);
  if (!HasFailure() && !std::getenv("YDSCOPE_KEEP_TEST_PNGS")) std::filesystem::remove_all(dir);
}

#endif

}  // namespace
}  // namespace ydscope::test
