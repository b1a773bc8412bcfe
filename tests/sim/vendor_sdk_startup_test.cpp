// The start-up of YDLIDAR's SDK (YDLidar-SDK 1.2.19 as its ROS 2 driver's params/G1.yaml, G6.yaml
// and TG.yaml set it up: serial, two-channel, frequency 10 Hz), replayed byte for byte against the
// virtual lidar in HostCompat::YdlidarSdk, every reply checked against what the SDK's source
// accepts. The sequence, read from its source (CYdLidar::initialize and turnOn, YDlidarDriver):
//   getHealth:      A5 00, A5 65 (its stop), then A5 92       -> type 06, >= 3 bytes, status 0 = "good"
//   getDeviceInfo:  A5 90                                     -> type 04, >= 20 bytes
//   TG only:        A5 D1 (sampling rate)                     -> type 04, exactly 1 byte
//   scan frequency: A5 0D, +1 Hz (A5 0B) / +0.1 Hz (A5 09) steps toward 10 Hz, A5 0D
//                                                             -> type 04, exactly 4 bytes each
//   G1 and TG:      A5 93 (zero-offset angle, up to 2 tries)  -> type 04, >= 4 bytes, |a| <= 4*360
//   startScan:      A5 00, A5 65, G6: A5 D1, then A5 60       -> type 81, size field >= 5, then
//                   a device-info frame (type 04, >= 20 bytes) within 1 s, then scan packets
// Expected bytes are written out here, not built with the encoders under test.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "core/protocol/lap.h"
#include "core/protocol/model_profile.h"
#include "core/protocol/scan_decoder.h"
#include "core/protocol/scan_packet.h"
#include "core/sim/host_compat.h"
#include "core/sim/virtual_lidar.h"
#include "sim/sim_test_support.h"

