// Key presses are never lost. Eight taps of S reach the app's window at once, between two frames
// (press and release of each before the next frame): the app must save eight screenshots. When it
// polled key state once per frame it saw none of them.
#include <gtest/gtest.h>

#include <cstdlib>

#include "app_test_support.h"
#include "hands_on_app.h"

namespace ydscope::test {
namespace {

#ifdef YDSCOPE_APP_PATH

int pngs_in(const std::filesystem::path& dir) {
  int n = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir)) n += entry.path().extension() == ".png";
  return n;
}

bool wait_for_pngs(const std::filesystem::path& dir, int wanted, std::chrono::seconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (std::chrono::steady_clock::now() < deadline) {
    if (pngs_in(dir) >= wanted) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  return false;
}

class AppKeys : public HandsOnApp {};

TEST_F(AppKeys, EveryQuickTapCounts) {
  X11Hands& hands = this->hands();
  const std::filesystem::path dir = fresh_temp_dir("ydscope-keys");
  const pid_t app = spawn_in(dir, {YDSCOPE_APP_PATH, "--sim", "G6"});
  ASSERT_TRUE(hands.find_window("ydscope", std::chrono::seconds(30))) << "no ydscope window appeared";
  // The loop runs and handles its signal: one screenshot the usual way first.
  std::set<std::string> seen;
  ASSERT_TRUE(screenshot_of(app, dir, seen, std::chrono::seconds(20))) << "the app saved no screenshot on SIGUSR1";
  ASSERT_EQ(pngs_in(dir), 1);

  constexpr int kTaps = 8;
  hands.tap(XK_s, kTaps);
  EXPECT_TRUE(wait_for_pngs(dir, 1 + kTaps, std::chrono::seconds(30)))
      << "only " << pngs_in(dir) - 1 << " of " << kTaps << " quick S taps saved a screenshot";
  EXPECT_EQ(pngs_in(dir), 1 + kTaps) << "a tap counted twice";

  EXPECT_EQ(stop_process(app, SIGTERM), 0);
  if (!HasFailure() && !std::getenv("YDSCOPE_KEEP_TEST_PNGS")) std::filesystem::remove_all(dir);
}

#endif

}  // namespace
}  // namespace ydscope::test
