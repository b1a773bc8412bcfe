// read_hold: how long the session may leave a scan stream unread. Holds must stay clear of the
// lap's close and of the point where the kernel throttles the port; without a line rate there is
// no hold at all.
#include <algorithm>
#include <chrono>
#include <random>

#include <gtest/gtest.h>

#include "core/session/read_hold.h"
#include "core/protocol/scan_packet.h"

namespace ydscope {
namespace {

using std::chrono::milliseconds;
using std::chrono::nanoseconds;

constexpr double kLine = 51'200;    // 512000 baud
constexpr double kStream = 20'000;  // what a G6 delivers on average
constexpr std::size_t kPacket = 90;

ReadHoldInputs inputs(std::size_t bytes, double stream = kStream) {
  ReadHoldInputs in;
  in.now_ns = 1'000'000'000;
  in.lap_end.bytes = bytes;
  in.lap_end.packet_bytes = kPacket;
  in.stream_bytes_per_s = stream;
  in.line_bytes_per_s = kLine;
  return in;
}

double ms(nanoseconds d) { return static_cast<double>(d.count()) * 1e-6; }

TEST(ReadHold, NoneWithoutALineRate) {
  ReadHoldInputs in = inputs(5000);
  in.line_bytes_per_s = 0;  // TCP, replay
  EXPECT_EQ(read_hold(in), nanoseconds(0));
}

TEST(ReadHold, NoneWhenTheLapMayCloseWithinAPacket) {
  EXPECT_EQ(read_hold(inputs(kPacket)), nanoseconds(0));
  EXPECT_EQ(read_hold(inputs(12)), nanoseconds(0));
}

TEST(ReadHold, AllButOnePacketAtTheStreamsRateWithAMargin) {
  // 800 bytes beyond one packet take 40 ms at 20 kB/s; the hold leaves a margin for a faster
  // stretch (15 %) but is still far longer than the line-rate bound (15.6 ms), and short of the
  // throttle-point bound (42.3 ms), which would hide the margin.
  const double held = ms(read_hold(inputs(kPacket + 800)));
  EXPECT_LT(held, 40.0);
  EXPECT_GT(held, 15.7);
  EXPECT_NEAR(held, 800 / (kStream * 1.15) * 1e3, 0.01);
}

TEST(ReadHold, AtLeastTheLineRateBoundWhenTheStreamRateIsUnknown) {
  EXPECT_NEAR(ms(read_hold(inputs(kPacket + 512, 0))), 10.0, 0.01);
}

TEST(ReadHold, NeverLongerThanTheLineNeedsToReachTheThrottlePoint) {
  // (4096 - 128 throttle room - 256 margin - 520 waiting packet) / 51 200 B/s - 20 ms timer lateness
  const double most = (4096.0 - 128 - 256 - 520) / kLine * 1e3 - 20;  // 42.3 ms
  EXPECT_NEAR(ms(read_hold(inputs(100'000))), most, 0.01);
  ReadHoldInputs due_late = inputs(100);
  due_late.lap_end.next_close_ns = due_late.now_ns + 1'000'000'000;
  EXPECT_NEAR(ms(read_hold(due_late)), most, 0.01);
}

// What may pile up in n_tty's 4 KiB buffer during a hold, at the worst (line) rate: a packet
// already waiting, the hold itself, and the timer firing late. It must stay below the point where
// n_tty throttles the driver (128 bytes free), past which a USB bridge's FIFO overflows.
TEST(ReadHold, WhatPilesUpStaysBelowTheThrottlePoint) {
  constexpr double kThrottlePoint = 4096 - 128;
  constexpr double kTimerLateness_s = 0.020;  // a loaded machine's late timer (p99 7.8-21.5 ms seen)
  std::mt19937 random(25);
  for (const double baud : {115'200.0, 128'000.0, 230'400.0, 512'000.0, 921'600.0}) {
    const double line = baud / 10;  // 8N1: 10 bits a byte
    double longest = 0;
    for (int tenths = 1; tenths <= 10; ++tenths) {
      const double stream = line * tenths / 10;
      for (int i = 0; i < 2000; ++i) {
        ReadHoldInputs in;
        in.now_ns = 1'000'000'000;
        in.line_bytes_per_s = line;
        in.stream_bytes_per_s = i % 7 == 0 ? 0 : stream;  // sometimes still unknown
        in.lap_end.bytes = std::uniform_int_distribution<std::size_t>(1, 200'000)(random);
        in.lap_end.packet_bytes =
            i % 5 == 0 ? 0 : std::uniform_int_distribution<std::size_t>(12, kMaxPacketSize)(random);
        if (i % 3 != 0) {  // a time forecast, up to far beyond any hold
          in.lap_end.next_close_ns = in.now_ns + std::uniform_int_distribution<std::int64_t>(0, 2'000'000'000)(random);
          in.lap_end.close_slack_ns = std::uniform_int_distribution<std::int64_t>(0, 5'000'000)(random);
        }
        const double hold_s = static_cast<double>(read_hold(in).count()) * 1e-9;
        longest = std::max(longest, hold_s);
        const double piled = (hold_s + kTimerLateness_s) * line + static_cast<double>(kMaxPacketSize);
        ASSERT_LT(piled, kThrottlePoint) << baud << " baud, stream " << stream << " B/s, hold " << hold_s * 1e3
                                         << " ms, forecast " << in.lap_end.bytes << " bytes";
      }
    }
    // Holds still pay for themselves: at every rate some last many milliseconds.
    EXPECT_GT(longest, 0.010) << baud << " baud";
  }
}

// A virtual TG on a pty opened at 230400 (model auto probes it first; a pty passes bytes whatever
// the baud) delivers a real TG's 45 kB/s where the baud says 23 kB/s: no hold is safe then.
TEST(ReadHold, NoneWhenTheStreamOutrunsTheBaud) {
  ReadHoldInputs in = inputs(100'000, 45'000);
  in.line_bytes_per_s = 23'040;
  EXPECT_EQ(read_hold(in), nanoseconds(0));
  in.stream_bytes_per_s = 20'000;  // within the baud: holds as before
  EXPECT_GT(read_hold(in), milliseconds(10));
}

TEST(ReadHold, UntilTheLapIsDueLessItsSlack) {
  ReadHoldInputs in = inputs(100);
  in.lap_end.next_close_ns = in.now_ns + 30'000'000;
  in.lap_end.close_slack_ns = 2'000'000;
  EXPECT_NEAR(ms(read_hold(in)), 28.0, 0.01);
  // A lap overdue (or due within its slack) leaves only the byte bounds.
  in.lap_end.next_close_ns = in.now_ns + 1'000'000;
  EXPECT_EQ(read_hold(in), nanoseconds(0));
}

}  // namespace
}  // namespace ydscope
