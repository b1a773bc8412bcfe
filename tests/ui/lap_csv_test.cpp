// The CSV export writes what is on screen: the laps the view holds (so a frozen view exports the
// frozen laps, not the live one), the newest only or every shown lap, each row with its lap's
// index and receive time t, in ydscope-cli's --format csv columns and number text.
#include "ui/view/export/lap_csv.h"
#include "support/text_file.h"

#include <gtest/gtest.h>

#include <sstream>
#include <vector>

namespace ydscope::ui {
namespace {

using test::lines_of;

// A lap whose bytes arrived over the 100 ms before `rx_ns`.
Lap lap_of(std::uint64_t index, std::int64_t rx_ns, std::vector<LapPoint> points) {
  Lap lap;
  lap.index = index;
  lap.first_rx_ns = rx_ns - 100'000'000;
  lap.last_rx_ns = rx_ns;
  lap.points = std::move(points);
  return lap;
}

TEST(LapCsv, TheNewestShownLapWithItsReceiveTime) {
  LapHistory history(10);
  history.push(lap_of(7, 9'000'000'000, {{10.0f, 1500.0f, PointFlag::None}}));
  history.push(lap_of(8, 9'500'000'000, {{20.5f, 2500.0f, PointFlag::Specular}, {30.0f, 0.0f, PointFlag::None}}));
  const auto lines = lines_of(shown_laps_csv(history, 1));
  ASSERT_EQ(lines.size(), 3u);
  EXPECT_EQ(lines[0] + "\n", kLapCsvHeader);
  EXPECT_EQ(lines[1], "8,0.1,20.5,2500,2") << "t from the lap's first byte to its last";
  EXPECT_EQ(lines[2], "8,0.1,30,0,0");
}

TEST(LapCsv, EveryShownLapOldestFirst) {
  LapHistory history(3);
  for (std::uint64_t i = 1; i <= 5; ++i)
    history.push(lap_of(i, static_cast<std::int64_t>(i) * 1'000'000'000, {{1.0f, 100.0f, PointFlag::None}}));
  const auto lines = lines_of(shown_laps_csv(history, 60));
  ASSERT_EQ(lines.size(), 4u) << "the view holds 3 laps; laps 1 and 2 are gone from the screen";
  EXPECT_EQ(lines[1].substr(0, 2), "3,");
  EXPECT_EQ(lines[2].substr(0, 2), "4,");
  EXPECT_EQ(lines[3].substr(0, 2), "5,");
  EXPECT_EQ(lines[1].substr(0, 6), "3,0.1,") << "t counts from the oldest exported lap's first byte";
  EXPECT_EQ(lines[3].substr(0, 6), "5,2.1,");
}

// The bug: the export took the session's newest lap, which keeps arriving while the view is
// frozen. The history is what the frozen view draws; the app stops pushing into it when frozen.
TEST(LapCsv, AFrozenViewExportsTheFrozenLaps) {
  LapHistory history(10);
  history.push(lap_of(41, 1'000, {{5.0f, 900.0f, PointFlag::None}}));
  const std::string frozen = shown_laps_csv(history, 1);
  // Laps 42.. arrive but are not pushed: the view is frozen.
  EXPECT_NE(frozen.find("\n41,"), std::string::npos);
  EXPECT_EQ(frozen.find("\n42,"), std::string::npos);
}

TEST(LapCsv, AnglesStayBelow360AsTheCliPrintsThem) {
  LapHistory history(10);
  history.push(lap_of(1, 1'000'000'000, {{359.99997f, 1000.0f, PointFlag::None}}));
  EXPECT_NE(shown_laps_csv(history, 1).find("\n1,0.1,0,1000,0\n"), std::string::npos);
}

TEST(LapCsv, NothingShownIsJustTheHeader) {
  LapHistory history(10);
  EXPECT_EQ(shown_laps_csv(history, 1), kLapCsvHeader);
}

}  // namespace
}  // namespace ydscope::ui
