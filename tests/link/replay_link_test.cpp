// ReplayLink: plays back exactly the recorded device->host bytes, pauses, loops, ignores writes,
// and takes its controls from another thread.
#include <unistd.h>

#include <array>
#include <atomic>
#include <filesystem>
#include <thread>
#include <vector>

#include <boost/asio/executor_work_guard.hpp>
#include <boost/asio/post.hpp>
#include <gtest/gtest.h>

#include "core/link/replay_link.h"
#include "link/link_read_support.h"
#include "core/record/recording_writer.h"
#include "support/temp_dir.h"

namespace ydscope {
namespace {

namespace fs = std::filesystem;
using Bytes = std::vector<std::uint8_t>;
constexpr auto kReplayHangGuard = std::chrono::seconds(10);

class ReplayLinkTest : public ::testing::Test {
 protected:
  // Device chunks at 1 ms steps, interleaved with commands that must not be replayed.
  Bytes write_recording(int chunks, std::int64_t step_ns = 1'000'000) {
    RecordingMetadata metadata;
    metadata.model = "G1";
    metadata.baud = 230400;
    std::string error;
    auto writer = RecordingWriter::create(path_, metadata, 0, error);
    EXPECT_TRUE(writer) << error;
    Bytes device;
    const Bytes command{0xA5, 0x60};
    writer->append(Direction::HostToDevice, command, 0);
    for (int i = 0; i < chunks; ++i) {
      Bytes chunk(static_cast<std::size_t>(7 + i % 5));
      for (std::size_t j = 0; j < chunk.size(); ++j) chunk[j] = static_cast<std::uint8_t>(i * 31 + j);
      writer->append(Direction::DeviceToHost, chunk, step_ns * (i + 1));
      if (i % 4 == 0) writer->append(Direction::HostToDevice, command, step_ns * (i + 1));
      device.insert(device.end(), chunk.begin(), chunk.end());
    }
    writer->close();
    return device;
  }

  // Reads until `want` bytes or an error; returns the bytes and the error that ended it.
  static std::pair<Bytes, boost::system::error_code> read_until(boost::asio::io_context& io, ByteLink& link,
                                                                std::size_t want, std::size_t buffer_size = 5) {
    auto result = test::read_from_link(io, link, want, buffer_size, kReplayHangGuard);
    return {std::move(result.bytes), result.end};
  }

