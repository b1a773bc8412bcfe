// The state-to-overlay mapping: a picture that is not live is always dimmed and says why in words.
#include <gtest/gtest.h>

#include "ui/view/view_state.h"

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
  for (const LinkState state : {LinkState::Idle, LinkState::Connecting, LinkState::Probing, LinkState::Ready, LinkState::Stalled,
                                LinkState::Reconnecting, LinkState::Failed}) {
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
