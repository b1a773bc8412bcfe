// Issue 17: a lap longer than Lap::kMaxPoints is cut, and says how many points it lost. decode's
// summary carried the count; a live session's counters (and so scan's summary and the app's
// statistics) did not. Here the overlong lap reaches a session through a replay, as the app reads it.
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "core/link/replay_link.h"
#include "core/session/session.h"
#include "core/protocol_test_support.h"
#include "support/raw_recording.h"
#include "support/temp_dir.h"

namespace ydscope {
namespace {

TEST(SessionCutPoints, ALiveSessionCountsThePointsItCut) {
  test::Bytes stream = test::packet(kCtLapStart, 0.0, 0.0, {40});
  for (int i = 0; i < 110; ++i) test::append(stream, test::packet(0, 10.0, 20.0, std::vector<std::uint16_t>(255, 400)));
  test::append(stream, test::packet(kCtLapStart, 0.0, 0.0, {40}));
  test::RawRecording recording;  // model G6
  recording.add(RecordType::DeviceToHost, 0, stream);
  const test::TempDir dir("cut-points");
  const std::string file = dir.file("cut.ydrec");
  recording.write(file);

  Session session(4);
  SessionConfig config;
  config.address = file;
  config.model = Model::G6;
  config.reconnect = false;
  config.open_link = [file](boost::asio::io_context& io, std::uint32_t,
                            std::string& error) -> std::unique_ptr<ByteLink> {
    return ReplayLink::open(io, file, {.speed = 0}, error);
  };
  session.connect(config);
  // The replay ends after its one lap; the counters stay until the next connection.
  const auto s = session.wait_until([](const SessionSnapshot& x) { return x.state == LinkState::Failed; },
                                    std::chrono::seconds(20));
  ASSERT_EQ(s.state, LinkState::Failed) << s.message;
  EXPECT_EQ(s.counters.laps, 1u);
  EXPECT_EQ(s.counters.cut_points, 1 + 110 * 255 - Lap::kMaxPoints);
  Lap lap;
  ASSERT_TRUE(session.laps().try_pop(lap));
  EXPECT_EQ(lap.cut_points, s.counters.cut_points);
}

}  // namespace
}  // namespace ydscope
