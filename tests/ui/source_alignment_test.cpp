// The Sources tab's Align, without a display: laps from the room scene, one lidar at its origin
// and one at a known pose; the proposal holds the pose found for the second, none for the
// reference, and a sentence instead of a pose when there is nothing to match.
#include <gtest/gtest.h>

#include <cmath>

#include "tests/align/scene_laps.h"
#include "ui/view/scene/source_alignment.h"

namespace ydscope::ui {
namespace {

TEST(SourceAlignment, ProposesTheKnownPoseAndKeepsTheReference) {
  const Pose truth{0.6, -0.4, 35.0, false};
  const std::vector<std::vector<Lap>> laps{test::scene_laps("room", std::nullopt, 8),
                                           test::scene_laps("room", truth, 8)};
  std::vector<SourceLook> looks(2);
  looks[0].name = "front";
  looks[1].name = "rear";
  looks[1].pose = Pose{0.3, -0.1, 10.0, false};  // where the user dragged it, roughly
  const AlignmentProposal proposal = propose_alignment(laps, looks);
  ASSERT_EQ(proposal.rows.size(), 2u);
  EXPECT_FALSE(proposal.rows[0].pose);
  EXPECT_EQ(proposal.rows[0].text.rfind("front: the reference", 0), 0u) << proposal.rows[0].text;
  ASSERT_TRUE(proposal.rows[1].pose) << proposal.rows[1].text;
  EXPECT_LT(1000.0 * std::hypot(proposal.rows[1].pose->x_m - truth.x_m, proposal.rows[1].pose->y_m - truth.y_m), 20.0);
  EXPECT_LT(std::abs(std::remainder(proposal.rows[1].pose->yaw_deg - truth.yaw_deg, 360.0)), 0.5);
  EXPECT_NE(proposal.rows[1].text.find("residual"), std::string::npos) << proposal.rows[1].text;
  EXPECT_TRUE(proposal.any_found());
}

TEST(SourceAlignment, NoLapsYetIsASentenceNotAPose) {
  const std::vector<std::vector<Lap>> laps(2);
  std::vector<SourceLook> looks(2);
  looks[0].name = "front";
  looks[1].name = "rear";
  const AlignmentProposal proposal = propose_alignment(laps, looks);
  ASSERT_EQ(proposal.rows.size(), 2u);
  EXPECT_FALSE(proposal.rows[1].pose);
  EXPECT_NE(proposal.rows[1].text.find("laps"), std::string::npos) << proposal.rows[1].text;
  EXPECT_FALSE(proposal.any_found());
}

}  // namespace
}  // namespace ydscope::ui
