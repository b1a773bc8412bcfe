// A long gap in a recording (core/record/recording_gap.h): what counts as one, and the words that
// ydscope-cli replay and the app say about it.
#include <gtest/gtest.h>

#include "core/record/recording_gap.h"

namespace ydscope {
namespace {

TEST(RecordingGap, OnlyAnOutageLongerThanACommandsPauseIsAGap) {
  EXPECT_FALSE(long_gap(1'000'000'000, 1'000'000'000 + kLongGapNs));
  const auto gap = long_gap(12'300'000'000, 71'300'000'000);
  ASSERT_TRUE(gap);
  EXPECT_EQ(gap->at_ns, 12'300'000'000);
  EXPECT_EQ(gap->length_ns, 59'000'000'000);
  EXPECT_EQ(long_gap(0, 6'000'000'000)->at_ns, 0) << "silence from the start is a gap too";
}

TEST(RecordingGap, SaysWhereItIsHowLongAndWhatPlaybackDoes) {
  const RecordingGap gap{12'300'000'000, 59'000'000'000};
  EXPECT_EQ(gap_sentence(gap, true),
            "the recording has a gap of 59.0 s at 12.3 s without a byte from the lidar; skipped to 71.3 s");
  EXPECT_EQ(gap_sentence(gap, false),
            "the recording has a gap of 59.0 s at 12.3 s without a byte from the lidar; waiting it out, playing on "
            "at 71.3 s");
  // The view shows it from the gap to kGapNoticeNs after it, no longer.
  EXPECT_EQ(gap_notice(gap, true, 71'300'000'000), "gap in recording: 59 s at 12 s, skipped");
  EXPECT_EQ(gap_notice(gap, false, 30'000'000'000), "gap in recording: 59 s at 12 s, waiting it out");
  EXPECT_EQ(gap_notice(gap, true, 71'300'000'000 + kGapNoticeNs + 1), "");
  EXPECT_EQ(gap_notice(gap, true, 12'000'000'000), "");
  EXPECT_EQ(gap_notice(RecordingGap{}, true, 0), "") << "no gap yet";
}

}  // namespace
}  // namespace ydscope
