// Export while frozen saves what is on screen: with the view frozen (P), two exports a second
// apart (E: every shown lap as CSV) hold the very same laps, though the lidar sent about eight
// more in between; once resumed, an export holds newer laps. The export once took the session's
// newest lap, frozen or not.
#include <gtest/gtest.h>

#include <cstdlib>

#include <fstream>
#include <sstream>

#include "app_test_support.h"
#include "hands_on_app.h"

namespace ydscope::test {
namespace {

#ifdef YDSCOPE_APP_PATH

// Taps E until the app writes a CSV not in `seen` (whole once it has its name: ui/view/export/whole_file.h);
// its text, or empty after `timeout`.
std::string export_csv(X11Hands& hands, const std::filesystem::path& dir, std::set<std::string>& seen,
                       std::chrono::seconds timeout = std::chrono::seconds(15)) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (std::chrono::steady_clock::now() < deadline) {
    // One tap, then up to 3 s for its file, so no export is left over for the next call (a tap
    // before laps are on screen writes nothing, and is tried again).
    hands.tap(XK_e, 1);
    for (int i = 0; i < 60; ++i) {
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
      for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        const std::string name = entry.path().filename().string();
        if (entry.path().extension() != ".csv" || seen.count(name)) continue;
        seen.insert(name);
        std::ifstream in(entry.path());
        std::stringstream text;
        text << in.rdbuf();
        return text.str();
      }
    }
  }
  return {};
}

// The lap indices of the rows, in file order, each once.
std::vector<std::uint64_t> laps_in(const std::string& csv) {
  std::vector<std::uint64_t> laps;
  std::istringstream in(csv);
  std::string line;
  std::getline(in, line);  // header
  while (std::getline(in, line)) {
    const std::uint64_t lap = std::stoull(line.substr(0, line.find(',')));
    if (laps.empty() || laps.back() != lap) laps.push_back(lap);
  }
  return laps;
}

class AppFrozenExport : public HandsOnApp {};

TEST_F(AppFrozenExport, ExportWhileFrozenSavesTheFrozenLaps) {
  X11Hands& hands = this->hands();
  const std::filesystem::path dir = fresh_temp_dir("ydscope-frozen-export");
  const pid_t app = spawn_in(dir, {YDSCOPE_APP_PATH, "--sim", "G6"});
  ASSERT_TRUE(hands.find_window("ydscope", std::chrono::seconds(30)));
  std::set<std::string> seen;
  // Live first: an export appears once laps are on screen.
  const std::string live = export_csv(hands, dir, seen, std::chrono::seconds(30));
  ASSERT_FALSE(laps_in(live).empty()) << "no CSV with laps from the live view";
  ASSERT_EQ(live.substr(0, live.find('\n')), "lap,t,angle_deg,range_mm,flag");

  hands.tap(XK_p, 1);  // freeze
  const std::string first = export_csv(hands, dir, seen);
  std::this_thread::sleep_for(std::chrono::milliseconds(1500));  // laps keep coming meanwhile
  const std::string second = export_csv(hands, dir, seen);
  const auto frozen = laps_in(first);
  ASSERT_GE(frozen.size(), 2u) << "every shown lap, not only the newest";
  EXPECT_EQ(laps_in(second), frozen) << "a frozen view exported laps it does not show";
  EXPECT_EQ(second, first) << "the same frozen laps, the same rows";

  hands.tap(XK_p, 1);  // resume
  std::vector<std::uint64_t> resumed;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(15);
  while (std::chrono::steady_clock::now() < deadline && (resumed.empty() || resumed.back() <= frozen.back()))
    resumed = laps_in(export_csv(hands, dir, seen));
  ASSERT_FALSE(resumed.empty());
  EXPECT_GT(resumed.back(), frozen.back()) << "after resuming the export holds newer laps";
  EXPECT_EQ(stop_process(app, SIGTERM), 0);
  if (!HasFailure() && !std::getenv("YDSCOPE_KEEP_TEST_PNGS")) std::filesystem::remove_all(dir);
}

#endif

}  // namespace
}  // namespace ydscope::test
