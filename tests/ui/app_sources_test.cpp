// Several lidars in one view, under an Xvfb of the test's own: each source's colour must appear
// where its pose puts it (not just "something was drawn"), and when one of them dies only its own
// cloud dims and its legend line turns amber while the others keep drawing.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "app_test_support.h"
#include "private_display.h"
#include "ui/view/scene/source_set.h"

namespace ydscope::test {
namespace {

#ifdef YDSCOPE_APP_PATH

constexpr double kPi = 3.14159265358979;

double hue_deg(const unsigned char* p) {
  const double r = p[0], g = p[1], b = p[2];
  const double hi = std::max({r, g, b}), lo = std::min({r, g, b});
  if (hi - lo < 1.0) return 0.0;
  double h = hi == r ? (g - b) / (hi - lo) : hi == g ? 2.0 + (b - r) / (hi - lo) : 4.0 + (r - g) / (hi - lo);
  h *= 60.0;
  return h < 0 ? h + 360.0 : h;
}

// A bright scan point of this source's colour (the hue survives the lap fading, brightness not).
bool is_source_point(const unsigned char* p, ui::Rgba8 colour) {
  if (!is_point_pixel(p)) return false;
  const unsigned char c[3] = {colour.r, colour.g, colour.b};
  const double d = std::fabs(hue_deg(p) - hue_deg(c));
  return std::min(d, 360.0 - d) < 20.0;
}

struct SourcePixels {
  int total = 0;
  int towards_pose = 0;  // within 60 degrees of the bearing of its pose from the view's centre
};

SourcePixels source_pixels(const Image& image, ui::Rgba8 colour, const Pose& pose) {
  const int cx = (kViewLeft + image.width) / 2, cy = image.height / 2;
  // Clockwise from straight up: the view draws forward (+x) up and left (+y) to the left.
  const double bearing = std::atan2(-pose.y_m, pose.x_m);
  SourcePixels counted;
  for (int y = 0; y < image.height; ++y) {
    for (int x = kViewLeft; x < image.width; ++x) {
      if (!is_source_point(image.at(x, y), colour)) continue;
      ++counted.total;
      const double off = std::remainder(std::atan2(x - cx, cy - y) - bearing, 2.0 * kPi);
      counted.towards_pose += std::fabs(off) < kPi / 3.0;
    }
  }
  return counted;
}

// `count` sources started together: each in the next colour of the palette, its cloud lying
// towards the pose spread_poses gives it round the origin.
void expect_spread_round_the_origin(const Image& image, std::size_t count) {
  const std::vector<Pose> poses = ui::spread_poses(count);
  for (std::size_t i = 0; i < poses.size(); ++i) {
    const SourcePixels pixels = source_pixels(image, ui::source_colour(i), poses[i]);
    EXPECT_GT(pixels.total, 1000) << "source " << i << "'s colour is hardly on the view";
    EXPECT_GT(pixels.towards_pose * 10, pixels.total * 6)
        << "source " << i << ": only " << pixels.towards_pose << " of " << pixels.total
        << " of its points lie towards its pose";
  }
}

// Each test on an Xvfb of its own, in a folder of its own (kept when it fails, to look at).
class AppSources : public testing::Test {
 protected:
  void SetUp() override {
    if (std::system("command -v Xvfb >/dev/null 2>&1") != 0) GTEST_SKIP() << "Xvfb is not installed";
    display_.emplace();
    ASSERT_TRUE(*display_) << "could not start an Xvfb of the test's own";
    dir_ = fresh_temp_dir(std::string("ydscope-") + testing::UnitTest::GetInstance()->current_test_info()->name());
  }
  void TearDown() override {
    if (!HasFailure() && !dir_.empty() && !std::getenv("YDSCOPE_KEEP_TEST_PNGS")) std::filesystem::remove_all(dir_);
  }
  // The app's --screenshot picture after 120 frames of `arguments`; empty when it failed.
  Image screenshot_run(const std::vector<std::string>& arguments) {
    const std::string png = (dir_ / "screenshot.png").string();
    std::vector<std::string> argv{YDSCOPE_APP_PATH};
    argv.insert(argv.end(), arguments.begin(), arguments.end());
    argv.insert(argv.end(), {"--screenshot", png, "--frames", "120"});
    const pid_t app = spawn_in(dir_, argv);
    int status = 0;
    if (waitpid(app, &status, 0) != app || !WIFEXITED(status) || WEXITSTATUS(status) != 0) return {};
    return load_png(png);
  }
  const std::filesystem::path& dir() const { return dir_; }

