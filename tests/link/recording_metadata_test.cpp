// Metadata text of a recording: every field round-trips, escaping, unknown keys, damaged values.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/protocol/model_profile.h"
#include "core/record/recording_metadata.h"

namespace ydscope {
namespace {

TEST(RecordingMetadata, EveryFieldRoundTrips) {
  RecordingMetadata metadata;
  metadata.model = "TG30";
  metadata.baud = 512000;
  metadata.distance_scale = 0.5;
  metadata.port = "tcp://[::1]:2000";
  metadata.start_wall_time = "2026-11-22T02:20:00.123Z";
  metadata.model_code = 101;
  metadata.firmware = "1.3";
  metadata.hardware = 1;
  metadata.serial = "2021010100000001";
  metadata.software = "ydscope 0.1.0";
  metadata.extra["note"] = "bench\\unit 3\nsecond line";
  const std::string text = metadata.encode();
  EXPECT_NE(text.find("baud=512000\n"), std::string::npos);
  EXPECT_NE(text.find("note=bench\\\\unit 3\\nsecond line\n"), std::string::npos) << text;
  std::vector<std::string> warnings;
  EXPECT_EQ(RecordingMetadata::parse(text, &warnings), metadata);
  EXPECT_TRUE(warnings.empty());
}

TEST(RecordingMetadata, EmptyMetadataEncodesToNothing) {
  EXPECT_EQ(RecordingMetadata{}.encode(), "");
  EXPECT_EQ(RecordingMetadata::parse(""), RecordingMetadata{});
}

TEST(RecordingMetadata, DamagedFieldsAreSkippedWithWarnings) {
  std::vector<std::string> warnings;
  const auto metadata = RecordingMetadata::parse("model=G1\nbaud=fast\ngarbage\ndistance_scale=x\nhardware=2\n", &warnings);
  EXPECT_EQ(metadata.model, "G1");
  EXPECT_FALSE(metadata.baud);
  EXPECT_FALSE(metadata.distance_scale);
  EXPECT_EQ(metadata.hardware, 2u);
  ASSERT_EQ(warnings.size(), 3u);
  EXPECT_NE(warnings[0].find("baud='fast'"), std::string::npos);
}

// Issue 17: a scale of nan once reached the JSON as [nan,nan,0]; 0, -1, inf, 1e300 gave nonsense.
TEST(RecordingMetadata, DistanceScaleIsHeldToTheBoundsOfTheOption) {
  for (const std::string bad : {"nan", "inf", "-inf", "1e300", "-1", "0", "1e-7", "1000001"}) {
    std::vector<std::string> warnings;
    const auto metadata = RecordingMetadata::parse("model=G6\ndistance_scale=" + bad + "\n", &warnings);
    EXPECT_FALSE(metadata.distance_scale) << bad;
    EXPECT_EQ(metadata.model, "G6");
    ASSERT_EQ(warnings.size(), 1u) << bad;
    EXPECT_EQ(warnings[0], "metadata distance_scale='" + bad +
                               "' is not a number from 1e-06 to 1e+06 mm per count; ignored, the model's own scale is used");
  }
  for (const double good : {kMinDistanceScale, 0.25, 1.0, kMaxDistanceScale}) {
    RecordingMetadata metadata;
    metadata.distance_scale = good;
    EXPECT_EQ(RecordingMetadata::parse(metadata.encode()).distance_scale, good);
  }
}

TEST(RecordingMetadata, MergeTakesOnlyTheFieldsSetLater) {
  RecordingMetadata start;
  start.model = "G1";
  start.baud = 230400;
  RecordingMetadata later;
  later.baud = 512000;
  later.serial = "123";
  start.merge(later);
  EXPECT_EQ(start.model, "G1");
  EXPECT_EQ(start.baud, 512000u);
  EXPECT_EQ(start.serial, "123");
}

}  // namespace
}  // namespace ydscope
