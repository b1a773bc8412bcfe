// Record then replay gives back the same laps: a session records the virtual lidar while the test
// takes its live laps; the recording, replayed through ReplayLink and decoded, holds exactly those
// laps, point for point, in order.
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <functional>
#include <future>
#include <vector>

#include <gtest/gtest.h>

#include "core/link/replay_link.h"
#include "core/session/session.h"
#include "core/protocol/scan_decoder.h"
#include "core/sim/sim_server.h"
#include "core/record/recorded_conventions.h"
#include "test_data.h"
#include "support/temp_dir.h"

namespace ydscope {
namespace {

namespace fs = std::filesystem;

bool same_points(const Lap& a, const Lap& b) {
  if (a.points.size() != b.points.size() || a.packets != b.packets) return false;
  for (std::size_t i = 0; i < a.points.size(); ++i) {
    const LapPoint& p = a.points[i];
    const LapPoint& q = b.points[i];
    if (p.angle_deg != q.angle_deg || p.range_mm != q.range_mm || p.flag != q.flag) return false;
  }
  return true;
}

CommandResult wait_result(std::future<CommandResult>& result) {
  if (result.wait_for(std::chrono::seconds(20)) != std::future_status::ready) {
    CommandResult timeout;
    timeout.message = "no answer within 20 s";
    return timeout;
  }
  return result.get();
}

void record_and_replay(Model model) {
  const test::TempDir dir("replay-session");
  const std::string file = dir.file("recording.ydrec");
  SimServerOptions options;
  options.device.model = model;
  options.device.scene = "room";
  SimServer sim(options);
  sim.start();

  std::vector<Lap> live;
  {
    Session session(256);
    SessionConfig config;
    config.address = sim.device_path();
    config.reconnect = false;
    session.connect(config);
    const auto scanning = session.wait_until(
        [](const SessionSnapshot& s) { return s.state == LinkState::Scanning || s.state == LinkState::Failed; },
        std::chrono::seconds(20));
    ASSERT_EQ(scanning.state, LinkState::Scanning) << scanning.message;

    std::promise<CommandResult> started;
    session.start_recording(file, [&started](const CommandResult& r) { started.set_value(r); });
    auto started_future = started.get_future();
    const CommandResult start = wait_result(started_future);
    ASSERT_TRUE(start.ok) << start.message;
    Lap discard;
    while (session.laps().try_pop(discard)) {  // laps completed before the recording began
    }
    Lap lap;
    const auto give_up = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    while (live.size() < 8 && std::chrono::steady_clock::now() < give_up) {
      if (session.laps().try_pop(lap))
        live.push_back(lap);
      else
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    std::promise<CommandResult> stopped;
    session.stop_recording([&stopped](const CommandResult& r) { stopped.set_value(r); });
    auto stopped_future = stopped.get_future();
    ASSERT_TRUE(wait_result(stopped_future).ok);
    EXPECT_EQ(session.snapshot().queue_dropped, 0u);
    session.disconnect();
  }
  sim.stop();
  ASSERT_EQ(live.size(), 8u);

  boost::asio::io_context io;
  std::string error;
  auto link = ReplayLink::open(io, file, {.speed = 0}, error);
  ASSERT_TRUE(link) << error;
  ASSERT_TRUE(link->metadata().model);
  const ModelProfile* profile = find_profile(*link->metadata().model);
  ASSERT_NE(profile, nullptr);
  EXPECT_EQ(profile->model, model);
  // Read back as it was read live: the recording names its conventions.
  ASSERT_TRUE(link->metadata().conventions.has_value());
  ScanDecoder decoder(*profile, recorded_conventions(link->metadata(), *profile, std::nullopt),
                      link->metadata().distance_scale);
  std::vector<Lap> replayed;
  std::array<std::uint8_t, 512> buffer{};
  std::function<void()> read_more = [&] {
    link->async_read_some(buffer, [&](const boost::system::error_code& ec, std::size_t n) {
      decoder.feed({buffer.data(), n}, 0, [&](const Lap& lap) { replayed.push_back(lap); });
      if (!ec) read_more();
    });
  };
  read_more();
  io.run_for(std::chrono::seconds(30));

  // The first live lap may have begun before the recording did; every later one must be in the
  // replay, consecutively.
  std::size_t at = 0;
  while (at < replayed.size() && !same_points(replayed[at], live[1])) ++at;
  ASSERT_LT(at, replayed.size()) << "live lap 1 not found among " << replayed.size() << " replayed laps";
  for (std::size_t i = 1; i < live.size(); ++i) {
    ASSERT_LT(at + i - 1, replayed.size());
    EXPECT_TRUE(same_points(replayed[at + i - 1], live[i])) << "live lap " << i;
  }
  EXPECT_GT(live[1].points.size(), 100u);
}

TEST(RecordThenReplay, G1GivesBackTheSameLaps) { record_and_replay(Model::G1); }
TEST(RecordThenReplay, G6GivesBackTheSameLaps) { record_and_replay(Model::G6); }
TEST(RecordThenReplay, Tg30GivesBackTheSameLaps) { record_and_replay(Model::TG30); }

TEST(ReplayThroughASession, ShowsTheDeviceTheRecordingCameFrom) {
  const std::string file = (test::assets_dir() / "demo-g6.ydrec").string();
  Session session(16);
  SessionConfig config;
  config.address = file;
  config.model = Model::G6;
  config.reconnect = false;
  config.open_link = [file](boost::asio::io_context& io, std::uint32_t,
                            std::string& error) -> std::unique_ptr<ByteLink> {
    return ReplayLink::open(io, file, {.speed = 1}, error);
  };
  session.connect(config);
  const auto s = session.wait_until([](const SessionSnapshot& x) { return x.state == LinkState::Scanning; },
                                    std::chrono::seconds(20));
  ASSERT_EQ(s.state, LinkState::Scanning) << s.message;
  ASSERT_TRUE(s.device);
  EXPECT_EQ(s.device->profile->model, Model::G6);
  EXPECT_EQ(s.device->model_code, 13);
  EXPECT_EQ(s.device->firmware.major, 1);
  EXPECT_EQ(s.device->firmware.minor, 2);
  EXPECT_EQ(s.device->hardware, 1);
  EXPECT_EQ(s.device->serial, "4443985271891104");
  session.disconnect();
}

}  // namespace
}  // namespace ydscope