 private:
  std::optional<PrivateDisplay> display_;
  std::filesystem::path dir_;
};

TEST_F(AppSources, ThreeVirtualLidarsDrawInTheirColoursWhereTheirPosesPutThem) {
  const Image image = screenshot_run({"--sim", "G1,G6,TG30"});
  ASSERT_TRUE(image) << "the app did not exit 0 with a picture";
  // Started together, the three sit round the origin, each in the next colour of the palette.
  expect_spread_round_the_origin(image, 3);
}

// View > split: two sources side by side, each drawn around itself in its own half.
TEST_F(AppSources, TheSplitViewPutsEachSourceInItsOwnHalf) {
  const Image image = screenshot_run({"--sim", "G1,G6", "--split"});
  ASSERT_TRUE(image) << "the app did not exit 0 with a picture";
  const int middle = (kViewLeft + image.width) / 2;
  const auto in = [&](int x0, int x1, ui::Rgba8 colour) {
    return count_pixels(image, {x0, 0, x1, image.height},
                        [&](const unsigned char* p) { return is_source_point(p, colour); });
  };
  const ui::Rgba8 first = ui::source_colour(0), second = ui::source_colour(1);
  EXPECT_GT(in(kViewLeft, middle, first), 1000) << "the first source is not in the left half";
  EXPECT_GT(in(middle, image.width, second), 1000) << "the second source is not in the right half";
  EXPECT_LT(in(kViewLeft, middle, second), 50) << "the second source spills into the first's half";
  EXPECT_LT(in(middle, image.width, first), 50) << "the first source spills into the second's half";
}

// Two ports given no --pose sit where two virtual lidars would, not both on the origin, so their
// clouds are told apart from the first frame (each can be dragged to where it really is).
TEST_F(AppSources, TwoPortsWithoutPosesAreSpreadLikeVirtualLidars) {
  const std::filesystem::path& dir = this->dir();
  std::vector<pid_t> sims;
  for (const char* link : {"a", "b"})
    sims.push_back(
        spawn_in(dir, {YDSCOPE_CLI_PATH, "sim", "--model", "G6", "--scene", "demo", "--pty", (dir / link).string()}));
  const bool ready =
      wait_for_path(dir / "a", std::chrono::seconds(15)) && wait_for_path(dir / "b", std::chrono::seconds(15));
  const Image image =
      ready ? screenshot_run({"--port", (dir / "a").string(), "--port", (dir / "b").string()}) : Image{};
  for (const pid_t sim : sims) stop_process(sim, SIGTERM);
  ASSERT_TRUE(ready) << "the virtual lidars' ports never appeared";
  ASSERT_TRUE(image) << "the app did not exit 0 with a picture";
  expect_spread_round_the_origin(image, 2);
}

// Amber legend words (255, 190, 80): the legend line of a source whose data stopped; the orange
// of the first source (255, 150, 40) is not amber.
bool is_amber(const unsigned char* p) { return p[0] > 220 && p[1] > 170 && p[1] < 210 && p[2] > 40 && p[2] < 120; }

TEST_F(AppSources, AKilledLidarDimsOnlyItsOwnCloudAndItsLegendSaysSo) {
  const std::filesystem::path& dir = this->dir();
  const std::string left_link = (dir / "left").string(), right_link = (dir / "right").string();
  // An ASSERT that ends the test early must not leave the sims and the app running.
  struct Running {
    std::vector<pid_t> pids;
    ~Running() {
      for (const pid_t pid : pids) stop_process(pid, SIGKILL);
    }
    pid_t add(pid_t pid) { return pids.push_back(pid), pid; }
    int stop(pid_t pid, int signal) {
      std::erase(pids, pid);
      return stop_process(pid, signal);
    }
  } running;
  const auto sim_at = [&](const std::string& link) {
    return running.add(spawn_in(dir, {YDSCOPE_CLI_PATH, "sim", "--model", "G6", "--scene", "demo", "--pty", link}));
  };
  const pid_t left_sim = sim_at(left_link);
  const pid_t right_sim = sim_at(right_link);
  ASSERT_TRUE(wait_for_path(left_link, std::chrono::seconds(15)) &&
              wait_for_path(right_link, std::chrono::seconds(15)));
  Pose left, right;
  left.y_m = 2.0;    // left of the centre (REP-103: +y is left)
  right.y_m = -2.0;  // right of it
  const pid_t app = running.add(
      spawn_in(dir, {YDSCOPE_APP_PATH, "--port", left_link, "--name", "left", "--pose", format_pose(left), "--port",
                     right_link, "--name", "right", "--pose", format_pose(right), "--model", "G6"}));
  std::set<std::string> seen;
  struct Reading {
    SourcePixels left, right;
    int amber = 0;  // legend words of a source whose data stopped
  };
  const auto read = [&](const Image& image) {
    return Reading{source_pixels(image, ui::source_colour(0), left), source_pixels(image, ui::source_colour(1), right),
                   count_pixels(image, {kViewLeft - 10, 0, kViewLeft + 400, 120}, is_amber)};
  };
  const Reading before = screenshot_until(
      app, dir, seen, read, [](const Reading& r) { return r.left.total > 1000 && r.right.total > 1000; },
      std::chrono::seconds(30));
  ASSERT_GT(before.left.total, 1000) << "the left lidar's cloud never showed";
  ASSERT_GT(before.right.total, 1000) << "the right lidar's cloud never showed";
  EXPECT_LT(before.amber, 30) << "amber legend words while both scan";

  running.stop(right_sim, SIGKILL);  // a crash: the pty's other end vanishes mid-stream
  // Its link names a pty number another test's lidar may take next; the app would show that one.
  std::filesystem::remove(right_link);
  // Bright is measured against the live twin (the same model and scene) in the same picture: the
  // first picture may come before either cloud is whole, on a slow machine.
  const auto right_dimmed = [&](const Reading& r) {
    return r.right.total < r.left.total / 10 && r.amber > 100 && r.left.total > 1000;
  };
  const Reading after = screenshot_until(app, dir, seen, read, right_dimmed, std::chrono::seconds(20));
  EXPECT_LT(after.right.total, after.left.total / 10)
      << "the dead lidar's cloud stays bright (" << after.right.total << " bright pixels; the live one "
      << after.left.total << ", and " << before.right.total << " before it died)";
  EXPECT_GT(after.amber, 100) << "its legend line did not turn amber";
  EXPECT_GT(after.left.total, 1000) << "the live lidar's cloud dimmed too";

  EXPECT_EQ(running.stop(app, SIGTERM), 0);
  running.stop(left_sim, SIGTERM);
}

#endif

}  // namespace
}  // namespace ydscope::test
