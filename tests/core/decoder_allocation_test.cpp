// Steady-state decoding allocates nothing: the framer's buffer is fixed and laps are preallocated.
// Counts global operator new calls around the feed loop (allocation_counter.h).
#include <gtest/gtest.h>

#include "allocation_counter.h"
#include "protocol_test_support.h"

namespace ydscope {
namespace {

TEST(DecoderAllocation, NoAllocationPerPacketOrLap) {
  for (const Model model : {Model::G1, Model::G6}) {
    test::Bytes stream;
    if (model == Model::G1) {
      test::G1LapSpec spec;
      std::uint8_t crc = 0;
      for (int i = 0; i < 50; ++i) crc = test::append_g1_lap(stream, spec, crc);
      stream.push_back(0x00);  // plus junk and a failed start, to exercise the resync path
      stream.push_back(0xAA);
    } else {
      stream = test::synthetic_stream(50, 20, 40);
    }
    ScanDecoder decoder(profile_for(model));
    std::uint64_t laps = 0;
    std::uint64_t points = 0;
    const auto on_lap = [&](const Lap& lap) {
      ++laps;
      points += lap.points.size();
    };
    const std::uint64_t before = test::allocations().calls;
    for (std::size_t pos = 0; pos < stream.size(); pos += 97)
      decoder.feed({stream.data() + pos, std::min<std::size_t>(97, stream.size() - pos)}, 0, on_lap);
    decoder.finish(on_lap);
    EXPECT_EQ(test::allocations().calls - before, 0u) << profile_for(model).name;
    EXPECT_GE(laps, 49u);
    EXPECT_GT(points, 0u);
  }
}

}  // namespace
}  // namespace ydscope
