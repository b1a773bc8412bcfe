// RecordTap: every record arrives in order across threads, a full tap drops and counts instead of
// blocking the producer, and close() ends the consumer.
#include <gtest/gtest.h>

#include <thread>

#include "core/session/record_tap.h"

namespace ydscope {
namespace {

TEST(RecordTap, DeliversEveryRecordInOrderAcrossThreads) {
  RecordTap tap;
  constexpr int kRecords = 20000;
  std::thread producer([&] {
    for (int i = 0; i < kRecords; ++i) {
      const std::uint8_t bytes[4] = {static_cast<std::uint8_t>(i), static_cast<std::uint8_t>(i >> 8), 1, 2};
      ASSERT_TRUE(tap.push(i % 2 ? RecordType::HostToDevice : RecordType::DeviceToHost, bytes, i));
    }
    tap.close();
  });
  std::vector<TapRecord> records;
  int next = 0;
  while (tap.wait_and_take(records, std::chrono::milliseconds(100))) {
    for (const auto& r : records) {
      ASSERT_EQ(r.t_ns, next);
      ASSERT_EQ(r.payload[0], static_cast<std::uint8_t>(next));
      ASSERT_EQ(r.type, next % 2 ? RecordType::HostToDevice : RecordType::DeviceToHost);
      ++next;
    }
    tap.recycle(records);
  }
  producer.join();
  EXPECT_EQ(next, kRecords);
  EXPECT_EQ(tap.dropped(), 0u);
}

TEST(RecordTap, AFullTapDropsAndCountsInsteadOfBlocking) {
  RecordTap tap(10);  // bytes
  const std::uint8_t four[4] = {};
  EXPECT_TRUE(tap.push(RecordType::DeviceToHost, four, 0));
  EXPECT_TRUE(tap.push(RecordType::DeviceToHost, four, 1));
  EXPECT_FALSE(tap.push(RecordType::DeviceToHost, four, 2));  // 12 > 10
  EXPECT_EQ(tap.dropped(), 1u);
  std::vector<TapRecord> records;
  EXPECT_TRUE(tap.wait_and_take(records, std::chrono::milliseconds(0)));
  EXPECT_EQ(records.size(), 2u);
  tap.recycle(records);
  EXPECT_TRUE(tap.push(RecordType::DeviceToHost, four, 3));  // room again
  tap.close();
  EXPECT_TRUE(tap.wait_and_take(records, std::chrono::milliseconds(0)));
  EXPECT_EQ(records.size(), 1u);
  records.clear();
  EXPECT_FALSE(tap.wait_and_take(records, std::chrono::milliseconds(0)));
}

}  // namespace
}  // namespace ydscope