namespace ydscope {
namespace {

using test::exchange;
using test::kMs;
using Bytes = std::vector<std::uint8_t>;

using test::is_tg;
using test::kNoReply;
using test::kScanHeader;
using test::scan_hz_reply;
using test::single_reply;
const Bytes kHealthGood = single_reply(0x03, 0x06, {0x00, 0x00, 0x00});
const Bytes kZeroOffsetNone = single_reply(0x04, 0x04, {0x00, 0x00, 0x00, 0x00});

class VendorSdkStartup : public ::testing::TestWithParam<Model> {
 protected:
  VirtualLidarConfig config(HostCompat compat) const {
    VirtualLidarConfig c;
    c.model = GetParam();
    c.seed = 3;
    c.host_compat = compat;
    return c;
  }
  const ModelProfile& profile() const { return profile_for(GetParam()); }
  // The SDK's stop before each request: two commands it waits no answer for.
  void sdk_stop(VirtualLidar& lidar) {
    EXPECT_EQ(exchange(lidar, {0xA5, 0x00}, now, 5 * kMs), kNoReply);
    EXPECT_EQ(exchange(lidar, {0xA5, 0x65}, now, 5 * kMs), kNoReply);
  }
  std::int64_t now = 0;
};

TEST_P(VendorSdkStartup, EveryRequestIsAnsweredAsTheSdkChecksIt) {
  VirtualLidar lidar(config(HostCompat::YdlidarSdk));
  const Model model = GetParam();

  sdk_stop(lidar);
  EXPECT_EQ(exchange(lidar, {0xA5, 0x92}, now), kHealthGood) << "A5 92 health on " << profile().name;

  const Bytes info = exchange(lidar, {0xA5, 0x90}, now);
  ASSERT_EQ(info.size(), 27u);
  EXPECT_EQ(Bytes(info.begin(), info.begin() + 8), single_reply(0x14, 0x04, {profile().model_code}));

  if (is_tg(model)) {
    EXPECT_EQ(exchange(lidar, {0xA5, 0xD1}, now), single_reply(0x01, 0x04, {0x02}));  // 9 kHz
  }

  // Scan frequency toward the yaml's 10 Hz. TG reports 0.4 Hz high (the SDK subtracts it), so at
  // its default 10 Hz the SDK sees 10.0 and steps nothing.
  if (model == Model::G1) {
    EXPECT_EQ(exchange(lidar, {0xA5, 0x0D}, now), scan_hz_reply(900));
    EXPECT_EQ(exchange(lidar, {0xA5, 0x0B}, now), scan_hz_reply(1000));
  } else if (model == Model::G6) {
    EXPECT_EQ(exchange(lidar, {0xA5, 0x0D}, now), scan_hz_reply(800));
    EXPECT_EQ(exchange(lidar, {0xA5, 0x0B}, now), scan_hz_reply(900));
    EXPECT_EQ(exchange(lidar, {0xA5, 0x0B}, now), scan_hz_reply(1000));
  } else {
    EXPECT_EQ(exchange(lidar, {0xA5, 0x0D}, now), scan_hz_reply(1040));
  }
  EXPECT_EQ(exchange(lidar, {0xA5, 0x0D}, now), scan_hz_reply(is_tg(model) ? 1040 : 1000));
  EXPECT_EQ(lidar.scan_centihz(), 1000u) << "the motor runs at the 10 Hz the host asked for";

  if (model == Model::G1 || is_tg(model)) {
    EXPECT_EQ(exchange(lidar, {0xA5, 0x93}, now), kZeroOffsetNone);
  }

  sdk_stop(lidar);
  if (model == Model::G6) {
    EXPECT_EQ(exchange(lidar, {0xA5, 0xD1}, now), single_reply(0x01, 0x04, {0x02}));
  }
  exchange(lidar, {0xA5, 0x60}, now, 0);
  now += 200 * kMs;
  Bytes stream;
  lidar.produce(now, stream);
  ASSERT_GE(stream.size(), 7u + 27u + 10u);
  EXPECT_EQ(Bytes(stream.begin(), stream.begin() + 7), kScanHeader);
  EXPECT_EQ(Bytes(stream.begin() + 7, stream.begin() + 15), single_reply(0x14, 0x04, {profile().model_code}))
      << "the device-info frame the SDK waits up to 1 s for";
  EXPECT_EQ(Bytes(stream.begin() + 15, stream.begin() + 34), Bytes(info.begin() + 8, info.end()));
  // Then the stream: G1 puts its LastCRC byte before the first zero packet, a real TG its byte.
  const std::size_t packet_at = lidar.conventions().byte_before_zero != ByteBeforeZero::None ? 35 : 34;
  EXPECT_EQ(stream[packet_at], kPacketHeader0);
  EXPECT_EQ(stream[packet_at + 1], kPacketHeader1);
  EXPECT_EQ(lidar.mode(), DeviceMode::Scanning);
  EXPECT_EQ(lidar.counters().unsupported, 0u) << "nothing the SDK sent went unanswered";
  EXPECT_EQ(lidar.counters().ignored_during_scan, 0u);
}

TEST_P(VendorSdkStartup, ForceStopIsAcceptedWhileScanningWithoutCountingIt) {
  VirtualLidar lidar(config(HostCompat::YdlidarSdk));
  exchange(lidar, {0xA5, 0x60}, now);
  EXPECT_FALSE(exchange(lidar, {0xA5, 0x00}, now, 5 * kMs).empty()) << "the stream goes on";
  EXPECT_EQ(lidar.counters().ignored_during_scan, 0u);
  exchange(lidar, {0xA5, 0x65}, now);
  EXPECT_EQ(lidar.mode(), DeviceMode::Idle);
}

TEST_P(VendorSdkStartup, ExtraRequestsAreIgnoredWhileScanningAsTheManualsSay) {
  VirtualLidar lidar(config(HostCompat::YdlidarSdk));
  exchange(lidar, {0xA5, 0x60}, now);
  const auto before = lidar.counters().replies;
  exchange(lidar, {0xA5, 0x93}, now);
  EXPECT_EQ(lidar.counters().replies, before);
  EXPECT_EQ(lidar.counters().ignored_during_scan, 1u);
}

TEST_P(VendorSdkStartup, HealthFaultsReachTheSdksHealthRequest) {
  VirtualLidarConfig c = config(HostCompat::YdlidarSdk);
  c.faults.health_bits = 0x05;
  VirtualLidar lidar(c);
  // G1's A5 92 is its manual's (status bits); G6/TG answer A5 92 as their A5 91: status 2 + code.
  const Bytes expected = GetParam() == Model::G1 ? single_reply(0x03, 0x06, {0x05, 0x00, 0x00})
                                                 : single_reply(0x03, 0x06, {0x02, 0x05, 0x00});
  EXPECT_EQ(exchange(lidar, {0xA5, 0x92}, now), expected);
}

TEST_P(VendorSdkStartup, ManualModeAnswersNoneOfTheExtras) {
  VirtualLidar lidar(config(HostCompat::Manual));
  if (GetParam() != Model::G1) {
    EXPECT_EQ(exchange(lidar, {0xA5, 0x92}, now), kNoReply);
  }
  EXPECT_EQ(exchange(lidar, {0xA5, 0x93}, now), kNoReply);
  EXPECT_EQ(exchange(lidar, {0xA5, 0x00}, now), kNoReply);
  EXPECT_EQ(exchange(lidar, {0xA5, 0x0D}, now), scan_hz_reply(GetParam() == Model::G1   ? 900
                                                              : GetParam() == Model::G6 ? 800
                                                                                        : 1000));
  const Bytes start = exchange(lidar, {0xA5, 0x60}, now, 200 * kMs);
  ASSERT_GT(start.size(), 9u);
  EXPECT_EQ(Bytes(start.begin(), start.begin() + 7), kScanHeader);
  // G1's LastCRC and a real TG's byte come before the first zero packet.
  EXPECT_EQ(start[lidar.conventions().byte_before_zero != ByteBeforeZero::None ? 8 : 7], kPacketHeader0)
      << "packets follow the header at once";
}

TEST_P(VendorSdkStartup, ManualRepliesAreUnchangedByTheMode) {
  VirtualLidar manual(config(HostCompat::Manual));
  VirtualLidar sdk(config(HostCompat::YdlidarSdk));
  std::int64_t t = 0;
  for (const Command command : profile().commands) {
    const std::uint8_t code = static_cast<std::uint8_t>(command);
    if (command == Command::Scan || command == Command::RestartG1 || command == Command::RestartG6TG) continue;
    if (command == Command::ScanHzGet || reply_spec(command).payload_length == 4) continue;  // TG's +0.4 Hz
    std::int64_t t2 = t;
    EXPECT_EQ(exchange(manual, {0xA5, code}, t), exchange(sdk, {0xA5, code}, t2)) << "A5 " << int(code);
  }
}

// What the mode costs ydscope's own decoder: the device-info frame after the scan header is 27
// bytes it skips as resync bytes, once per scan start; the laps are the same.
TEST_P(VendorSdkStartup, OwnDecoderSkipsTheDeviceInfoFrameAndDecodesTheSameLaps) {
  DecoderCounters counters[2];
  std::vector<std::size_t> lap_sizes[2];
  for (const HostCompat compat : {HostCompat::Manual, HostCompat::YdlidarSdk}) {
    const auto k = static_cast<std::size_t>(compat);
    VirtualLidar lidar(config(compat));
    ScanDecoder decoder(lidar.profile(), lidar.conventions());
    std::int64_t t = 0;
    lidar.receive(std::vector<std::uint8_t>{0xA5, 0x60}, t);
    std::vector<std::uint8_t> out;
    for (t = 0; t < 1'000 * kMs; t += 5 * kMs) {
      out.clear();
      lidar.produce(t, out);
      decoder.feed(out, t, [&](const Lap& lap) { lap_sizes[k].push_back(lap.points.size()); });
    }
    counters[k] = decoder.counters();
  }
  EXPECT_EQ(lap_sizes[0], lap_sizes[1]);
  EXPECT_GE(lap_sizes[1].size(), 7u);
  EXPECT_EQ(counters[1].packets, counters[0].packets);
  EXPECT_EQ(counters[1].checksum_errors, 0u);
  EXPECT_EQ(counters[1].resync_bytes, counters[0].resync_bytes + 27u);
}

INSTANTIATE_TEST_SUITE_P(Models, VendorSdkStartup,
                         ::testing::Values(Model::G1, Model::G6, Model::TG15, Model::TG30, Model::TG50),
                         [](const auto& param_info) { return std::string(profile_for(param_info.param).name); });

TEST(HostCompatTable, NamesRoundTripAndUnknownNamesAreRefused) {
  EXPECT_EQ(host_compat_from_name("manual"), HostCompat::Manual);
  EXPECT_EQ(host_compat_from_name("ydlidar-sdk"), HostCompat::YdlidarSdk);
  EXPECT_EQ(host_compat_from_name("sdk"), std::nullopt);
  EXPECT_EQ(host_compat_name(HostCompat::YdlidarSdk), "ydlidar-sdk");
  EXPECT_TRUE(compat_commands(HostCompat::Manual).empty());
}

TEST(HostCompatTable, NeverOverridesACommandTheManualAnswers) {
  // A5 92 is G1's own health command: the table's entry is for G6/TG only.
  EXPECT_EQ(find_compat_command(HostCompat::YdlidarSdk, profile_for(Model::G1), 0x92), nullptr);
  ASSERT_NE(find_compat_command(HostCompat::YdlidarSdk, profile_for(Model::G6), 0x92), nullptr);
  EXPECT_EQ(find_compat_command(HostCompat::Manual, profile_for(Model::G6), 0x92), nullptr);
}

TEST(HostCompatTable, ZeroOffsetAngleIsQuarterDegrees) {
  EXPECT_EQ(encode_zero_offset_angle(0.0), (Bytes{0, 0, 0, 0}));
  EXPECT_EQ(encode_zero_offset_angle(180.0), (Bytes{0xD0, 0x02, 0, 0}));  // 720, the SDK's "uncorrected"
  EXPECT_EQ(encode_zero_offset_angle(-1.0), (Bytes{0xFC, 0xFF, 0xFF, 0xFF}));
}

}  // namespace
}  // namespace ydscope
