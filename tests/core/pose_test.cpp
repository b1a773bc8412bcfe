// Pose: a lidar's lap into the common frame several lidars share, and the --pose text.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/frame/pose.h"
#include "core/frame/pose_convention.h"

namespace ydscope {
namespace {

constexpr float kTolMm = 0.05f;

LapPoint at(float angle_deg, float range_mm) { return {angle_deg, range_mm, PointFlag::None}; }

void expect_near(CommonPoint got, float x_mm, float y_mm) {
  EXPECT_NEAR(got.x_mm, x_mm, kTolMm);
  EXPECT_NEAR(got.y_mm, y_mm, kTolMm);
}

TEST(Pose, TheOriginPoseIsTheOfficialDriversLaserFrame) {
  const Pose pose;
  // REP-103, x forward, y left: the unit's 0 points back, its clockwise sweep runs through left.
  expect_near(pose.to_common(at(0, 1000)), -1000, 0);
  expect_near(pose.to_common(at(90, 1000)), 0, 1000);
  expect_near(pose.to_common(at(180, 500)), 500, 0);
  expect_near(pose.to_common(at(270, 2000)), 0, -2000);
}

TEST(Pose, ShiftsByItsPositionInMetres) {
  const Pose pose{1.5, -0.25, 0, false};
  expect_near(pose.to_common(at(180, 1000)), 2500, -250);
  expect_near(pose.to_common(at(0, 0)), 1500, -250);  // no return: the lidar's own position
}

TEST(Pose, YawTurnsCounterClockwise) {
  const Pose pose{0, 0, 90, false};
  // The laser's forward (the unit's 180) of a lidar turned 90 degrees to the left points along +y.
  expect_near(pose.to_common(at(180, 1000)), 0, 1000);
  expect_near(pose.to_common(at(90, 1000)), -1000, 0);
}

TEST(Pose, UpsideDownMirrorsTheAngles) {
  const Pose flipped{0, 0, 0, true};
  // The head spins the other way as seen from above: device 90 lands where 270 would, 0 and 180 stay.
  expect_near(flipped.to_common(at(90, 1000)), 0, -1000);
  expect_near(flipped.to_common(at(30, 1000)), Pose{}.to_common(at(330, 1000)).x_mm,
              Pose{}.to_common(at(330, 1000)).y_mm);
  expect_near(flipped.to_common(at(0, 800)), -800, 0);
  expect_near(flipped.to_common(at(180, 800)), 800, 0);
}

TEST(Pose, MirrorComesBeforeYawAndShift) {
  const Pose pose{1, 2, 90, true};
  // Device 90 mirrored to -y in the laser frame, turned 90 left (+x), shifted by (1 m, 2 m).
  expect_near(pose.to_common(at(90, 1000)), 2000, 2000);
}

TEST(Pose, TheAngleOffsetAddsToTheUnitsAnglesBeforeTheMirror) {
  // A unit whose 0 really points 10 degrees further clockwise: its 80 is where 90 should be.
  const Pose offset{0, 0, 0, false, 10};
  expect_near(offset.to_common(at(80, 1000)), Pose{}.to_common(at(90, 1000)).x_mm, Pose{}.to_common(at(90, 1000)).y_mm);
  // Upside down, the corrected angle is mirrored: 80 + 10 lands where 270 does upright.
  const Pose both{0, 0, 0, true, 10};
  expect_near(both.to_common(at(80, 1000)), Pose{}.to_common(at(270, 1000)).x_mm, Pose{}.to_common(at(270, 1000)).y_mm);
}

TEST(Pose, ToLaserUndoesToCommon) {
  for (const Pose& pose :
       {Pose{}, Pose{1, -2, 30, false}, Pose{-0.5, 0.25, -135, true}, Pose{0.1, 0, 20, true, -7.5}}) {
    for (const float angle : {0.0f, 45.0f, 200.0f}) {
      const CommonPoint laser = laser_point(at(angle, 1234));
      const CommonPoint back = pose.to_laser(pose.to_common(laser));
      EXPECT_NEAR(back.x_mm, laser.x_mm, 0.05f) << format_pose(pose);
      EXPECT_NEAR(back.y_mm, laser.y_mm, 0.05f) << format_pose(pose);
    }
  }
}

TEST(Pose, TransformsAWholeLapInOrder) {
  Lap lap;
  lap.points = {at(0, 1000), at(90, 1000), at(180, 0)};
  std::vector<CommonPoint> out(7);  // replaced, not appended to
  Pose{0, 0, 180, false}.to_common(lap, out);
  ASSERT_EQ(out.size(), 3u);
  expect_near(out[0], 1000, 0);
  expect_near(out[1], 0, -1000);
  expect_near(out[2], 0, 0);
}

// A pose written before REP-103 (x right, y forward, the unit's 0 forward) puts every point where
// it put it then, read in REP-103 axes: forward = old y, left = -old x.
TEST(PoseConvention, AnOldPoseConvertsToTheSameMount) {
  const Pose olds[] = {{0, 0, 0, false}, {0.2, -0.15, 90, false}, {-1, 2, -170, true}, {0.5, 0.5, 180, true}};
  for (const Pose& old : olds) {
    const Pose now = pose_from_pre_rep103(old);
    EXPECT_GT(now.yaw_deg, -180.0) << format_pose(old);
    EXPECT_LE(now.yaw_deg, 180.0) << format_pose(old);
    EXPECT_EQ(now.upside_down, old.upside_down);
    for (const float angle : {0.0f, 30.0f, 90.0f, 250.0f}) {
      // The old rule, written out: (r sin a, r cos a), mirrored x, turned by yaw, shifted.
      const double a = angle * std::numbers::pi / 180.0;
      const double lx = (old.upside_down ? -1.0 : 1.0) * 1000.0 * std::sin(a);
      const double ly = 1000.0 * std::cos(a);
      const double yaw = old.yaw_deg * std::numbers::pi / 180.0;
      const double right = lx * std::cos(yaw) - ly * std::sin(yaw) + old.x_m * 1000.0;
      const double forward = lx * std::sin(yaw) + ly * std::cos(yaw) + old.y_m * 1000.0;
      SCOPED_TRACE(format_pose(old) + " at " + std::to_string(angle));
      expect_near(now.to_common(at(angle, 1000)), static_cast<float>(forward), static_cast<float>(-right));
    }
  }
  EXPECT_EQ(pose_from_pre_rep103({0.2, -0.15, 90, false}), (Pose{-0.15, -0.2, -90, false}));
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
  const auto offset = parse_pose("0,0,0,offset=-2.5,flip", error);  // either order
  ASSERT_TRUE(offset) << error;
  EXPECT_EQ(*offset, (Pose{0, 0, 0, true, -2.5}));
  EXPECT_EQ(format_pose(*offset), "0,0,0,flip,offset=-2.5");
  EXPECT_EQ(parse_pose("1,2,3,offset=4", error), (Pose{1, 2, 3, false, 4}));
}

TEST(PoseText, EachMistakeIsOneSentenceNamingTheText) {
  const char* mistakes[] = {"",
                            "1,2",
                            "1,2,3,4,5",
                            "1,,3",
                            "a,b,c",
                            "1,2,90deg",
                            "1,2,nan",
                            "1,2,inf",
                            "1500,0,0",
                            "0,0,400",
                            "0,0,0,flipped",
                            "0,0,0,",
                            "0,0,0,flip,flip",
                            "0,0,0,offset=",
                            "0,0,0,offset=400",
                            "0,0,0,offset=1,offset=2",
                            "0,0,0,flip,offset=1,x"};
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
