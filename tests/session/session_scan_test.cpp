// Scanning through the session: the laps in the queue are the laps the virtual lidar sent, point
// for point; corrupted and dropped bytes are counted and never stop the stream.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <mutex>

#include "core/link/serial_link.h"
#include "support/session_test_support.h"

namespace ydscope {
namespace {

using namespace test;

// Every point the virtual lidar generated, by lap, as a correct host must decode it.
class Truth {
 public:
  void attach(SimServer& server) {
    server.with_device([this](VirtualLidar& d) {
      d.set_truth([this](const TruthPacket& packet) {
        std::lock_guard lock(mutex_);
        auto& lap = laps_[packet.lap];
        lap.insert(lap.end(), packet.points.begin(), packet.points.end());
      });
    });
  }
  std::vector<LapPoint> lap(std::uint64_t index) {
    std::lock_guard lock(mutex_);
    return laps_[index];
  }

 private:
  std::mutex mutex_;
  std::map<std::uint64_t, std::vector<LapPoint>> laps_;
};

class ScanEveryModel : public ::testing::TestWithParam<Model> {};

TEST_P(ScanEveryModel, LapsEqualWhatTheVirtualLidarSent) {
  Truth truth;  // outlives the sim, whose thread feeds it until the sim stops
  SimOnPty sim(GetParam());
  truth.attach(sim.server());
  Session session(64);
  session.connect(config_for(sim.port(), GetParam()));
  std::vector<Lap> laps;
  ASSERT_EQ(take_laps(session, 12, &laps), 12u) << describe_snapshot(session.snapshot());
  session.disconnect();
  wait_for_state(session, LinkState::Idle);
  for (std::size_t i = 0; i < laps.size(); ++i) {
    const Lap& lap = laps[i];
    EXPECT_EQ(lap.index, i);
    const std::vector<LapPoint> expected = truth.lap(lap.index);
    ASSERT_EQ(lap.points.size(), expected.size()) << "lap " << lap.index;
    for (std::size_t p = 0; p < expected.size(); ++p) {
      ASSERT_NEAR(lap.points[p].range_mm, expected[p].range_mm, 0.3) << "lap " << lap.index << " point " << p;
      const double angle_error = std::fabs(lap.points[p].angle_deg - expected[p].angle_deg);
      ASSERT_LT(std::min(angle_error, 360.0 - angle_error), 0.02) << "lap " << lap.index << " point " << p;
      ASSERT_EQ(lap.points[p].flag, expected[p].flag) << "lap " << lap.index << " point " << p;
    }
    EXPECT_EQ(lap.checksum_errors, 0u);
    if (GetParam() == Model::G1) {
      EXPECT_EQ(lap.crc, CrcVerdict::Ok) << "lap " << lap.index;
    }
  }
  const CounterSnapshot c = session.snapshot().counters;
  EXPECT_EQ(c.checksum_errors, 0u);
  EXPECT_EQ(c.crc8_failures, 0u);
  EXPECT_EQ(c.resync_bytes, 0u) << "the A5 5A reply header is taken off before the decoder";
  EXPECT_EQ(session.snapshot().queue_dropped, 0u);
  EXPECT_GE(c.laps, 12u);
}

INSTANTIATE_TEST_SUITE_P(AllModels, ScanEveryModel,
                         ::testing::Values(Model::G1, Model::G6, Model::TG15, Model::TG30, Model::TG50),
                         [](const auto& param_info) { return std::string(profile_for(param_info.param).name); });

TEST(SessionScan, MidLapTheStreamIsReadInBatchesNotPacketByPacket) {
  // The virtual lidar writes each packet in one or two pieces; once the stream's rhythm is known
  // the session holds off reading mid-lap, so it wakes a few times a lap, not for every piece.
  SimOnPty sim(Model::G6);
  Session session(64);
  session.connect(config_for(sim.port(), Model::G6));
  ASSERT_EQ(take_laps(session, 12), 12u) << describe_snapshot(session.snapshot());  // rates known
  const CounterSnapshot before = session.snapshot().counters;
  std::vector<Lap> laps;
  ASSERT_EQ(take_laps(session, 16, &laps), 16u) << describe_snapshot(session.snapshot());
  const CounterSnapshot after = session.snapshot().counters;
  session.disconnect();
  const auto reads = after.reads - before.reads;
  const auto packets = after.packets - before.packets;
  EXPECT_GT(packets, 16u * 10u);
  EXPECT_LT(2 * reads, packets) << reads << " reads for " << packets << " packets";
  for (std::size_t i = 1; i < laps.size(); ++i) EXPECT_EQ(laps[i].index, laps[i - 1].index + 1) << "no lap lost";
}

TEST(SessionScan, CorruptedAndDroppedBytesAreCountedAndTheStreamGoesOn) {
  SimOnPty sim(Model::G1, [](SimServerOptions& o) {
    o.device.faults.corrupt_byte_rate = 0.002;
    o.device.faults.drop_byte_rate = 0.0005;
    o.device.seed = 7;
  });
  Session session(64);
  session.connect(config_for(sim.port(), Model::G1));
  ASSERT_EQ(take_laps(session, 20), 20u) << describe_snapshot(session.snapshot());
  EXPECT_EQ(session.snapshot().state, LinkState::Scanning);
  session.disconnect();
  wait_for_state(session, LinkState::Idle);
  const CounterSnapshot c = session.snapshot().counters;
  const FaultCounters injected = sim.counters().faults;
  EXPECT_GT(c.checksum_errors, 0u);
  EXPECT_LE(c.checksum_errors, injected.corrupted_packets + injected.dropped_bytes);
  EXPECT_GT(c.resync_bytes, 0u);
  EXPECT_GT(c.crc8_failures, 0u) << "a dropped byte loses a packet, so that lap's CT CRC8 fails";
}

// The room does not move much between laps: its largest range compares two scales.
float largest_range(const Lap& lap) {
  float largest = 0;
  for (const LapPoint& p : lap.points) largest = std::max(largest, p.range_mm);
  return largest;
}

// `count` laps decoded after a change to the session: what was queued before it goes first.
std::vector<Lap> laps_after_change(Session& session, std::size_t count) {
  Lap lap;
  while (session.laps().try_pop(lap)) {
  }
  std::vector<Lap> laps;
  take_laps(session, count, &laps);
  return laps;
}

TEST(SessionScan, ADistanceScaleOverrideAppliesToTheLaps) {
  SimOnPty sim(Model::TG15);
  Session session(64);
  session.connect(config_for(sim.port(), Model::TG15));
  std::vector<Lap> before;
  ASSERT_EQ(take_laps(session, 2, &before), 2u);
  ASSERT_EQ(session.snapshot().distance_scale, 1.0) << "a real TG's scale on current firmware";
  session.set_distance_scale(0.5);  // what older TG firmware needs: half
  ASSERT_TRUE(
      session.wait_until([](const SessionSnapshot& s) { return s.distance_scale == 0.5; }, kPatience).distance_scale ==
      0.5);
  const std::vector<Lap> after = laps_after_change(session, 2);
  ASSERT_EQ(after.size(), 2u);
  EXPECT_NEAR(largest_range(after.back()) / largest_range(before.back()), 0.5, 0.05);
}

TEST(SessionScan, ReadingAUnitAsItsManualSaysHalvesAG6sRangesAndNamesTheRow) {
  SimOnPty sim(Model::G6);  // writes as a real G6: S/2 mm
  Session session(64);
  session.connect(config_for(sim.port(), Model::G6));
  std::vector<Lap> before;
  ASSERT_EQ(take_laps(session, 2, &before), 2u);
  ASSERT_NE(session.snapshot().conventions, nullptr);
  EXPECT_EQ(session.snapshot().conventions->id, "g6-field");
  session.set_reading(Reading::Manual);
  const SessionSnapshot s = session.wait_until(
      [](const SessionSnapshot& snap) { return snap.conventions && snap.conventions->reading == Reading::Manual; },
      kPatience);
  ASSERT_NE(s.conventions, nullptr);
  EXPECT_EQ(s.conventions->id, "g6-manual");
  EXPECT_EQ(s.distance_scale, 0.25);
  const std::vector<Lap> after = laps_after_change(session, 2);
  ASSERT_EQ(after.size(), 2u);
  EXPECT_NEAR(largest_range(after.back()) / largest_range(before.back()), 0.5, 0.05);
}

// A serial link that removes the A5 5A 05 00 00 40 81 header after A5 60, as a device in
// power-down protection mode does for later scan commands: the session must find packets anyway.
class ScanHeaderEater final : public ByteLink {
 public:
  explicit ScanHeaderEater(std::unique_ptr<ByteLink> inner) : inner_(std::move(inner)) {}
  void async_read_some(std::span<std::uint8_t> buffer, IoHandler handler) override {
    inner_->async_read_some(buffer, [this, buffer, handler](const boost::system::error_code& ec, std::size_t n) {
      std::size_t start = 0;
      while (to_eat_ > 0 && start < n) {
        ++start;
        --to_eat_;
      }
      if (start > 0 && start == n && !ec) {  // all eaten: read again rather than report 0 bytes
        async_read_some(buffer, handler);
        return;
      }
      std::copy(buffer.begin() + static_cast<std::ptrdiff_t>(start), buffer.begin() + static_cast<std::ptrdiff_t>(n),
                buffer.begin());
      handler(ec, n - start);
    });
  }
  void async_write(std::span<const std::uint8_t> bytes, IoHandler handler) override {
    if (bytes.size() == 2 && bytes[0] == 0xA5 && bytes[1] == 0x60) to_eat_ = 7;
    inner_->async_write(bytes, std::move(handler));
  }
  void close() override { inner_->close(); }
  bool set_baud(std::uint32_t baud, std::string& error) override { return inner_->set_baud(baud, error); }
  bool accepts_commands() const override { return true; }
  std::string describe() const override { return inner_->describe(); }

 private:
  std::unique_ptr<ByteLink> inner_;
  std::size_t to_eat_ = 0;  // I/O thread only
};

TEST(SessionScan, AStreamWithoutItsReplyHeaderStillDecodes) {
  SimOnPty sim(Model::G6);
  Session session(64);
  SessionConfig config = config_for(sim.port(), Model::G6);
  const std::string port = sim.port();
  config.open_link = [port](boost::asio::io_context& io, std::uint32_t baud,
                            std::string& error) -> std::unique_ptr<ByteLink> {
    auto serial = SerialLink::open(io, port, baud, error);
    if (!serial) return nullptr;
    return std::make_unique<ScanHeaderEater>(std::move(serial));
  };
  session.connect(config);
  ASSERT_EQ(take_laps(session, 3), 3u) << describe_snapshot(session.snapshot());
  const CounterSnapshot c = session.snapshot().counters;
  EXPECT_EQ(c.checksum_errors, 0u);
  EXPECT_EQ(c.resync_bytes, 0u) << "the stream starts at a packet header";
}

}  // namespace
}  // namespace ydscope
