// read_hold: how long the session may leave a scan stream unread. Holds must stay clear of the
// lap's close and of the kernel buffer's limit; without a line rate there is no hold at all.
#include <chrono>

#include <gtest/gtest.h>

#include "core/link/read_hold.h"

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
  // 1000 bytes beyond one packet take 50 ms at 20 kB/s; the hold leaves a margin for a faster
  // stretch but is still far longer than the line-rate bound (19.5 ms).
  const double held = ms(read_hold(inputs(kPacket + 1000)));
  EXPECT_LT(held, 50.0);
  EXPECT_GT(held, 19.6);
}

TEST(ReadHold, AtLeastTheLineRateBoundWhenTheStreamRateIsUnknown) {
  EXPECT_NEAR(ms(read_hold(inputs(kPacket + 512, 0))), 10.0, 0.01);
}

TEST(ReadHold, NeverLongerThanTheLineNeedsToFillTheTtyBuffer) {
  const double most = 4096 / kLine * 1e3;  // 80 ms
  EXPECT_NEAR(ms(read_hold(inputs(100'000))), most, 0.01);
  ReadHoldInputs due_late = inputs(100);
  due_late.lap_end.next_close_ns = due_late.now_ns + 1'000'000'000;
  EXPECT_NEAR(ms(read_hold(due_late)), most, 0.01);
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