  test::TempDir dir_{"replay-link"};
  std::string path_ = dir_.file("recording.ydrec");
};

TEST_F(ReplayLinkTest, OfSeveralLidarsOnlyTheChosenOnesBytesPlay) {
  RecordingMetadata g1;
  g1.model = "G1";
  RecordingMetadata g6;
  g6.model = "G6";
  std::string error;
  auto writer = RecordingWriter::create_sources(path_, {g1, g6}, 0, error);
  ASSERT_TRUE(writer) << error;
  Bytes first, second;
  for (std::uint8_t i = 0; i < 20; ++i) {
    const Bytes a(5, i), b(3, static_cast<std::uint8_t>(100 + i));
    writer->append(Direction::DeviceToHost, a, 1000 * (i + 1), 0);
    writer->append(Direction::DeviceToHost, b, 1000 * (i + 1) + 500, 1);
    first.insert(first.end(), a.begin(), a.end());
    second.insert(second.end(), b.begin(), b.end());
  }
  writer->close();
  for (const std::uint16_t source : {std::uint16_t{0}, std::uint16_t{1}}) {
    boost::asio::io_context io;
    auto link = ReplayLink::open(io, path_, {.speed = 0, .source = source}, error);
    ASSERT_TRUE(link) << error;
    EXPECT_EQ(link->metadata().model, source == 0 ? "G1" : "G6");
    EXPECT_EQ(read_until(io, *link, SIZE_MAX, 4).first, source == 0 ? first : second);
  }
  boost::asio::io_context io;
  EXPECT_FALSE(ReplayLink::open(io, path_, {.speed = 0, .source = 2}, error));
  EXPECT_EQ(error, path_ + " has no source 2 (it holds 2)");
}

// Issue 26: a legal 59 s gap paused a replay for 59 s without a word. At speed 1 it is skipped
// (the read guard is 10 s, so waiting it out would fail here), and whoever plays hears of it.
TEST_F(ReplayLinkTest, ALongGapIsSkippedAndSaidUnlessItIsToBeWaitedOut) {
  RecordingMetadata metadata;
  metadata.model = "G6";
  std::string error;
  auto writer = RecordingWriter::create(path_, metadata, 0, error);
  ASSERT_TRUE(writer) << error;
  const std::int64_t gap_at = 2'000'000, gap = 59'000'000'000;
  for (const std::int64_t t : {std::int64_t{1'000'000}, gap_at, gap_at + gap, gap_at + gap + 1'000'000})
    writer->append(Direction::DeviceToHost, Bytes{static_cast<std::uint8_t>(t % 251)}, t);
  writer->close();
  for (const bool skip : {true, false}) {
    std::vector<std::pair<RecordingGap, bool>> heard;
    ReplayOptions options{.speed = skip ? 1.0 : 1000.0, .skip_gaps = skip};  // waited out: 59 ms
    options.on_gap = [&](const RecordingGap& g, bool skipped) { heard.emplace_back(g, skipped); };
    boost::asio::io_context io;
    auto link = ReplayLink::open(io, path_, options, error);
    ASSERT_TRUE(link) << error;
    const auto [bytes, end] = read_until(io, *link, SIZE_MAX, 8);
    EXPECT_EQ(bytes.size(), 4u) << "skip " << skip;
    EXPECT_EQ(end, boost::asio::error::eof) << "skip " << skip;
    ASSERT_EQ(heard.size(), 1u);
    EXPECT_EQ(heard[0].first.at_ns, gap_at);
    EXPECT_EQ(heard[0].first.length_ns, gap);
    EXPECT_EQ(heard[0].second, skip);
    const ReplayStatus status = link->status();
    EXPECT_EQ(status.gaps, 1u);
    EXPECT_EQ(status.last_gap.length_ns, gap);
    EXPECT_EQ(status.skip_gaps, skip);
    EXPECT_EQ(status.position_ns, status.duration_ns) << "the playback point jumps the gap";
  }
}

TEST_F(ReplayLinkTest, FastestSpeedReturnsExactlyTheDeviceBytesThenEof) {
  const Bytes device = write_recording(40);
  boost::asio::io_context io;
  std::string error;
  auto link = ReplayLink::open(io, path_, {.speed = 0}, error);
  ASSERT_TRUE(link) << error;
  EXPECT_FALSE(link->accepts_commands());
  EXPECT_EQ(link->metadata().model, "G1");
  EXPECT_EQ(link->metadata().baud, 230400u);
  EXPECT_TRUE(link->warnings().empty());
  EXPECT_EQ(link->describe(), "replay of " + fs::path(path_).filename().string());

  const auto [bytes, end] = read_until(io, *link, SIZE_MAX, 5);
  EXPECT_EQ(bytes, device);
  EXPECT_EQ(end, boost::asio::error::eof);
  const auto status = link->status();
  EXPECT_TRUE(status.finished);
  EXPECT_EQ(status.bytes, device.size());
  EXPECT_EQ(status.duration_ns, 40'000'000);
  EXPECT_EQ(status.position_ns, 40'000'000);
}

TEST_F(ReplayLinkTest, OriginalTimingDeliversTheSameBytes) {
  const Bytes device = write_recording(10, 200'000);  // 2 ms of recording
  boost::asio::io_context io;
  std::string error;
  auto link = ReplayLink::open(io, path_, {.speed = 1.0}, error);
  ASSERT_TRUE(link) << error;
  const auto [bytes, end] = read_until(io, *link, SIZE_MAX, 64);
  EXPECT_EQ(bytes, device);
  EXPECT_EQ(end, boost::asio::error::eof);
}

TEST_F(ReplayLinkTest, PausedPlaybackDeliversNothingUntilResumed) {
  const Bytes device = write_recording(5);
  boost::asio::io_context io;
  std::string error;
  auto link = ReplayLink::open(io, path_, {.speed = 0, .paused = true}, error);
  ASSERT_TRUE(link) << error;
  std::array<std::uint8_t, 64> buffer{};
  std::size_t delivered = 0;
  bool called = false;
  link->async_read_some(buffer, [&](const boost::system::error_code& ec, std::size_t n) {
    EXPECT_FALSE(ec);
    delivered = n;
    called = true;
  });
  io.run_for(std::chrono::milliseconds(100));
  EXPECT_FALSE(called);
  EXPECT_TRUE(link->status().paused);

  link->set_paused(false);
  io.restart();
  io.run_for(kReplayHangGuard);
  ASSERT_TRUE(called);
  EXPECT_EQ(Bytes(buffer.begin(), buffer.begin() + static_cast<std::ptrdiff_t>(delivered)),
            Bytes(device.begin(), device.begin() + 7));
  EXPECT_FALSE(link->status().paused);
}

TEST_F(ReplayLinkTest, LoopStartsOverAndStopsWhenLoopIsTurnedOff) {
  const Bytes device = write_recording(6);
  boost::asio::io_context io;
  std::string error;
  auto link = ReplayLink::open(io, path_, {.speed = 0, .loop = true}, error);
  ASSERT_TRUE(link) << error;
  auto [bytes, end] = read_until(io, *link, device.size() * 3, 3);
  EXPECT_FALSE(end);
  ASSERT_GE(bytes.size(), device.size() * 3);
  for (int pass = 0; pass < 3; ++pass)
    EXPECT_EQ(Bytes(bytes.begin() + pass * static_cast<std::ptrdiff_t>(device.size()),
                    bytes.begin() + (pass + 1) * static_cast<std::ptrdiff_t>(device.size())),
              device)
        << "pass " << pass;
  EXPECT_GE(link->status().loops, 2u);

  link->set_loop(false);
  std::tie(bytes, end) = read_until(io, *link, SIZE_MAX, 64);
  EXPECT_EQ(end, boost::asio::error::eof);
  EXPECT_LE(bytes.size(), device.size());  // at most the rest of the current pass
}

TEST_F(ReplayLinkTest, RestartPlaysFromTheBeginningAgain) {
  const Bytes device = write_recording(4);
  boost::asio::io_context io;
  std::string error;
  auto link = ReplayLink::open(io, path_, {.speed = 0}, error);
  ASSERT_TRUE(link) << error;
  auto [first, end1] = read_until(io, *link, SIZE_MAX, 64);
  EXPECT_EQ(end1, boost::asio::error::eof);
  link->restart();  // posted: let the io_context apply it before the next read
  io.restart();
  io.poll();
  auto [second, end2] = read_until(io, *link, SIZE_MAX, 64);
  EXPECT_EQ(second, device);
  EXPECT_EQ(end2, boost::asio::error::eof);
}

TEST_F(ReplayLinkTest, WritesAreAcceptedAndIgnored) {
  write_recording(2);
  boost::asio::io_context io;
  std::string error;
  auto link = ReplayLink::open(io, path_, {}, error);
  ASSERT_TRUE(link) << error;
  const std::array<std::uint8_t, 2> stop{0xA5, 0x65};
  std::size_t written = 0;
  link->async_write(stop, [&](const boost::system::error_code& ec, std::size_t n) {
    EXPECT_FALSE(ec);
    written = n;
  });
  io.run_for(kReplayHangGuard);
  EXPECT_EQ(written, 2u);
  EXPECT_FALSE(link->set_baud(512000, error));
  EXPECT_NE(error.find("no line rate"), std::string::npos);
}

TEST_F(ReplayLinkTest, CloseAbortsAWaitingRead) {
  write_recording(2, 60'000'000'000);  // first bytes a minute in, waited out
  boost::asio::io_context io;
  std::string error;
  auto link = ReplayLink::open(io, path_, {.speed = 1.0, .skip_gaps = false}, error);
  ASSERT_TRUE(link) << error;
  std::array<std::uint8_t, 8> buffer{};
  boost::system::error_code seen;
  link->async_read_some(buffer, [&](const boost::system::error_code& ec, std::size_t) { seen = ec; });
  boost::asio::post(io, [&] { link->close(); });
  io.run_for(kReplayHangGuard);
  EXPECT_EQ(seen, boost::asio::error::operation_aborted);
}

TEST_F(ReplayLinkTest, ControlsFromAnotherThreadWhileItPlays) {
  const Bytes device = write_recording(200, 50'000);
  boost::asio::io_context io;
  std::string error;
  auto link = ReplayLink::open(io, path_, {.speed = 4.0, .loop = true}, error);
  ASSERT_TRUE(link) << error;
  std::atomic<bool> stop{false};
  std::thread ui([&] {  // what the UI does: flip controls and read the status every frame
    for (int i = 0; !stop.load() && i < 2000; ++i) {
      link->set_speed(i % 3 == 0 ? 0.0 : 8.0);
      link->set_paused(i % 7 == 3);
      const auto status = link->status();
      EXPECT_LE(status.position_ns, status.duration_ns + 1'000'000'000);
      std::this_thread::yield();
    }
    link->set_paused(false);
    link->set_speed(0.0);
  });
  const auto [bytes, end] = read_until(io, *link, device.size() * 2, 16);
  stop = true;
  ui.join();
  EXPECT_FALSE(end);
  ASSERT_GE(bytes.size(), device.size() * 2);
  EXPECT_EQ(Bytes(bytes.begin(), bytes.begin() + static_cast<std::ptrdiff_t>(device.size())), device);
}

TEST_F(ReplayLinkTest, LastOwnerMayBeTheUiThread) {
  // The app's shape: the session reads the link on the I/O thread and drops it on disconnect;
  // the UI reaches it through a weak pointer, so its temporary strong pointer may be the last.
  write_recording(50, 10'000);
  for (int round = 0; round < 20; ++round) {
    boost::asio::io_context io;
    auto work = boost::asio::make_work_guard(io);
    std::thread io_thread([&io] { io.run(); });
    std::string error;
    std::shared_ptr<ReplayLink> session_link = ReplayLink::open(io, path_, {.speed = 0, .loop = true}, error);
    ASSERT_TRUE(session_link) << error;
    std::weak_ptr<ReplayLink> ui_link = session_link;
    auto buffer = std::make_shared<std::array<std::uint8_t, 32>>();
    std::atomic<bool> stopped{false};
    std::atomic<int> ui_reached{0};  // times the UI held the link (so it races the close)
    std::atomic<int> bad_status{0};  // status the UI read that no replay can have
    std::function<void()> read_more = [&] {
      if (!session_link) return;
      session_link->async_read_some(*buffer, [&](const boost::system::error_code& ec, std::size_t) {
        if (!ec) read_more();
      });
    };
    boost::asio::post(io, read_more);
    std::thread ui([&] {
      while (!stopped.load()) {
        if (auto link = ui_link.lock()) {
          link->set_speed(round % 2 ? 0.0 : 50.0);
          const auto status = link->status();
          if (status.position_ns < 0 || status.position_ns > status.duration_ns || status.duration_ns <= 0)
            bad_status.fetch_add(1);
          ui_reached.fetch_add(1);
        } else {
          break;
        }
      }
    });
    while (ui_reached.load() == 0) std::this_thread::yield();  // the UI holds the link now and then
    boost::asio::post(io, [&] {                                // disconnect: close and drop the session's reference
      session_link->close();
      session_link.reset();
    });
    while (!ui_link.expired()) std::this_thread::yield();
    stopped = true;
    ui.join();

    work.reset();
    io_thread.join();
    // Reaching here without a crash (or a sanitizer report) is the point; while it held the link,
    // the UI also read a sane status before, during and after the close.
    EXPECT_EQ(bad_status.load(), 0) << "round " << round;
  }
}

TEST_F(ReplayLinkTest, OpenErrorsAreSentences) {
  boost::asio::io_context io;
  std::string error;
  EXPECT_FALSE(ReplayLink::open(io, path_ + ".missing", {}, error));
  EXPECT_NE(error.find("cannot open recording"), std::string::npos) << error;

  std::string create_error;
  auto writer = RecordingWriter::create(path_, {}, 0, create_error);
  ASSERT_TRUE(writer) << create_error;
  const Bytes command{0xA5, 0x90};
  writer->append(Direction::HostToDevice, command, 10);
  writer->close();
  EXPECT_FALSE(ReplayLink::open(io, path_, {}, error));
  EXPECT_NE(error.find("holds no bytes from a device"), std::string::npos) << error;
}

}  // namespace
}  // namespace ydscope
