// The scan decoder's counters as the session publishes them, after every read: a G1 LastCRC byte
// that a read ended on is pending until the next packet decides what it was.
#include <gtest/gtest.h>

#include "core/protocol/scan_decoder.h"
#include "protocol_test_support.h"

namespace ydscope {
namespace {

using namespace test;

TEST(ScanDecoderCounters, G1LastCrcByteReadAloneIsPendingNotResync) {
  Bytes first;
  append(first, packet(1, 0.0, 0.0, {4}));
  append(first, packet(0, 10.0, 20.0, {4}));
  first.push_back(0x5C);
  Bytes second;
  append(second, packet(1, 0.0, 0.0, {4}));
  ScanDecoder decoder(profile_for(Model::G1));
  const auto ignore = [](const Lap&) {};
  decoder.feed(first, 0, ignore);
  EXPECT_EQ(decoder.counters().resync_bytes, 0u);
  EXPECT_EQ(decoder.counters().pending_bytes, 1u);
  decoder.feed(second, 0, ignore);
  EXPECT_EQ(decoder.counters().resync_bytes, 0u);
  EXPECT_EQ(decoder.counters().pending_bytes, 0u);
  EXPECT_EQ(decoder.counters().laps, 1u);

  // Had an ordinary packet followed, the byte was junk after all.
  ScanDecoder junk(profile_for(Model::G1));
  junk.feed(first, 0, ignore);
  junk.feed(packet(0, 30.0, 40.0, {4}), 0, ignore);
  EXPECT_EQ(junk.counters().resync_bytes, 1u);
  EXPECT_EQ(junk.counters().pending_bytes, 0u);
}

TEST(ScanDecoderCounters, OtherModelsCountAStrayByteAtOnce) {
  Bytes stream;
  append(stream, packet(1, 0.0, 0.0, {4}));
  stream.push_back(0x5C);
  ScanDecoder decoder(profile_for(Model::G6));
  decoder.feed(stream, 0, [](const Lap&) {});
  EXPECT_EQ(decoder.counters().resync_bytes, 1u);
  EXPECT_EQ(decoder.counters().pending_bytes, 0u);
}

}  // namespace
}  // namespace ydscope
