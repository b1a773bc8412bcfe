// Metadata text of a recording: every field round-trips, escaping, unknown keys, damaged values;
// and the device details a replay shows from it.
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "core/session/recorded_device.h"
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
  const auto metadata =
      RecordingMetadata::parse("model=G1\nbaud=fast\ngarbage\ndistance_scale=x\nhardware=2\n", &warnings);
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
    EXPECT_EQ(warnings[0],
              "metadata distance_scale='" + bad +
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

namespace ydscope {
namespace {

// A recording's device fields are bytes on the wire; a file claiming more leaves them blank
// instead of showing a wrapped-around value (or reading an overflowing number, which sscanf
// would do with undefined behaviour).
TEST(RecordedDevice, FieldsWiderThanADeviceByteStayBlank) {
  const ModelProfile& g6 = profile_for(Model::G6);
  RecordingMetadata sound;
  sound.model_code = 13;
  sound.hardware = 1;
  sound.firmware = "1.2";
  const DeviceDetails ok = recorded_device(sound, g6);
  EXPECT_EQ(ok.model_code, 13);
  EXPECT_EQ(ok.hardware, 1);
  EXPECT_EQ(ok.firmware.major, 1);
  EXPECT_EQ(ok.firmware.minor, 2);
  for (const char* firmware : {"300.7", "-1.2", "4294967297.1", "1.256", "1", "1.", ".2", "1.2.3", "x.y", ""}) {
    RecordingMetadata lying;
    lying.firmware = firmware;
    const DeviceDetails device = recorded_device(lying, g6);
    EXPECT_EQ(device.firmware.major, 0) << firmware;
    EXPECT_EQ(device.firmware.minor, 0) << firmware;
  }
  RecordingMetadata wide;
  wide.model_code = 1000;
  wide.hardware = 256;
  const DeviceDetails device = recorded_device(wide, g6);
  EXPECT_EQ(device.model_code, 0);
  EXPECT_EQ(device.hardware, 0);
}

}  // namespace
}  // namespace ydscope
