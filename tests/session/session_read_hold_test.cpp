// Read holds against a virtual G6 on a pty: at a real G6's rate (18 000 samples/s, about 40.8 KB/s
// of 51.2 KB/s line rate) and at full line rate, what piles up while the session holds off reading
// must stay below the point where n_tty throttles the port (128 bytes free of 4096), past which a
// USB bridge loses bytes and a pty makes the virtual lidar wait.
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <mutex>
#include <string>

#include "core/link/serial_link.h"
#include "core/protocol/scan_packet.h"
#include "support/session_test_support.h"

namespace ydscope {
namespace {

using namespace test;

constexpr std::size_t kThrottlePoint = 4096 - 128;

// What the session's reads brought, judged against the line. A pty has no line: a virtual lidar
// starved of CPU on a loaded machine catches up in a burst no serial line could carry, and such
// reads say nothing about the hold, so they are counted apart.
struct ReadStats {
  std::mutex mutex;
  std::size_t largest = 0;        // any read
  std::size_t largest_paced = 0;  // reads the line could have carried since the previous one
  std::size_t outran = 0;         // reads it could not have
};

// A serial link that watches its reads and passes everything else on (holds included).
class ReadWatch final : public ByteLink {
 public:
  ReadWatch(std::unique_ptr<ByteLink> inner, std::shared_ptr<ReadStats> stats)
      : inner_(std::move(inner)), stats_(std::move(stats)) {}
  void async_read_some(std::span<std::uint8_t> buffer, IoHandler handler) override {
    inner_->async_read_some(buffer, [this, handler](const boost::system::error_code& ec, std::size_t n) {
      if (!ec) note(n);
      handler(ec, n);
    });
  }
  void async_write(std::span<const std::uint8_t> bytes, IoHandler handler) override {
    inner_->async_write(bytes, std::move(handler));
  }
  void close() override { inner_->close(); }
  void stop_watching_input() override { inner_->stop_watching_input(); }
  double line_bytes_per_s() const override { return inner_->line_bytes_per_s(); }
  bool set_baud(std::uint32_t baud, std::string& error) override { return inner_->set_baud(baud, error); }
  bool accepts_commands() const override { return true; }
  std::string describe() const override { return inner_->describe(); }

 private:
  void note(std::size_t n) {
    const auto now = std::chrono::steady_clock::now();
    const double gap_s = std::chrono::duration<double>(now - last_).count();
    last_ = now;
    // What the line carries in the gap, plus a packet that may have been on its way already.
    const bool paced = static_cast<double>(n) <= gap_s * line_bytes_per_s() + static_cast<double>(kMaxPacketSize);
    std::lock_guard lock(stats_->mutex);
    stats_->largest = std::max(stats_->largest, n);
    if (paced)
      stats_->largest_paced = std::max(stats_->largest_paced, n);
    else
      ++stats_->outran;
  }

  std::unique_ptr<ByteLink> inner_;
  std::shared_ptr<ReadStats> stats_;
  std::chrono::steady_clock::time_point last_ = std::chrono::steady_clock::now();
};

// time_scale 1: a real G6's stream; 1.25: the same device sped up to 51 KB/s, the 512000 baud line
// full (a pty has no baud of its own, while the session takes the line rate from the baud).
class SessionReadHold : public ::testing::TestWithParam<double> {};

TEST_P(SessionReadHold, NoReadComesNearTheThrottlePoint) {
  const double time_scale = GetParam();
  SimOnPty sim(Model::G6, [time_scale](SimServerOptions& o) { o.time_scale = time_scale; });
  auto stats = std::make_shared<ReadStats>();
  SessionConfig config = config_for(sim.port(), Model::G6);
  const std::string port = sim.port();
  config.open_link = [port, stats](boost::asio::io_context& io, std::uint32_t baud,
                                   std::string& error) -> std::unique_ptr<ByteLink> {
    auto serial = SerialLink::open(io, port, baud, error);
    if (!serial) return nullptr;
    return std::make_unique<ReadWatch>(std::move(serial), stats);
  };
  Session session(64);
  session.connect(config);
  std::vector<Lap> laps;
  ASSERT_EQ(take_laps(session, 36, &laps), 36u) << describe_snapshot(session.snapshot());
  const CounterSnapshot c = session.snapshot().counters;
  session.disconnect();
  wait_for_state(session, LinkState::Idle);
  std::lock_guard lock(stats->mutex);
  RecordProperty("bytes_per_s", std::to_string(c.bytes_per_s));
  RecordProperty("largest_read", std::to_string(stats->largest));
  RecordProperty("largest_paced_read", std::to_string(stats->largest_paced));
  RecordProperty("reads_beyond_the_line", std::to_string(stats->outran));
  EXPECT_GT(c.bytes_per_s, 35'000.0 * time_scale) << "the virtual G6 should stream as a real one does";
  EXPECT_LT(stats->largest_paced, kThrottlePoint) << "a hold let n_tty's buffer reach the throttle point";
  EXPECT_GT(stats->largest_paced, kMaxPacketSize) << "holds should still gather several packets a read";
  for (std::size_t i = 1; i < laps.size(); ++i) EXPECT_EQ(laps[i].index, laps[i - 1].index + 1) << "no lap lost";
}

INSTANTIATE_TEST_SUITE_P(RealAndFullLine, SessionReadHold, ::testing::Values(1.0, 1.25),
                         [](const auto& param_info) { return param_info.param == 1.0 ? "RealG6" : "FullLine"; });

}  // namespace
}  // namespace ydscope
