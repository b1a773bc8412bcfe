// LapEndForecast through ScanDecoder: the bytes it says can still arrive before a lap closes must
// never overshoot the real distance to the next published lap (an overshoot would let the session
// sleep through a lap), and must be large mid-lap (or the forecast saves nothing).
#include <algorithm>
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "core/protocol/lap_end_forecast.h"
#include "core/protocol/scan_decoder.h"
#include "core/protocol/scan_packet.h"
#include "core/protocol/model_profile.h"
#include "core/protocol/g1_ct.h"
#include "protocol_test_support.h"

namespace ydscope {
namespace {

using test::Bytes;

// Laps the way a device sends them: a one-sample zero packet at `zero_deg`, then packets of up to
// `lsn` samples going round, the last one short. G1 puts its LastCRC byte before each zero packet.
Bytes device_stream(int laps, int samples_per_lap, int lsn, double zero_deg, bool last_crc) {
  Bytes out;
  const double step = 360.0 / samples_per_lap;
  for (int lap = 0; lap <= laps; ++lap) {
    if (last_crc) out.push_back(0x5C);
    test::append(out, test::packet(kCtLapStart, zero_deg, zero_deg, {1000}));
    if (lap == laps) break;
    for (int first = 1; first < samples_per_lap; first += lsn) {
      const int last = std::min(first + lsn - 1, samples_per_lap - 1);
      std::vector<std::uint16_t> samples(static_cast<std::size_t>(last - first + 1), 2000);
      test::append(out, test::packet(0x02, zero_deg + first * step, zero_deg + last * step, samples));
    }
  }
  return out;
}

struct Walk {
  std::vector<std::size_t> forecast;    // outlook bytes after each byte fed
  std::vector<std::size_t> lap_closes;  // stream positions (bytes fed) at which a lap was published
};

Walk walk_byte_by_byte(const ModelProfile& profile, const Bytes& stream) {
  ScanDecoder decoder(profile);
  Walk walk;
  for (std::size_t i = 0; i < stream.size(); ++i) {
    decoder.feed({stream.data() + i, 1}, 0, [&](const Lap&) { walk.lap_closes.push_back(i + 1); });
    walk.forecast.push_back(decoder.lap_end_outlook().bytes);
  }
  return walk;
}

// For every position before the last lap closed: forecast <= distance to the next close.
void expect_never_past_a_lap_close(const Walk& walk) {
  ASSERT_FALSE(walk.lap_closes.empty());
  std::size_t next = 0;
  for (std::size_t fed = 1; fed <= walk.forecast.size(); ++fed) {
    while (next < walk.lap_closes.size() && walk.lap_closes[next] <= fed) ++next;
    if (next == walk.lap_closes.size()) break;
    const std::size_t distance = walk.lap_closes[next] - fed;
    ASSERT_LE(walk.forecast[fed - 1], distance) << "after byte " << fed;
  }
}

TEST(LapEndForecast, NeverReachesPastTheNextLapClose) {
  const ModelProfile& g6 = *find_profile("G6");
  for (const double zero_deg : {0.0, 3.5, 200.0}) {
    for (const int lsn : {40, 32, 7}) {
      SCOPED_TRACE(testing::Message() << "zero at " << zero_deg << " deg, lsn " << lsn);
      expect_never_past_a_lap_close(walk_byte_by_byte(g6, device_stream(4, 1000, lsn, zero_deg, false)));
    }
  }
}

TEST(LapEndForecast, CountsG1sLastCrcByteBeforeTheZeroPacket) {
  const ModelProfile& g1 = *find_profile("G1");
  expect_never_past_a_lap_close(walk_byte_by_byte(g1, device_stream(4, 900, 40, 0.0, true)));
}

TEST(LapEndForecast, MidLapItAllowsMostOfTheLap) {
  const ModelProfile& g6 = *find_profile("G6");
  const Bytes stream = device_stream(3, 1000, 40, 0.0, false);
  const Walk walk = walk_byte_by_byte(g6, stream);
  ASSERT_GE(walk.lap_closes.size(), 2u);
  // Just after a lap closed, the next one is a whole lap of packets away; the forecast should
  // allow all but a few packets of it.
  const std::size_t close = walk.lap_closes[0];
  const std::size_t lap_bytes = walk.lap_closes[1] - close;
  EXPECT_GE(walk.forecast[close - 1 + packet_size(40)], lap_bytes - 4 * packet_size(40));
}

TEST(LapEndForecast, WithoutARhythmItAsksForEveryByte) {
  LapEndForecast forecast;
  EXPECT_EQ(forecast.outlook({}).bytes, 1u);
  EXPECT_EQ(forecast.outlook({}).packet_bytes, 0u);
  EXPECT_EQ(forecast.outlook({}).next_close_ns, 0);
}

PacketView view(std::uint8_t ct, double fsa_deg, std::uint8_t lsn, std::int64_t rx_ns) {
  PacketView p;
  p.ct = ct;
  p.lsn = lsn;
  p.fsa = p.lsa = encode_raw_angle(fsa_deg);
  p.rx_ns = rx_ns;
  return p;
}

TEST(LapEndForecast, PredictsTheNextCloseFromTheLapPeriod) {
  LapEndForecast forecast;
  constexpr std::int64_t kPeriod = 100'000'000;
  // The slack starts wide and narrows as the laps keep their rhythm.
  forecast.observe(view(kCtLapStart, 0, 1, kPeriod));
  forecast.observe(view(kCtLapStart, 0, 1, 2 * kPeriod));
  const std::int64_t first_slack = forecast.outlook({}).close_slack_ns;
  for (int lap = 3; lap <= 12; ++lap) forecast.observe(view(kCtLapStart, 0, 1, lap * kPeriod));
  const LapEndOutlook steady = forecast.outlook({});
  EXPECT_NEAR(static_cast<double>(steady.next_close_ns), 13.0 * kPeriod, 1e6);
  EXPECT_LT(steady.close_slack_ns, first_slack);
  EXPECT_GT(steady.close_slack_ns, 0);
  EXPECT_LT(steady.close_slack_ns, kPeriod / 10);

  // A lap that comes 20 ms early widens the slack beyond what it missed by.
  forecast.observe(view(kCtLapStart, 0, 1, 13 * kPeriod - 20'000'000));
  EXPECT_GT(forecast.outlook({}).close_slack_ns, 20'000'000);
}

TEST(LapEndForecast, ResetForgetsTheRhythm) {
  const ModelProfile& g6 = *find_profile("G6");
  ScanDecoder decoder(g6);
  const Bytes stream = device_stream(2, 1000, 40, 0.0, false);
  decoder.feed(stream, 1'000, [](const Lap&) {});
  EXPECT_GT(decoder.lap_end_outlook().packet_bytes, 0u);
  decoder.reset();
  EXPECT_EQ(decoder.lap_end_outlook().bytes, 1u);
  EXPECT_EQ(decoder.lap_end_outlook().packet_bytes, 0u);
}

}  // namespace
}  // namespace ydscope
