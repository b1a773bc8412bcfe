// The state-to-overlay mapping: a picture that is not live is always dimmed and says why in words.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "ui/view/status/view_state.h"

namespace ydscope::ui {
namespace {

ViewStateInput scanning(double seconds_since_lap) {
  ViewStateInput in;
  in.state = LinkState::Scanning;
  in.address = "/dev/ttyUSB0";
  in.has_source = true;
  in.seconds_since_lap = seconds_since_lap;
  return in;
}

TEST(ViewState, FreshLapsWhileScanningAreLive) {
  const ViewState v = describe_view_state(scanning(0.1));
  EXPECT_TRUE(v.live);
  EXPECT_FALSE(v.dim);
  EXPECT_EQ(v.severity, Severity::Ok);
  EXPECT_EQ(v.status, "scanning");
}

TEST(ViewState, ReconnectingDimsAndSaysWhereAndHowOld) {
  ViewStateInput in = scanning(12.2);
  in.state = LinkState::Reconnecting;
  in.link_message = "the port disappeared; retrying in 2 s";
  const ViewState v = describe_view_state(in);
  EXPECT_FALSE(v.live);
  EXPECT_TRUE(v.dim);
  EXPECT_EQ(v.severity, Severity::Warning);
  EXPECT_EQ(v.headline, "No data");
  EXPECT_EQ(v.subtitle, "reconnecting to /dev/ttyUSB0, last lap 12 s ago");
  EXPECT_EQ(v.detail, "the port disappeared; retrying in 2 s");
  EXPECT_EQ(v.status, "reconnecting");
}

TEST(ViewState, ScanningWithoutNewLapsIsNotLive) {
  // The link may still say "scanning" before its stall timeout: the lap age decides.
  const ViewState v = describe_view_state(scanning(kStaleLapSeconds + 0.5));
  EXPECT_FALSE(v.live);
  EXPECT_TRUE(v.dim);
  EXPECT_EQ(v.severity, Severity::Warning);
  EXPECT_NE(v.subtitle.find("sends no laps"), std::string::npos) << v.subtitle;
}

TEST(ViewState, ScanningBeforeTheFirstLapWaits) {
  ViewStateInput in = scanning(0.0);
  in.seconds_since_lap.reset();
  const ViewState v = describe_view_state(in);
  EXPECT_TRUE(v.dim);
  EXPECT_EQ(v.severity, Severity::Info);
  EXPECT_NE(v.subtitle.find("no lap yet"), std::string::npos) << v.subtitle;
}

TEST(ViewState, EveryStateButLiveScanningDims) {
  for (const LinkState state : {LinkState::Idle, LinkState::Connecting, LinkState::Probing, LinkState::Ready,
                                LinkState::Stalled, LinkState::Reconnecting, LinkState::Failed}) {
    ViewStateInput in = scanning(0.1);  // even with a fresh lap in hand
    in.state = state;
    const ViewState v = describe_view_state(in);
    EXPECT_TRUE(v.dim) << link_state_name(state);
    EXPECT_FALSE(v.live) << link_state_name(state);
    EXPECT_FALSE(v.headline.empty()) << link_state_name(state);
    EXPECT_FALSE(v.subtitle.empty()) << link_state_name(state);
  }
}

TEST(ViewState, FailedIsAnErrorButAnEndedReplayIsNot) {
  ViewStateInput in = scanning(3.0);
  in.state = LinkState::Failed;
  EXPECT_EQ(describe_view_state(in).severity, Severity::Error);
  in.replay = true;
  in.address = "recording demo.ydrec";
  const ViewState v = describe_view_state(in);
  EXPECT_EQ(v.headline, "Replay ended");
  EXPECT_EQ(v.severity, Severity::Info);
  EXPECT_NE(v.subtitle.find("recording demo.ydrec played to the end"), std::string::npos) << v.subtitle;
}

TEST(ViewState, PausedReplayIsDimmedAndSaysSo) {
  ViewStateInput in = scanning(5.0);
  in.replay = true;
  in.replay_paused = true;
  const ViewState v = describe_view_state(in);
  EXPECT_TRUE(v.dim);
  EXPECT_EQ(v.headline, "Replay paused");
}

TEST(ViewState, NoSourceSaysDisconnected) {
  ViewStateInput in;
  const ViewState v = describe_view_state(in);
  EXPECT_TRUE(v.dim);
  EXPECT_EQ(v.headline, "Disconnected");
  EXPECT_EQ(v.status, "disconnected");
}

// Issue 17: the app once showed a recording it could not play as "Disconnected" (or retried it
// for ever); now the overlay carries the sentence ydscope-cli gives (core/record/recording_plan.h).
TEST(ViewState, ASourceThatDidNotStartSaysWhyInLargeWords) {
  ViewStateInput in;
  in.replay = true;
  in.start_error = "x.ydrec does not say which lidar made it; pass --model (G1, G6, TG15, TG30, TG50)";
  ViewState v = describe_view_state(in);
  EXPECT_TRUE(v.dim);
  EXPECT_EQ(v.severity, Severity::Error);
  EXPECT_EQ(v.headline, "Cannot replay");
  EXPECT_EQ(v.subtitle, in.start_error);
  EXPECT_NE(v.detail.find("a model to decode it as"), std::string::npos) << v.detail;
  EXPECT_EQ(v.status, "cannot replay");
  in.replay = false;
  in.start_error = "the virtual lidar did not start: no pseudo-terminal";
  v = describe_view_state(in);
  EXPECT_EQ(v.headline, "Cannot connect");
  EXPECT_EQ(v.subtitle, in.start_error);
}

TEST(ViewState, ASourcesWarningsAreSaidLiveOrNot) {
  const std::vector<std::string> warnings{
      "cut.ydrec ends inside a record at byte 9 (the recorder was probably stopped "
      "abruptly); the 3 records before it are intact"};
  ViewStateInput in = scanning(0.1);
  in.replay = true;
  in.source_warnings = warnings;
  ViewState v = describe_view_state(in);
  EXPECT_TRUE(v.live);
  EXPECT_EQ(v.notices, warnings);
  in.replay_paused = true;
  EXPECT_EQ(describe_view_state(in).notices, warnings);
  in.source_warnings = {};
  EXPECT_TRUE(describe_view_state(in).notices.empty());
}

TEST(ViewState, AReplayThatWentRoundWithoutALapGivesUp) {
  ViewStateInput in = scanning(0.0);
  in.seconds_since_lap.reset();
  in.replay = true;
  in.address = "recording junk.ydrec";
  in.model = "G6";
  EXPECT_FALSE(describe_view_state(in).give_up) << "the first pass may still bring one";
  in.replay_passes = 1;
  const ViewState v = describe_view_state(in);
  EXPECT_TRUE(v.give_up);
  EXPECT_TRUE(v.dim);
  EXPECT_EQ(v.severity, Severity::Error);
  EXPECT_EQ(v.headline, "No laps");
  EXPECT_EQ(v.subtitle, "recording junk.ydrec played through without one complete lap");
  EXPECT_NE(v.detail.find("its bytes are not G6 scan packets"), std::string::npos) << v.detail;
  in.replay_paused = true;  // the app pauses it: still the reason, not "paused"
  EXPECT_EQ(describe_view_state(in).headline, "No laps");
  in.seconds_since_lap = 30.0;  // it did give laps once: going round is fine
  EXPECT_FALSE(describe_view_state(in).give_up);
}

// Issue 26: a recording of G6 packets too short for a lap was "not G6 scan packets".
TEST(ViewState, AReplayOfPacketsTooShortForALapSaysSo) {
  ViewStateInput in = scanning(0.0);
  in.seconds_since_lap.reset();
  in.replay = true;
  in.replay_passes = 1;
  in.address = "recording short.ydrec";
  in.model = "G6";
  in.decoded = {72, 3, 1};
  const ViewState v = describe_view_state(in);
  EXPECT_TRUE(v.give_up);
  EXPECT_EQ(v.detail,
            "its 3 G6 scan packets (72 bytes) are too short for a lap, which runs from a zero packet to the next zero "
            "packet; they hold 1 zero packet (counted over every pass so far); record at least one whole turn");
}

TEST(ViewState, AReplayThatFailedBeforeItsFirstLapCouldNotPlay) {
  ViewStateInput in = scanning(0.0);
  in.seconds_since_lap.reset();
  in.state = LinkState::Failed;
  in.replay = true;
  in.address = "recording gone.ydrec";
  in.link_message = "cannot open gone.ydrec: No such file or directory";
  ViewState v = describe_view_state(in);
  EXPECT_EQ(v.headline, "Cannot replay");
  EXPECT_EQ(v.severity, Severity::Error);
  EXPECT_EQ(v.detail, in.link_message);
  // One that played laps and ended does not repeat the link's words about unplugged devices.
  in.seconds_since_lap = 2.0;
  in.link_message = "the link to replay of demo.ydrec closed (device unplugged or bridge gone)";
  v = describe_view_state(in);
  EXPECT_EQ(v.headline, "Replay ended");
  EXPECT_EQ(v.detail, "");
}

TEST(ViewState, CommandPauseIsLiveUntilTheLapsGoStale) {
  ViewStateInput in = scanning(0.4);
  in.state = LinkState::CommandInProgress;
  EXPECT_TRUE(describe_view_state(in).live);
  in.seconds_since_lap = 5.0;
  EXPECT_TRUE(describe_view_state(in).dim);
}

TEST(ViewState, AgesReadShort) {
  EXPECT_EQ(format_age(0.2), "0 s");
  EXPECT_EQ(format_age(12.4), "12 s");
  EXPECT_EQ(format_age(125.0), "2 min 5 s");
  EXPECT_EQ(format_age(3 * 3600.0 + 120.0), "3 h 2 min");
  EXPECT_EQ(format_age(-1.0), "0 s");
}

}  // namespace
}  // namespace ydscope::ui
