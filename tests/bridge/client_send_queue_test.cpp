// ClientSendQueue: a slow client's bounded queue drops its oldest waiting messages and counts
// them, and never moves or drops the message a socket write is reading.
#include <gtest/gtest.h>

#include "core/bridge/client_send_queue.h"

namespace ydscope::foxglove {
namespace {

OutgoingMessage numbered(int n) {
  OutgoingMessage message;
  message.header[0] = 0x01;
  message.header[1] = static_cast<std::uint8_t>(n);
  message.header[2] = static_cast<std::uint8_t>(n >> 8);
  message.payload = std::make_shared<const std::vector<std::uint8_t>>(64, static_cast<std::uint8_t>(n));
  return message;
}

int number_of(const OutgoingMessage& message) { return message.header[1] | message.header[2] << 8; }

// Regression: with the in-flight message at the front of the same deque, dropping the oldest
// waiting one (right behind it) moved it while Beast was still writing its header bytes.
TEST(ClientSendQueue, TheMessageBeingWrittenNeverMovesWhileTheQueueOverflows) {
  ClientSendQueue queue(4);
  ASSERT_FALSE(queue.push(numbered(0)));
  const OutgoingMessage* in_flight = queue.begin_write();
  ASSERT_NE(in_flight, nullptr);
  const std::uint8_t* header_bytes = in_flight->header.data();
  for (int n = 1; n <= 1000; ++n) queue.push(numbered(n));
  // Still there, unchanged, at the same address the write was given.
  EXPECT_EQ(in_flight->header.data(), header_bytes);
  EXPECT_EQ(number_of(*in_flight), 0);
  EXPECT_EQ(queue.begin_write(), nullptr) << "one write at a time";
  // Capacity 4 = the one in flight and 3 waiting: 1000 pushed, 997 dropped, the oldest first.
  EXPECT_EQ(queue.waiting(), 3u);
  EXPECT_EQ(queue.dropped(), 997u);
  queue.end_write();
  for (int expected : {998, 999, 1000}) {
    const OutgoingMessage* next = queue.begin_write();
    ASSERT_NE(next, nullptr);
    EXPECT_EQ(number_of(*next), expected);
    queue.end_write();
  }
  EXPECT_EQ(queue.begin_write(), nullptr);
}

TEST(ClientSendQueue, WithNothingInFlightItHoldsItsCapacityAndDropsTheOldest) {
  ClientSendQueue queue(3);
  EXPECT_FALSE(queue.push(numbered(1)));
  EXPECT_FALSE(queue.push(numbered(2)));
  EXPECT_FALSE(queue.push(numbered(3)));
  EXPECT_TRUE(queue.push(numbered(4)));
  EXPECT_EQ(queue.dropped(), 1u);
  EXPECT_EQ(queue.waiting(), 3u);
  EXPECT_EQ(number_of(*queue.begin_write()), 2);
}

TEST(ClientSendQueue, CapacityOneStillDeliversTheNewestAfterTheWrite) {
  ClientSendQueue queue(0);  // taken as 1
  queue.push(numbered(1));
  ASSERT_NE(queue.begin_write(), nullptr);
  queue.push(numbered(2));  // waits behind the write: nothing older to drop
  queue.push(numbered(3));  // replaces 2
  EXPECT_EQ(queue.dropped(), 1u);
  queue.end_write();
  EXPECT_EQ(number_of(*queue.begin_write()), 3);
}

// Regression: the status warning about drops was queued behind laps and dropped by the next
// ones, so a client slow enough to lose laps never heard about it.
TEST(ClientSendQueue, TextMessagesOutliveLapsWhenTheQueueIsFull) {
  ClientSendQueue queue(3);
  queue.push(numbered(1));
  OutgoingMessage warning;
  warning.text = true;
  warning.json = R"({"op":"status"})";
  queue.push(warning);
  for (int n = 2; n <= 50; ++n) queue.push(numbered(n));
  EXPECT_EQ(queue.dropped(), 48u);
  const OutgoingMessage* first = queue.begin_write();
  ASSERT_NE(first, nullptr);
  EXPECT_TRUE(first->text) << "the warning was dropped";
  queue.end_write();
  EXPECT_EQ(number_of(*queue.begin_write()), 49);
}

TEST(ClientSendQueue, AQueueOfTextAloneStaysBounded) {
  ClientSendQueue queue(2);
  for (int n = 0; n < 10; ++n) {
    OutgoingMessage status;
    status.text = true;
    status.json = std::to_string(n);
    queue.push(status);
  }
  EXPECT_EQ(queue.waiting(), 2u);
  EXPECT_EQ(queue.dropped(), 8u);
  EXPECT_EQ(queue.begin_write()->json, "8");
}

// What a client that never reads pins: never more than the capacity, in messages and so in bytes,
// and nothing once everything is written.
TEST(ClientSendQueue, CountsWhatItHoldsInMessagesAndBytes) {
  ClientSendQueue queue(4);
  const std::size_t lap_bytes = numbered(0).bytes();
  EXPECT_EQ(lap_bytes, 13u + 64u);
  queue.push(numbered(0));
  ASSERT_NE(queue.begin_write(), nullptr);
  for (int n = 1; n <= 100; ++n) {
    queue.push(numbered(n));
    EXPECT_LE(queue.queued(), 4u);
    EXPECT_EQ(queue.queued_bytes(), queue.queued() * lap_bytes);
  }
  OutgoingMessage status;
  status.text = true;
  status.json = "0123456789";
  queue.push(status);  // a lap goes for it
  EXPECT_EQ(queue.queued(), 4u);
  EXPECT_EQ(queue.queued_bytes(), 3 * lap_bytes + 10);
  queue.end_write();
  while (queue.begin_write()) queue.end_write();
  EXPECT_EQ(queue.queued(), 0u);
  EXPECT_EQ(queue.queued_bytes(), 0u);
}

}  // namespace
}  // namespace ydscope::foxglove
