// Alignment against known poses: laps from the room and booth scenes, one lidar at the scene's
// origin (the reference), another standing at a known pose; alignment starts from rough guesses
// up to 30 degrees and 0.5 m off and must land within 2 cm and 0.5 degree of the truth, or refuse
// with the numbers when the two do not see enough of the same walls.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <vector>

#include "core/align/align.h"
#include "core/align/rigid_motion.h"
#include "tests/align/scene_laps.h"

namespace ydscope::align {
namespace {

constexpr int kLaps = 8;

struct Case {
  std::string scene;
  Pose truth;
};

// Where the second lidar stands, in the common frame of the reference at the scene's origin:
// inside each scene's walls, clear of its furniture and of where its people walk.
std::vector<Case> cases() {
  return {
      {"room", Pose{0.6, -0.4, 35.0, false}},   {"room", Pose{-0.8, 0.5, -120.0, false}},
      {"room", Pose{0.3, 0.9, 170.0, false}},   {"booth", Pose{-0.5, -0.3, 60.0, false}},
      {"booth", Pose{0.7, -0.6, -25.0, false}},
  };
}

// Rough starts: the truth moved by up to 30 degrees and 0.5 m, several ways.
std::vector<Pose> rough_starts(const Pose& truth) {
  const double turns[] = {30.0, -30.0, 15.0, -20.0};
  const double shifts[][2] = {{0.5, 0.0}, {0.0, -0.5}, {-0.35, 0.35}, {0.3, 0.4}};
  std::vector<Pose> starts;
  for (int i = 0; i < 4; ++i) {
    Pose start = truth;
    start.x_m += shifts[i][0];
    start.y_m += shifts[i][1];
    start.yaw_deg += turns[i];
    starts.push_back(start);
  }
  return starts;
}

double position_error_mm(const Pose& a, const Pose& b) { return 1000.0 * std::hypot(a.x_m - b.x_m, a.y_m - b.y_m); }
double yaw_error_deg(const Pose& a, const Pose& b) { return std::abs(std::remainder(a.yaw_deg - b.yaw_deg, 360.0)); }

TEST(Align, FindsKnownPosesFromRoughStartsInTwoScenes) {
  double worst_mm = 0, worst_deg = 0, worst_residual_mm = 0, least_overlap = 1;
  for (const Case& c : cases()) {
    const std::vector<Lap> reference = test::scene_laps(c.scene, std::nullopt, kLaps, 3);
    const std::vector<Lap> lidar = test::scene_laps(c.scene, c.truth, kLaps, 3);
    for (const Pose& start : rough_starts(c.truth)) {
      SCOPED_TRACE(c.scene + " truth " + format_pose(c.truth) + " start " + format_pose(start));
      const AlignResult r = align_to_reference(reference, Pose{}, lidar, start);
      ASSERT_EQ(r.verdict, AlignVerdict::Aligned) << r.message;
      EXPECT_LT(position_error_mm(r.pose, c.truth), 20.0) << format_pose(r.pose);
      EXPECT_LT(yaw_error_deg(r.pose, c.truth), 0.5) << format_pose(r.pose);
      EXPECT_GT(r.overlap, 0.3);
      EXPECT_LT(r.residual_mm, 30.0);
      EXPECT_NE(r.message.find("mm"), std::string::npos) << r.message;
      worst_mm = std::max(worst_mm, position_error_mm(r.pose, c.truth));
      worst_deg = std::max(worst_deg, yaw_error_deg(r.pose, c.truth));
      worst_residual_mm = std::max(worst_residual_mm, r.residual_mm);
      least_overlap = std::min(least_overlap, r.overlap);
    }
  }
  // The figures docs/align.md quotes.
  std::printf("worst of %zu alignments: %.1f mm, %.3f deg off; residual up to %.1f mm; overlap from %.0f %%\n",
              cases().size() * 4, worst_mm, worst_deg, worst_residual_mm, 100.0 * least_overlap);
}

TEST(Align, ReferenceElsewhereInTheFrameMovesTheResultWithIt) {
  // The reference itself posed: the answer is the truth carried into the reference's frame.
  const Pose reference_pose{1.0, -2.0, 90.0, false};
  const Pose truth{0.6, -0.4, 35.0, false};
  const std::vector<Lap> reference = test::scene_laps("room", std::nullopt, kLaps, 5);
  const std::vector<Lap> lidar = test::scene_laps("room", truth, kLaps, 5);
  const Pose expected = moved_pose(truth, motion_between(Pose{}, reference_pose));
  Pose start = expected;
  start.yaw_deg += 20.0;
  start.x_m -= 0.3;
  const AlignResult r = align_to_reference(reference, reference_pose, lidar, start);
  ASSERT_EQ(r.verdict, AlignVerdict::Aligned) << r.message;
  EXPECT_LT(position_error_mm(r.pose, expected), 20.0) << format_pose(r.pose) << " vs " << format_pose(expected);
  EXPECT_LT(yaw_error_deg(r.pose, expected), 0.5) << format_pose(r.pose) << " vs " << format_pose(expected);
}

TEST(Align, RefusesWhenTheLidarSeesTooLittleOfTheSameWalls) {
  const Pose truth{0.6, -0.4, 35.0, false};
  const std::vector<Lap> reference = test::scene_laps("room", std::nullopt, kLaps);
  std::vector<Lap> lidar = test::scene_laps("room", truth, kLaps);
  // Something blocks all but a 25 degree slice of its view: one stretch of one wall.
  for (Lap& lap : lidar)
    for (LapPoint& p : lap.points)
      if (p.angle_deg > 25.0f) p.range_mm = 0.0f;
  const AlignResult r = align_to_reference(reference, Pose{}, lidar, truth);
  EXPECT_EQ(r.verdict, AlignVerdict::NotEnoughOverlap) << r.message;
  EXPECT_EQ(r.message.rfind("not enough overlap", 0), 0u) << r.message;
  EXPECT_NE(r.message.find("points"), std::string::npos) << r.message;
}

TEST(Align, RefusesTwoLidarsInDifferentPlaces) {
  // The reference in the room, the other in the booth: nothing in common, whatever the start.
  const std::vector<Lap> reference = test::scene_laps("room", std::nullopt, kLaps);
  const std::vector<Lap> lidar = test::scene_laps("booth", std::nullopt, kLaps);
  const AlignResult r = align_to_reference(reference, Pose{}, lidar, Pose{});
  EXPECT_NE(r.verdict, AlignVerdict::Aligned) << r.message;
}

TEST(Align, OneLapIsNotEnoughToTellWallsFromPassersBy) {
  const std::vector<Lap> reference = test::scene_laps("room", std::nullopt, 1);
  const std::vector<Lap> lidar = test::scene_laps("room", Pose{0.5, 0, 0, false}, 1);
  const AlignResult r = align_to_reference(reference, Pose{}, lidar, Pose{});
  EXPECT_EQ(r.verdict, AlignVerdict::NotEnoughOverlap);
  EXPECT_NE(r.message.find("laps"), std::string::npos) << r.message;
}

TEST(RigidMotion, MovedPoseFollowsTheFramesTransform) {
  // Whatever the pose convention, moving a pose by the motion between two poses lands on the second,
  // and every point of its cloud lands where the second pose puts it (upside down too).
  const Pose poses[] = {{0.2, -0.1, 30, false}, {-1.5, 2.0, -170, true}, {3.0, 0.0, 95, false}};
  for (const Pose& from : poses)
    for (const Pose& to : poses) {
      if (from.upside_down != to.upside_down) continue;
      const RigidMotion m = motion_between(from, to);
      const Pose moved = moved_pose(from, m);
      EXPECT_NEAR(moved.x_m, to.x_m, 1e-6);
      EXPECT_NEAR(moved.y_m, to.y_m, 1e-6);
      EXPECT_NEAR(yaw_error_deg(moved, to), 0.0, 1e-4);
      const LapPoint p{123.0f, 2500.0f, PointFlag::None};
      const CommonPoint a = from.to_common(p);
      const Point2 carried = m.apply({a.x_mm, a.y_mm});
      const CommonPoint b = to.to_common(p);
      EXPECT_NEAR(carried.x, b.x_mm, 0.05);
      EXPECT_NEAR(carried.y, b.y_mm, 0.05);
    }
}

TEST(PosedScene, TheSceneAtTheIdentityPoseIsTheSceneItself) {
  const std::vector<Lap> plain = test::scene_laps("room", std::nullopt, 1);
  const std::vector<Lap> posed = test::scene_laps("room", Pose{}, 1);
  ASSERT_EQ(plain[0].points.size(), posed[0].points.size());
  for (std::size_t i = 0; i < plain[0].points.size(); ++i)
    EXPECT_NEAR(plain[0].points[i].range_mm, posed[0].points[i].range_mm, 0.5) << "at " << plain[0].points[i].angle_deg;
}

TEST(PosedScene, TheDemoSceneCannotBePosedAndSaysWhy) {
  try {
    PosedScene scene(make_scene("demo", 1), Pose{1, 0, 0, false});
    FAIL() << "the demo scene took a pose";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("room or booth"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace ydscope::align
