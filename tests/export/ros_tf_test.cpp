// /tf_static in ROS terms: each pose as the transform that carries the lidar's own /points onto
// where the app puts them (REP-103 numbers in, where the cloud lands out), and the unit frame that
// says how the unit's 0 degrees and clockwise sweep map to the laser frame.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "core/export/ros_tf.h"

namespace ydscope {
namespace {

// p' = q p q* + t, with the rotation written out as a matrix.
void apply(const RosTransform& t, const double p[3], double out[3]) {
  const double x = t.rotation[0], y = t.rotation[1], z = t.rotation[2], w = t.rotation[3];
  const double m[3][3] = {{1 - 2 * (y * y + z * z), 2 * (x * y - z * w), 2 * (x * z + y * w)},
                          {2 * (x * y + z * w), 1 - 2 * (x * x + z * z), 2 * (y * z - x * w)},
                          {2 * (x * z - y * w), 2 * (y * z + x * w), 1 - 2 * (x * x + y * y)}};
  for (int r = 0; r < 3; ++r) out[r] = m[r][0] * p[0] + m[r][1] * p[1] + m[r][2] * p[2] + t.translation[r];
}

TEST(RosTf, EachTransformCarriesTheLidarsPointsWhereThePosePutsThem) {
  const Pose poses[] = {{0, 0, 0, false},  {1.5, -0.5, 30, false},   {-0.2, 0.3, -120, true},
                        {0, 0, 180, true}, {0.4, 0.1, 15, false, 7}, {-1, 2, 60, true, -12.5}};
  RosFrameOptions frames[4];
  frames[1].reversion = false;
  frames[2].inverted = false;
  frames[3].reversion = frames[3].inverted = false;
  for (const RosFrameOptions& frame : frames) {
    for (const Pose& pose : poses) {
      const RosTransform t = ros_transform_of(pose, frame, "base_link", "front");
      EXPECT_NEAR(std::hypot(std::hypot(t.rotation[0], t.rotation[1]), std::hypot(t.rotation[2], t.rotation[3])), 1.0,
                  1e-12);
      for (const float angle : {0.0f, 37.5f, 90.0f, 200.0f, 359.0f}) {
        SCOPED_TRACE(format_pose(pose) + " at " + std::to_string(angle) + (frame.reversion ? " rev" : "") +
                     (frame.inverted ? " inv" : ""));
        const LapPoint point{angle, 2000.0f, PointFlag::None};
        // /points of this lidar: its laser frame, metres.
        const double a = ros_angle_rad(angle, frame);
        const double laser[3] = {2.0 * std::cos(a), 2.0 * std::sin(a), 0};
        double common[3];
        apply(t, laser, common);
        // Where the app puts the point in the common frame (REP-103, the same axes).
        const CommonPoint expected = pose.to_common(point);
        EXPECT_NEAR(common[0], expected.x_mm / 1000.0, 1e-5);
        EXPECT_NEAR(common[1], expected.y_mm / 1000.0, 1e-5);
        EXPECT_NEAR(common[2], 0.0, 1e-9);
      }
    }
  }
  const RosTransform identity = ros_transform_of({}, {}, "base_link", "front");
  EXPECT_NEAR(identity.rotation[3], 1.0, 1e-12);
}

// REP-103 numbers in, as a URDF would give them; where the cloud lands out.
TEST(RosTf, ARep103PoseIsTheTransformAsAUrdfWritesIt) {
  // 1 m forward, 0.5 m left, turned a quarter to the left.
  const Pose pose{1.0, 0.5, 90, false};
  const RosTransform t = ros_transform_of(pose, {}, "base_link", "front");
  EXPECT_NEAR(t.translation[0], 1.0, 1e-12);
  EXPECT_NEAR(t.translation[1], 0.5, 1e-12);
  EXPECT_NEAR(t.rotation[2], std::sin(std::numbers::pi / 4), 1e-12);  // yaw +90: q = (0, 0, sin 45, cos 45)
  EXPECT_NEAR(t.rotation[3], std::cos(std::numbers::pi / 4), 1e-12);
  // The unit's 180 degrees is the laser's forward: 2 m along it lands 2 m to the robot's left of the mount.
  const double a = ros_angle_rad(180.0f, {});
  const double laser[3] = {2.0 * std::cos(a), 2.0 * std::sin(a), 0};
  double robot[3];
  apply(t, laser, robot);
  EXPECT_NEAR(robot[0], 1.0, 1e-6);
  EXPECT_NEAR(robot[1], 2.5, 1e-6);
  // Upside down: a roll of 180 degrees about the laser's x, then the yaw.
  const RosTransform flipped = ros_transform_of({0, 0, 90, true}, {}, "base_link", "front");
  EXPECT_NEAR(flipped.rotation[0], std::cos(std::numbers::pi / 4), 1e-12);
  EXPECT_NEAR(flipped.rotation[1], std::sin(std::numbers::pi / 4), 1e-12);
  EXPECT_NEAR(flipped.rotation[2], 0.0, 1e-12);
  EXPECT_NEAR(flipped.rotation[3], 0.0, 1e-12);
}

RosFrameOptions frame_with(bool reversion, bool inverted) {
  RosFrameOptions frame;
  frame.reversion = reversion;
  frame.inverted = inverted;
  return frame;
}

TEST(RosTf, TheUnitFrameHasTheUnitsAnglesCounterClockwiseAboutItsZ) {
  // The official driver's frame: the unit's 0 on -x, 90 on +y, so its z points down.
  const RosTransform unit = ros_unit_transform({}, "laser");
  EXPECT_EQ(unit.parent_frame, "laser");
  EXPECT_EQ(unit.child_frame, "laser_unit");
  EXPECT_NEAR(std::abs(unit.rotation[1]), 1.0, 1e-12);  // a half turn about y
  for (const RosFrameOptions& frame :
       {frame_with(true, true), frame_with(false, true), frame_with(true, false), frame_with(false, false)}) {
    const RosTransform t = ros_unit_transform(frame, "laser");
    for (const float angle : {0.0f, 30.0f, 90.0f, 181.0f, 300.0f}) {
      SCOPED_TRACE(std::to_string(angle) + (frame.reversion ? " rev" : "") + (frame.inverted ? " inv" : ""));
      // Device angle a, counter-clockwise about the unit frame's z, 2 m out...
      const double a = angle * std::numbers::pi / 180.0;
      const double in_unit[3] = {2.0 * std::cos(a), 2.0 * std::sin(a), 0};
      double in_laser[3];
      apply(t, in_unit, in_laser);
      // ...is where /points puts that sample.
      const double r = ros_angle_rad(angle, frame);
      EXPECT_NEAR(in_laser[0], 2.0 * std::cos(r), 1e-9);
      EXPECT_NEAR(in_laser[1], 2.0 * std::sin(r), 1e-9);
      EXPECT_NEAR(in_laser[2], 0.0, 1e-9);
    }
  }
}

TEST(RosTf, EachLidarGetsItsMountAndItsUnitFrame) {
  std::vector<RosTransform> out;
  append_lidar_transforms({0.2, 0, 0, false}, {}, "base_link", "front", out);
  ASSERT_EQ(out.size(), 2u);
  EXPECT_EQ(out[0].parent_frame, "base_link");
  EXPECT_EQ(out[0].child_frame, "front");
  EXPECT_NEAR(out[0].translation[0], 0.2, 1e-12);
  EXPECT_EQ(out[1].parent_frame, "front");
  EXPECT_EQ(out[1].child_frame, "front_unit");
}

}  // namespace
}  // namespace ydscope
