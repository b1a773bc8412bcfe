// The one writer of points as text (ydscope-cli's JSON lines and CSV, the app's CSV export).
#include "core/export/lap_text.h"

#include <gtest/gtest.h>

#include <vector>

namespace ydscope {
namespace {

std::string fields(LapPoint point) {
  std::string out;
  append_point_fields(out, point);
  return out;
}

TEST(LapText, PointFieldsTrimZerosAndKeepAnglesBelow360) {
  EXPECT_EQ(fields({12.5f, 1000.0f, PointFlag::None}), "12.5,1000,0");
  EXPECT_EQ(fields({0.00004f, 0.25f, PointFlag::Specular}), "0,0.25,2");
  EXPECT_EQ(fields({359.99997f, 731.125f, PointFlag::None}), "0,731.12,0") << "360 is 0; ties round to even";
  EXPECT_EQ(fields({123.45678f, 1.005f, PointFlag::None}), "123.4568,1,0");
}

TEST(LapText, OneCsvRowPerPointInTheHeadersColumns) {
  const std::vector<LapPoint> points{{1.0f, 100.0f, PointFlag::None}, {2.0f, 0.0f, PointFlag::AmbientLight}};
  std::string csv = kLapCsvHeader;
  append_lap_csv_rows(csv, 42, 1.5, points);
  EXPECT_EQ(csv, "lap,t,angle_deg,range_mm,flag\n42,1.5,1,100,0\n42,1.5,2,0,3\n");
  std::string none;
  append_lap_csv_rows(none, 1, 0.0, {});
  EXPECT_EQ(none, "");
}

}  // namespace
}  // namespace ydscope
