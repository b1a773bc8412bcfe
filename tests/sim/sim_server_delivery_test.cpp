// SimServer with a delivery model, behind a real pseudo-terminal: the host gets a stream that
// decodes cleanly whatever the bridge does to it, and zero packets are still time-stamped.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cctype>
#include <filesystem>
#include <functional>
#include <mutex>
#include <string>
#include <vector>

#include "core/protocol/scan_decoder.h"
#include "core/sim/sim_server.h"
#include "sim/host_port.h"
#include "support/temp_dir.h"
#include "support/field_decoder.h"

namespace ydscope {
namespace {

using namespace std::chrono_literals;
using test::HostPort;

class SimServerDelivery : public ::testing::TestWithParam<std::string> {};

TEST_P(SimServerDelivery, HostDecodesTheStreamAndZeroPacketsAreStamped) {
  const test::TempDir dir("delivery");
  SimServerOptions options;
  options.device.model = Model::G6;
  options.device.scene = "room";
  options.device.host_compat = HostCompat::YdlidarSdk;
  options.transport = SimTransport::Pty;
  options.pty_link = (dir / "lidar").string();
  options.delivery = *parse_delivery(GetParam());
  std::mutex mu;
  std::vector<std::uint64_t> stamps;
  options.on_zero_packet_written = [&](std::int64_t, std::uint64_t index) {
    std::lock_guard lock(mu);
    stamps.push_back(index);
  };
  SimServer server(options);
  server.start();
  HostPort host;
  ASSERT_TRUE(host.open_device(options.pty_link));
  ASSERT_TRUE(host.send({0xA5, 0x90}));
  EXPECT_EQ(host.read(27, 3s).size(), 27u) << "a reply shorter than a burst still arrives (the latency timer)";
  ASSERT_TRUE(host.send({0xA5, 0x60}));
  const auto stream = host.read(30'000, 5s);  // about 0.7 s of a real G6's 40.8 kB/s
  server.stop();
  ASSERT_GE(stream.size(), 30'000u);

  ScanDecoder decoder = test::field_decoder(Model::G6);
  std::size_t laps = 0;
  decoder.feed(stream, 0, [&](const Lap&) { ++laps; });
  EXPECT_GE(laps, 4u);
  EXPECT_EQ(decoder.counters().checksum_errors, 0u);
  EXPECT_EQ(decoder.counters().resync_bytes, 7u + 27u) << "the scan header and the SDK's device-info frame only";
  std::lock_guard lock(mu);
  ASSERT_GE(stamps.size(), decoder.counters().zero_packets);
  for (std::size_t i = 0; i < stamps.size(); ++i) EXPECT_EQ(stamps[i], i);
  EXPECT_EQ(server.counters().server.zero_packets_written, stamps.size());
}

INSTANTIATE_TEST_SUITE_P(Models, SimServerDelivery, ::testing::Values("whole", "burst:64:1000", "random:17"),
                         [](const auto& param_info) {
                           std::string name = param_info.param;
                           for (char& c : name) c = std::isalnum(static_cast<unsigned char>(c)) ? c : '_';
                           return name;
                         });

}  // namespace
}  // namespace ydscope
