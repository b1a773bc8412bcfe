// Several record taps at once: the app shares its source over the Foxglove bridge while an MCAP
// recording of it starts and stops, each from a tap of its own. Both taps get every device byte
// from the moment they start, and closing one leaves the other open and fed.
#include <gtest/gtest.h>

#include "core/session/record_tap.h"
#include "core/session/source_set.h"
#include "support/session_test_support.h"

namespace ydscope {
namespace {

using namespace test;

// The device bytes a tap holds now (waiting up to `wait` for the first), and whether it is open.
std::size_t device_bytes_in(RecordTap& tap, bool& open,
                            std::chrono::milliseconds wait = std::chrono::milliseconds(500)) {
  std::vector<TapRecord> records;
  open = tap.wait_and_take(records, wait);
  std::size_t bytes = 0;
  for (const TapRecord& r : records)
    if (r.type == RecordType::DeviceToHost) bytes += r.payload.size();
  tap.recycle(records);
  return bytes;
}

TEST(SessionTaps, TwoTapsAreFedAtOnceAndStopOneByOne) {
  SimOnPty sim(Model::G6);
  Session session(64);
  auto share = std::make_shared<RecordTap>();
  auto mcap = std::make_shared<RecordTap>();
  ASSERT_TRUE(run_command([&](CommandCallback done) { session.start_tap(share, done); }).ok);
  session.connect(config_for(sim.port()));
  ASSERT_EQ(take_laps(session, 2), 2u) << describe_snapshot(session.snapshot());
  ASSERT_TRUE(run_command([&](CommandCallback done) { session.start_tap(mcap, done); }).ok);
  bool open = false;
  device_bytes_in(*share, open);  // what came before the second tap
  ASSERT_EQ(take_laps(session, 2), 2u);

  // Both saw the last two laps' bytes, and the same ones: the taps are fed from one place.
  std::size_t share_bytes = device_bytes_in(*share, open);
  std::size_t mcap_bytes = device_bytes_in(*mcap, open);
  EXPECT_GT(share_bytes, 1000u);
  EXPECT_GT(mcap_bytes, 1000u);

  const CommandResult stopped = run_command([&](CommandCallback done) { session.stop_tap(mcap, done); });
  EXPECT_TRUE(stopped.ok);
  EXPECT_EQ(stopped.message, "tap closed");
  device_bytes_in(*mcap, open);
  EXPECT_FALSE(open) << "the stopped tap is closed";
  device_bytes_in(*share, open);
  ASSERT_EQ(take_laps(session, 2), 2u);
  share_bytes = device_bytes_in(*share, open);
  EXPECT_TRUE(open) << "the other tap stays open";
  EXPECT_GT(share_bytes, 1000u) << "and is still fed";

  // A tap that is not the session's is not closed by asking.
  auto stranger = std::make_shared<RecordTap>();
  EXPECT_EQ(run_command([&](CommandCallback done) { session.stop_tap(stranger, done); }).message,
            "that tap was not open");
  device_bytes_in(*stranger, open, std::chrono::milliseconds(10));
  EXPECT_TRUE(open);
}

// A .ydrec and an MCAP file of one run come from two taps of each session: closed together, they
// end at the same byte, so both files hold the same laps (closed one by one, a read could land
// between the two closes, and under load the MCAP file once held a lap the .ydrec did not).
TEST(SessionTaps, TapsClosedTogetherEndAtTheSameByte) {
  for (int round = 0; round < 3; ++round) {
    SimOnPty sim(Model::G6);
    Session session(64);
    auto ydrec = std::make_shared<RecordTap>();
    auto mcap = std::make_shared<RecordTap>();
    ASSERT_TRUE(run_command([&](CommandCallback done) { session.start_tap(ydrec, done); }).ok);
    ASSERT_TRUE(run_command([&](CommandCallback done) { session.start_tap(mcap, done); }).ok);
    session.connect(config_for(sim.port()));
    ASSERT_EQ(take_laps(session, 2), 2u) << describe_snapshot(session.snapshot());

    for (auto& closed : close_taps_together({{&session, ydrec}, {&session, mcap}})) EXPECT_TRUE(closed.get().ok);
    std::size_t ydrec_bytes = 0, mcap_bytes = 0;
    for (bool open = true; open;) ydrec_bytes += device_bytes_in(*ydrec, open);
    for (bool open = true; open;) mcap_bytes += device_bytes_in(*mcap, open);
    EXPECT_GT(ydrec_bytes, 1000u);
    EXPECT_EQ(ydrec_bytes, mcap_bytes) << "round " << round;
  }
}

}  // namespace
}  // namespace ydscope
