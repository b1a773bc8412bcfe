// Pose: a lidar's lap into the common frame several lidars share, and the --pose text.
#include <gtest/gtest.h>

#include "core/frame/pose.h"

namespace ydscope {
namespace {

constexpr float kTolMm = 0.01f;

LapPoint at(float angle_deg, float range_mm) { return {angle_deg, range_mm, PointFlag::None}; }

void expect_near(CommonPoint got, float x_mm, float y_mm) {
  EXPECT_NEAR(got.x_mm, x_mm, kTolMm);
  EXPECT_NEAR(got.y_mm, y_mm, kTolMm);
}

TEST(Pose, TheOriginPoseKeepsTheViewsOwnLayout) {
  const Pose pose;
  expect_near(pose.to_common(at(0, 1000)), 0, 1000);   // 0 degrees: forward
  expect_near(pose.to_common(at(90, 1000)), 1000, 0);  // clockwise: 90 is to the right
  expect_near(pose.to_common(at(180, 500)), 0, -500);
  expect_near(pose.to_common(at(270, 2000)), -2000, 0);
}

TEST(Pose, ShiftsByItsPositionInMetres) {
  const Pose pose{1.5, -0.25, 0, false};
  expect_near(pose.to_common(at(0, 1000)), 1500, 750);
  expect_near(pose.to_common(at(0, 0)), 1500, -250);  // no return: the lidar's own position
}

TEST(Pose, YawTurnsCounterClockwise) {
  const Pose pose{0, 0, 90, false};
  // Forward of a lidar turned 90 degrees to the left points along -x.
  expect_near(pose.to_common(at(0, 1000)), -1000, 0);
  expect_near(pose.to_common(at(90, 1000)), 0, 1000);
  EXPECT_NEAR(pose.common_angle_deg(0), 270.0, 1e-9);
  EXPECT_NEAR(pose.common_angle_deg(90), 0.0, 1e-9);
}

TEST(Pose, UpsideDownMirrorsTheAngles) {
  const Pose flipped{0, 0, 0, true};
  // The head spins the other way as seen from above: device 90 shows at 270, 0 and 180 stay.
  expect_near(flipped.to_common(at(90, 1000)), -1000, 0);
  expect_near(flipped.to_common(at(30, 1000)), Pose{}.to_common(at(330, 1000)).x_mm,
              Pose{}.to_common(at(330, 1000)).y_mm);
  expect_near(flipped.to_common(at(0, 800)), 0, 800);
  expect_near(flipped.to_common(at(180, 800)), 0, -800);
  EXPECT_NEAR(flipped.common_angle_deg(90), 270.0, 1e-9);
  EXPECT_NEAR(flipped.common_angle_deg(0), 0.0, 1e-9);
}

TEST(Pose, MirrorComesBeforeYawAndShift) {
  const Pose pose{1, 2, 90, true};
  // Device 90 mirrored to 270 (-x in the lidar's frame), turned 90 left (-y), shifted by (1 m, 2 m).
  expect_near(pose.to_common(at(90, 1000)), 1000, 1000);
  EXPECT_NEAR(pose.common_angle_deg(90), 180.0, 1e-9);
}

TEST(Pose, TransformsAWholeLapInOrder) {
  Lap lap;
  lap.points = {at(0, 1000), at(90, 1000), at(180, 0)};
  std::vector<CommonPoint> out(7);  // replaced, not appended to
  Pose{0, 0, 180, false}.to_common(lap, out);
  ASSERT_EQ(out.size(), 3u);
  expect_near(out[0], 0, -1000);
  expect_near(out[1], -1000, 0);
  expect_near(out[2], 0, 0);
}

TEST(PoseText, ParsesAndFormatsBothForms) {
  std::string error;
  const auto plain = parse_pose("0.2,-0.15,90", error);
  ASSERT_TRUE(plain) << error;
  EXPECT_EQ(*plain, (Pose{0.2, -0.15, 90, false}));
  EXPECT_EQ(format_pose(*plain), "0.2,-0.15,90");
  const auto flipped = parse_pose("0,0,-180,flip", error);
  ASSERT_TRUE(flipped) << error;
  EXPECT_EQ(*flipped, (Pose{0, 0, -180, true}));
  EXPECT_EQ(format_pose(*flipped), "0,0,-180,flip");
  const Pose odd{0.1 + 0.2, 1e-7, 33.333333333333336, true};
  EXPECT_EQ(parse_pose(format_pose(odd), error), odd);
}

TEST(PoseText, EachMistakeIsOneSentenceNamingTheText) {
  const char* mistakes[] = {"",        "1,2",     "1,2,3,4,5", "1,,3",    "a,b,c",         "1,2,90deg",
                            "1,2,nan", "1,2,inf", "1500,0,0",  "0,0,400", "0,0,0,flipped", "0,0,0,"};
  for (const char* text : mistakes) {
    std::string error;
    EXPECT_FALSE(parse_pose(text, error)) << text;
    EXPECT_NE(error.find(std::string("'") + text + "'"), std::string::npos) << error;
    EXPECT_EQ(error.find('\n'), std::string::npos) << error;
  }
  std::string error;
  parse_pose("1500,0,0", error);
  EXPECT_NE(error.find("millimetres"), std::string::npos) << error;
}

}  // namespace
}  // namespace ydscope
