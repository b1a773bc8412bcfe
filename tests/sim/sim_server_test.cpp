// SimServer behind a real pseudo-terminal and a TCP port, talked to by a plain POSIX host.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <atomic>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <functional>
#include <mutex>
#include <thread>

#include "core/protocol/scan_decoder.h"
#include "core/sim/sim_server.h"
#include "sim/host_port.h"
#include "sim/sim_test_support.h"
#include "support/field_decoder.h"

namespace ydscope {
namespace {

using namespace std::chrono_literals;
using test::Clock;
using test::HostPort;

using test::kScanHeader;

std::filesystem::path temp_root() {
  return std::filesystem::temp_directory_path() / ("ydscope-sim-test-" + std::to_string(::getpid()));
}

// Removes this run's links and logs when the test program ends.
struct TempCleanup : ::testing::Environment {
  void TearDown() override {
    std::error_code ignored;
    std::filesystem::remove_all(temp_root(), ignored);
  }
};
[[maybe_unused]] ::testing::Environment* const kCleanup = ::testing::AddGlobalTestEnvironment(new TempCleanup);

std::string temp_path(const std::string& name) {
  const auto dir = temp_root() / ::testing::UnitTest::GetInstance()->current_test_info()->name();
  std::filesystem::create_directories(dir);
  return (dir / name).string();
}

std::string read_link(const std::string& path) {
  std::error_code error;
  const auto target = std::filesystem::read_symlink(path, error);
  return error ? std::string() : target.string();
}

SimServerOptions pty_options(Model model, const std::string& link) {
  SimServerOptions options;
  options.device.model = model;
  options.device.scene = "room";
  options.transport = SimTransport::Pty;
  options.pty_link = link;
  return options;
}

// The server's counters once `done` holds them, or when `patience` runs out (a hang guard, not a
// timing: the caller asserts on what it gets).
SimServerCounters counters_once(const SimServer& server, const std::function<bool(const SimServerCounters&)>& done,
                                std::chrono::milliseconds patience) {
  const auto give_up = Clock::now() + patience;
  SimServerCounters counters = server.counters().server;
  while (!done(counters) && Clock::now() < give_up) {
    std::this_thread::sleep_for(10ms);
    counters = server.counters().server;
  }
  return counters;
}

bool is_device_info_reply(const std::vector<std::uint8_t>& bytes) {
  return bytes.size() == 27 && bytes[0] == 0xA5 && bytes[1] == 0x5A && bytes[2] == 0x14 && bytes[6] == 0x04;
}

TEST(SimServerPty, HostTalksScansAndTheStreamStopsWithin100msOfStop) {
  const std::string link = temp_path("lidar");
  SimServer server(pty_options(Model::G6, link));
  server.start();
  ASSERT_FALSE(server.device_path().empty());
  EXPECT_EQ(read_link(link), server.device_path());

  HostPort host;
  ASSERT_TRUE(host.open_device(link));
  ASSERT_TRUE(host.send({0xA5, 0x90}));
  EXPECT_TRUE(is_device_info_reply(host.read(27, 2s)));

  ASSERT_TRUE(host.send({0xA5, 0x60}));
  const auto stream = host.read(20'000, 5s);
  ASSERT_GT(stream.size(), 7u);
  EXPECT_EQ(std::vector<std::uint8_t>(stream.begin(), stream.begin() + 7), kScanHeader);
  ScanDecoder decoder = test::field_decoder(Model::G6);
  std::size_t laps = 0;
  decoder.feed(stream, 0, [&](const Lap&) { ++laps; });
  EXPECT_GE(laps, 2u);
  EXPECT_EQ(decoder.counters().checksum_errors, 0u);

  ASSERT_TRUE(host.send({0xA5, 0x65}));
  Clock::time_point last_byte;
  host.read_until_silence(300ms, 5s, last_byte);
  // The stream ends (silence came within the read's bound) because the device stopped, not
  // because a pause happened to last 300 ms. How fast it stops is the benchmarks' business.
  DeviceMode mode = DeviceMode::Scanning;
  server.with_device([&](VirtualLidar& d) { mode = d.mode(); });
  EXPECT_EQ(mode, DeviceMode::Idle);

  // Idle again: it answers commands.
  ASSERT_TRUE(host.send({0xA5, 0x90}));
  EXPECT_TRUE(is_device_info_reply(host.read(27, 2s)));
  server.stop();
  EXPECT_TRUE(read_link(link).empty());
  EXPECT_FALSE(std::filesystem::exists(std::filesystem::symlink_status(link)));
}

TEST(SimServerPty, AHostCanCloseAndReopenThePort) {
  const std::string link = temp_path("lidar");
  SimServer server(pty_options(Model::G1, link));
  server.start();
  {
    HostPort host;
    ASSERT_TRUE(host.open_device(link));
    ASSERT_TRUE(host.send({0xA5, 0x60}));
    EXPECT_GT(host.read(2'000, 3s).size(), 1'000u);
  }  // closed while the device streams
  const auto unheard = [](const SimServerCounters& c) { return c.bytes_unheard > 0; };
  EXPECT_GT(counters_once(server, unheard, 5s).bytes_unheard, 0u);
  HostPort host;
  ASSERT_TRUE(host.open_device(link));
  ASSERT_TRUE(host.send({0xA5, 0x65}));
  Clock::time_point last_byte;
  host.read_until_silence(300ms, 5s, last_byte);
  ASSERT_TRUE(host.send({0xA5, 0x90}));
  EXPECT_TRUE(is_device_info_reply(host.read(27, 2s)));
}

// A host that stops reading: the pty fills and the device's bytes overrun, as on a UART. No zero
// packet gets through meanwhile, so the loss falls into one lap, which runs on until a zero packet
// is written whole again.
TEST(SimServerPty, BytesAHostDoesNotReadOverrunOneLap) {
  const std::string link = temp_path("lidar");
  SimServer server(pty_options(Model::G1, link));
  server.start();
  HostPort host;
  ASSERT_TRUE(host.open_device(link));
  ASSERT_TRUE(host.send({0xA5, 0x60}));
  const auto counters = [&] { return server.counters().server; };
  auto give_up = Clock::now() + 10s;
  while (counters().zero_packets_written < 2 && Clock::now() < give_up) (void)host.read(512, 100ms);
  ASSERT_GE(counters().zero_packets_written, 2u) << "the device never scanned";
  const SimServerCounters full = counters_once(
      server, [](const SimServerCounters& c) { return c.bytes_unheard > 0; }, 10s);
  ASSERT_GT(full.bytes_unheard, 0u) << "the pty never filled";
  EXPECT_EQ(full.laps_overrun, 1u);
  // Several laps' worth more bytes (a G1 lap is about 1.6 kB) fall into the same lap.
  const SimServerCounters later = counters_once(
      server, [&](const SimServerCounters& c) { return c.bytes_unheard >= full.bytes_unheard + 8'000; }, 10s);
  ASSERT_GE(later.bytes_unheard, full.bytes_unheard + 8'000);
  EXPECT_EQ(later.zero_packets_written, full.zero_packets_written);
  EXPECT_EQ(later.laps_overrun, 1u);
  // Reading again lets the next zero packet through.
  give_up = Clock::now() + 10s;
  while (counters().zero_packets_written == later.zero_packets_written && Clock::now() < give_up)
    (void)host.read(4'096, 100ms);
  EXPECT_GT(counters().zero_packets_written, later.zero_packets_written);
}

TEST(SimServerPty, UnplugRemovesThePortAndReplugComesBackPoweredOn) {
  const std::string link = temp_path("lidar");
  SimServer server(pty_options(Model::TG30, link));
  server.start();
  const std::string first_path = server.device_path();
  HostPort host;
  ASSERT_TRUE(host.open_device(link));
  ASSERT_TRUE(host.send({0xA5, 0x0B}));  // +1 Hz: lost with the power
  EXPECT_EQ(host.read(11, 2s).size(), 11u);
  ASSERT_TRUE(host.send({0xA5, 0x60}));
  host.read(500, 2s);

  server.unplug();
  EXPECT_FALSE(server.plugged());
  EXPECT_TRUE(server.device_path().empty());
  EXPECT_FALSE(std::filesystem::exists(std::filesystem::symlink_status(link)));
  host.read(100'000, 1s);  // the host sees the port go away
  EXPECT_TRUE(host.eof());
  host.close();
  EXPECT_FALSE(std::filesystem::exists(first_path));

  server.replug();
  EXPECT_TRUE(server.plugged());
  EXPECT_EQ(read_link(link), server.device_path());
  HostPort again;
  ASSERT_TRUE(again.open_device(link));
  ASSERT_TRUE(again.send({0xA5, 0x0D}));
  const auto reply = again.read(11, 2s);
  ASSERT_EQ(reply.size(), 11u);
  EXPECT_EQ(reply[7] | reply[8] << 8, 1000);  // TG default 10 Hz: the device lost power
  const SimCounters counters = server.counters();
  EXPECT_EQ(counters.server.unplugs, 1u);
  EXPECT_EQ(counters.server.replugs, 1u);
}

TEST(SimServerPty, ScheduledUnplugAndReplug) {
  const std::string link = temp_path("lidar");
  SimServerOptions options = pty_options(Model::G6, link);
  options.unplug_after = 100ms;
  options.replug_after = 200ms;
  SimServer server(options);
  server.start();
  const auto end = Clock::now() + 5s;
  while (server.counters().server.replugs == 0 && Clock::now() < end) std::this_thread::sleep_for(10ms);
  const SimCounters counters = server.counters();
  EXPECT_EQ(counters.server.unplugs, 1u);
  EXPECT_EQ(counters.server.replugs, 1u);
  EXPECT_EQ(read_link(link), server.device_path());
}

TEST(SimServerPty, ZeroPacketsAreTimeStampedAsTheyAreWritten) {
  const std::string link = temp_path("lidar");
  const std::string log = temp_path("zero.log");
  SimServerOptions options = pty_options(Model::G6, link);
  std::mutex mu;
  std::vector<std::pair<std::int64_t, std::uint64_t>> stamps;
  options.on_zero_packet_written = [&](std::int64_t ns, std::uint64_t index) {
    std::lock_guard lock(mu);
    stamps.emplace_back(ns, index);
  };
  options.zero_packet_log = log;
  SimServer server(options);
  server.start();
  HostPort host;
  ASSERT_TRUE(host.open_device(link));
  ASSERT_TRUE(host.send({0xA5, 0x60}));
  host.read(30'000, 3s);  // about 0.7 s of a real G6's 40.8 kB/s: 5 or more laps
  const std::int64_t read_done = monotonic_ns();
  server.stop();
  std::lock_guard lock(mu);
  ASSERT_GE(stamps.size(), 4u);
  for (std::size_t i = 0; i < stamps.size(); ++i) {
    EXPECT_EQ(stamps[i].second, i);
    if (i > 0) {
      EXPECT_GT(stamps[i].first, stamps[i - 1].first);
    }
  }
  EXPECT_LT(stamps.front().first, read_done);
  std::ifstream lines(log);
  std::uint64_t index = 0;
  std::int64_t ns = 0;
  std::size_t count = 0;
  while (lines >> index >> ns) {
    ASSERT_LT(count, stamps.size());
    EXPECT_EQ(index, stamps[count].second);
    EXPECT_EQ(ns, stamps[count].first);
    ++count;
  }
  EXPECT_EQ(count, stamps.size());
  EXPECT_EQ(server.counters().server.zero_packets_written, stamps.size());
}

TEST(SimServerPty, RefusesALinkPathThatIsNotAStalePtyLink) {
  const std::string link = temp_path("taken");
  std::ofstream(link) << "mine";
  SimServer server(pty_options(Model::G6, link));
  try {
    server.start();
    FAIL() << "start() accepted an existing file as the link";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("already exists"), std::string::npos) << error.what();
  }
  std::ifstream kept(link);
  std::string content;
  kept >> content;
  EXPECT_EQ(content, "mine");
}

TEST(SimServerPty, ReplacesADanglingPtyLinkFromAnEarlierRun) {
  const std::string link = temp_path("stale");
  std::filesystem::create_symlink("/dev/pts/98765", link);
  SimServer server(pty_options(Model::G6, link));
  server.start();
  EXPECT_EQ(read_link(link), server.device_path());
}

TEST(SimServerTcp, ServesOneHostAtATime) {
  SimServerOptions options;
  options.device.model = Model::G1;
  options.transport = SimTransport::Tcp;
  SimServer server(options);
  server.start();
  ASSERT_NE(server.tcp_port(), 0);
  EXPECT_EQ(server.device_path(), "tcp://127.0.0.1:" + std::to_string(server.tcp_port()));

  HostPort host;
  ASSERT_TRUE(host.connect_tcp(server.tcp_port()));
  ASSERT_TRUE(host.send({0xA5, 0x90}));
  const auto reply = host.read(27, 2s);
  ASSERT_TRUE(is_device_info_reply(reply));
  EXPECT_EQ(reply[7], 19);  // G1

  HostPort second;
  ASSERT_TRUE(second.connect_tcp(server.tcp_port()));
  second.read(1, 2s);
  EXPECT_TRUE(second.eof());  // turned away
  EXPECT_EQ(server.counters().server.rejected_hosts, 1u);

  ASSERT_TRUE(host.send({0xA5, 0x60}));
  const auto stream = host.read(5'000, 3s);
  ASSERT_GT(stream.size(), 7u);
  EXPECT_EQ(std::vector<std::uint8_t>(stream.begin(), stream.begin() + 7), kScanHeader);
  host.close();

  // The next host gets the port once the first has gone.
  HostPort third;
  const auto end = Clock::now() + 3s;
  bool answered = false;
  while (!answered && Clock::now() < end) {
    third.close();
    ASSERT_TRUE(third.connect_tcp(server.tcp_port()));
    third.send({0xA5, 0x65});
    Clock::time_point last;
    third.read_until_silence(200ms, 2s, last);
    third.send({0xA5, 0x90});
    answered = is_device_info_reply(third.read(27, 1s));
  }
  EXPECT_TRUE(answered);
}

TEST(SimServerTcp, PortInUseIsAClearError) {
  SimServerOptions options;
  options.transport = SimTransport::Tcp;
  SimServer first(options);
  first.start();
  options.tcp_port = first.tcp_port();
  SimServer second(options);
  try {
    second.start();
    FAIL() << "two servers on one port";
  } catch (const std::runtime_error& error) {
    EXPECT_NE(std::string(error.what()).find("could not listen"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace ydscope
