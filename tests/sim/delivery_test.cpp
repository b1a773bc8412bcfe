// Delivery models: how the virtual lidar's bytes reach the host (whole, USB-bridge bursts at a
// latency timer, random splits). Whatever the delivery, the bytes are the same, and the project's
// own decoder gives the same laps from them.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/protocol/lap.h"
#include "core/protocol/scan_decoder.h"
#include "core/sim/delivery.h"
#include "core/sim/virtual_lidar.h"
#include "sim/sim_test_support.h"
#include "support/field_decoder.h"

namespace ydscope {
namespace {

using test::kMs;
constexpr std::int64_t kUs = 1'000;

TEST(DeliveryParse, ReadsEveryModelAndWritesItBack) {
  for (const std::string text : {"whole", "burst:64:1000", "burst:62:16000", "random:17", "random:1"}) {
    const auto model = parse_delivery(text);
    ASSERT_TRUE(model) << text;
    EXPECT_EQ(delivery_text(*model), text);
  }
  const auto burst = parse_delivery("burst:64:1000");
  EXPECT_EQ(burst->kind, DeliveryKind::Burst);
  EXPECT_EQ(burst->burst_bytes, 64u);
  EXPECT_EQ(burst->interval_ns, 1'000'000);
}

TEST(DeliveryParse, RefusesBadTextWithASentence) {
  for (const std::string text : {"", "bursts", "burst:64", "burst:0:1000", "burst:64:0", "burst:64:x", "random:0",
                                 "random:", "random:5000", "whole:1"}) {
    std::string error;
    EXPECT_FALSE(parse_delivery(text, &error)) << text;
    EXPECT_FALSE(error.empty()) << text;
  }
}

struct Write {
  std::int64_t at_ns;
  std::vector<std::uint8_t> bytes;
};

struct Delivered {
  std::vector<std::uint8_t> line;  // what the device's line carried, in order
  std::vector<Write> writes;       // what the bridge handed the host
};

// The virtual lidar scanning for `duration`, its line drained every `step`, through the shaper.
Delivered deliver(Model model, const DeliveryModel& delivery, std::int64_t duration, std::int64_t step = 250 * kUs) {
  VirtualLidarConfig config;
  config.model = model;
  config.scene = "room";
  VirtualLidar lidar(config);
  DeliveryShaper shaper(delivery, lidar.profile().default_baud, 11, 0);
  Delivered d;
  std::int64_t now = 0;
  lidar.receive(test::bytes({0xA5, 0x60}), now);
  std::vector<std::uint8_t> out;
  std::vector<std::uint8_t> shaped;
  std::vector<std::size_t> ends;
  for (; now <= duration + 100 * kMs; now += step) {
    out.clear();
    if (now <= duration) lidar.produce(now, out);
    d.line.insert(d.line.end(), out.begin(), out.end());
    shaper.push(now, out);
    shaped.clear();
    ends.clear();
    shaper.pop(now, shaped, ends);
    std::size_t from = 0;
    for (const std::size_t end : ends) {
      d.writes.push_back({now, std::vector<std::uint8_t>(shaped.begin() + static_cast<std::ptrdiff_t>(from),
                                                         shaped.begin() + static_cast<std::ptrdiff_t>(end))});
      from = end;
    }
    EXPECT_EQ(from, shaped.size()) << "every released byte belongs to a write";
  }
  EXPECT_EQ(shaper.held(), 0u) << "everything held is delivered once the line is quiet";
  return d;
}

std::vector<std::uint8_t> joined(const std::vector<Write>& writes) {
  std::vector<std::uint8_t> all;
  for (const Write& w : writes) all.insert(all.end(), w.bytes.begin(), w.bytes.end());
  return all;
}

struct Decoded {
  std::vector<Lap> laps;
  DecoderCounters counters;
};

// The project's decoder fed one write at a time, as a host's reads would see them at best.
Decoded decode(Model model, const std::vector<Write>& writes) {
  ScanDecoder decoder = test::field_decoder(model);
  Decoded result;
  for (const Write& w : writes) decoder.feed(w.bytes, w.at_ns, [&](const Lap& lap) { result.laps.push_back(lap); });
  result.counters = decoder.counters();
  return result;
}

void expect_same_laps(const Decoded& a, const Decoded& b, const std::string& what) {
  ASSERT_EQ(a.laps.size(), b.laps.size()) << what;
  for (std::size_t i = 0; i < a.laps.size(); ++i) {
    const Lap& x = a.laps[i];
    const Lap& y = b.laps[i];
    ASSERT_EQ(x.points.size(), y.points.size()) << what << " lap " << i;
    for (std::size_t p = 0; p < x.points.size(); ++p) {
      EXPECT_EQ(x.points[p].angle_deg, y.points[p].angle_deg) << what << " lap " << i << " point " << p;
      EXPECT_EQ(x.points[p].range_mm, y.points[p].range_mm) << what << " lap " << i << " point " << p;
      EXPECT_EQ(x.points[p].flag, y.points[p].flag) << what << " lap " << i << " point " << p;
    }
    EXPECT_EQ(x.crc, y.crc) << what << " lap " << i;
    EXPECT_EQ(x.scan_hz, y.scan_hz) << what << " lap " << i;
  }
  EXPECT_EQ(a.counters.packets, b.counters.packets) << what;
  EXPECT_EQ(a.counters.checksum_errors, b.counters.checksum_errors) << what;
  EXPECT_EQ(a.counters.resync_bytes, b.counters.resync_bytes) << what;
}

class DeliverySameLaps : public ::testing::TestWithParam<Model> {};

TEST_P(DeliverySameLaps, EveryDeliveryGivesTheSameBytesAndTheSameLaps) {
  const Model model = GetParam();
  const std::int64_t duration = 1'500 * kMs;
  const Delivered whole = deliver(model, {}, duration);
  const Decoded reference = decode(model, whole.writes);
  ASSERT_GE(reference.laps.size(), 10u);
  EXPECT_EQ(reference.counters.checksum_errors, 0u);
  for (const std::string text :
       {"burst:64:1000", "burst:62:16000", "burst:32:250", "random:17", "random:1", "random:300"}) {
    const Delivered d = deliver(model, *parse_delivery(text), duration);
    EXPECT_EQ(d.line, whole.line) << text << ": the device sent the same";
    EXPECT_EQ(joined(d.writes), d.line) << text << ": nothing lost, added or reordered";
    expect_same_laps(decode(model, d.writes), reference, text);
  }
}

INSTANTIATE_TEST_SUITE_P(Models, DeliverySameLaps, ::testing::Values(Model::G1, Model::G6, Model::TG30),
                         [](const auto& param_info) { return std::string(profile_for(param_info.param).name); });

TEST(DeliveryBurst, FullBurstsAtTicksAndTheRestAfterOneQuietInterval) {
  const DeliveryModel burst = *parse_delivery("burst:64:16000");
  const Delivered d = deliver(Model::G6, burst, 500 * kMs, 100 * kUs);
  ASSERT_FALSE(d.writes.empty());
  std::size_t partial = 0;
  for (std::size_t i = 0; i < d.writes.size(); ++i) {
    const Write& w = d.writes[i];
    EXPECT_EQ(w.at_ns % burst.interval_ns, 0) << "write " << i << " off the latency timer's ticks";
    EXPECT_LE(w.bytes.size(), 64u);
    if (w.bytes.size() < 64u) ++partial;
  }
  // A G6 stream is ~20 bytes a millisecond: a 16 ms tick finds about five full bursts, and what is
  // left over tops up the next burst unless it has waited a whole interval.
  EXPECT_LT(partial, d.writes.size() / 4);
}

TEST(DeliveryRandom, WritesAreOneToMaxBytesAndNeverFasterThanTheLine) {
  const Delivered d = deliver(Model::G1, *parse_delivery("random:17"), 500 * kMs, 20 * kUs);
  ASSERT_GT(d.writes.size(), 100u);
  std::size_t sizes_seen[18] = {};
  for (const Write& w : d.writes) {
    ASSERT_GE(w.bytes.size(), 1u);
    ASSERT_LE(w.bytes.size(), 17u);
    ++sizes_seen[w.bytes.size()];
  }
  for (std::size_t size = 1; size <= 17; ++size) EXPECT_GT(sizes_seen[size], 0u) << size << "-byte writes";
  // 17 bytes at 230400 baud take 738 us: the whole delivery cannot beat the line.
  const std::int64_t span = d.writes.back().at_ns - d.writes.front().at_ns;
  const auto carried = static_cast<double>(joined(d.writes).size() - d.writes.back().bytes.size());
  EXPECT_GE(static_cast<double>(span), carried * 10e9 / 230400 * 0.99);
}

TEST(DeliveryShaperState, ClearLosesHeldBytesAndNothingIsDueAfter) {
  DeliveryShaper shaper(*parse_delivery("burst:64:1000"), 512000, 1, 0);
  const std::vector<std::uint8_t> bytes(40, 0x11);
  shaper.push(100 * kUs, bytes);
  EXPECT_EQ(shaper.held(), 40u);
  EXPECT_EQ(shaper.next_due_ns(), 1'000 * kUs);
  shaper.clear();
  EXPECT_EQ(shaper.held(), 0u);
  EXPECT_EQ(shaper.next_due_ns(), DeliveryShaper::kNever);
}

}  // namespace
}  // namespace ydscope
