// The ROS 2 messages: CDR layout, /scan binned as the official driver bins with REP-117's special
// values and stamped at the first ray, /points exact, and the record stream -> topics path giving
// exactly the laps ScanDecoder gives.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "core/export/cdr_writer.h"
#include "core/export/mcap_recording_export.h"
#include "core/export/ros_encoding.h"
#include "core/export/ros_topic_encoder.h"
#include "core/protocol/scan_decoder.h"
#include "core/protocol/scan_packet.h"
#include "export/cdr_test_reader.h"
#include "export/mcap_test_reader.h"
#include "export/laser_scan_reader.h"
#include "export/point_cloud_reader.h"

namespace ydscope {
namespace {

TEST(CdrWriter, AlignsFromTheEndOfTheEncapsulationHeader) {
  std::vector<std::uint8_t> out;
  CdrWriter cdr(out);
  cdr.u8(7);
  cdr.u32(0x01020304);
  cdr.string("ab");
  cdr.f64(1.0);
  const std::vector<std::uint8_t> expected = {0, 1, 0, 0, 7, 0, 0,    0,   4, 3, 2, 1, 3, 0, 0, 0, 'a', 'b', 0,
                                              0,  // to 8-byte alignment: offset 16 after the header
                                              0, 0, 0, 0, 0, 0, 0xF0, 0x3F};
  EXPECT_EQ(out, expected);
}

TEST(RosAngle, FollowsTheDriversReversionAndInversion) {
  RosFrameOptions frame;  // reversion and inverted, as the official parameter files
  EXPECT_NEAR(ros_angle_rad(0.0f, frame), std::numbers::pi, 1e-12);       // device 0 deg -> behind
  EXPECT_NEAR(ros_angle_rad(90.0f, frame), std::numbers::pi / 2, 1e-12);  // clockwise 90 -> counter-clockwise +90
  EXPECT_NEAR(ros_angle_rad(180.0f, frame), 0.0, 1e-12);
  EXPECT_NEAR(ros_angle_rad(270.0f, frame), -std::numbers::pi / 2, 1e-12);
  frame.reversion = frame.inverted = false;
  EXPECT_NEAR(ros_angle_rad(270.0f, frame), -std::numbers::pi / 2, 1e-12);
  EXPECT_NEAR(ros_angle_rad(90.0f, frame), std::numbers::pi / 2, 1e-12);
}

Lap four_point_lap() {
  Lap lap;
  lap.points = {{10.0f, 1000.0f, PointFlag::None},
                {100.0f, 30000.0f, PointFlag::None},  // beyond G6's 25 m: +Inf in /scan
                {190.0f, 2500.5f, PointFlag::Specular},
                {280.0f, 0.0f, PointFlag::None}};  // no return
  lap.first_rx_ns = 2'000'000'123;
  lap.last_rx_ns = 2'100'000'123;
  return lap;
}

TEST(ScanTimes, StampTheFirstRayAndTimeTheLapByItsOwnReceiveTimes) {
  Lap lap = four_point_lap();
  lap.index = 0;  // the first lap of a stream: no previous lap to time it by
  const ScanTimes times = scan_times(lap, 10'000'000'000);
  EXPECT_EQ(times.stamp_ns, 12'000'000'123u) << "the lap's first receive time, not its closing byte's";
  EXPECT_DOUBLE_EQ(times.scan_time_s, 0.1);
  EXPECT_DOUBLE_EQ(times.time_increment_s, 0.1 / 4);
  lap.points.clear();
  EXPECT_EQ(scan_times(lap, 0).time_increment_s, 0.0);
  EXPECT_EQ(scan_times(lap, -5'000'000'000).stamp_ns, 0u) << "before the epoch is clamped, not wrapped";
}

TEST(ScanRange, UsesRep117sSpecialValues) {
  const RangeLimits g1 = range_limits(Model::G1);
  constexpr float kInf = std::numeric_limits<float>::infinity();
  EXPECT_EQ(scan_range(0.0f, g1), kInf) << "no return";
  EXPECT_EQ(scan_range(17000.0f, g1), kInf) << "beyond range_max: nothing within range";
  EXPECT_EQ(scan_range(50.0f, g1), -kInf) << "below range_min: too close to measure";
  EXPECT_FLOAT_EQ(scan_range(1234.5f, g1), 1.2345f);
  EXPECT_FLOAT_EQ(scan_range(g1.max_m * 1000.0f, g1), g1.max_m);
  EXPECT_FLOAT_EQ(scan_range(g1.min_m * 1000.0f, g1), g1.min_m);
}

TEST(LaserScan, BinsLikeTheOfficialDriver) {
  RosFrameOptions frame;
  frame.frame_id = "lidar_0";
  std::vector<float> scratch;
  std::vector<std::uint8_t> out;
  const Lap lap = four_point_lap();
  encode_laser_scan(lap, frame, range_limits(Model::G6), scan_times(lap, 10'000'000'000), scratch, out);
  test::CdrReader r(out);
  EXPECT_EQ(r.i32(), 12);
  EXPECT_EQ(r.u32(), 123u);
  EXPECT_EQ(r.str(), "lidar_0");
  EXPECT_FLOAT_EQ(r.f32(), static_cast<float>(-std::numbers::pi));
  EXPECT_FLOAT_EQ(r.f32(), static_cast<float>(std::numbers::pi));
  const float increment = r.f32();
  EXPECT_FLOAT_EQ(increment, static_cast<float>(2 * std::numbers::pi / 3));  // 4 points: 3 intervals
  EXPECT_FLOAT_EQ(r.f32(), 0.1f / 4);
  EXPECT_FLOAT_EQ(r.f32(), 0.1f);
  EXPECT_FLOAT_EQ(r.f32(), 0.1f);
  EXPECT_FLOAT_EQ(r.f32(), 25.0f);
  const auto ranges = r.f32s();
  const auto intensities = r.f32s();
  EXPECT_TRUE(r.at_end());
  ASSERT_EQ(ranges.size(), 4u);
  // ROS angle = 180 - device angle; bin = ceil((angle + 180) / 120 deg): 10 deg -> 170 -> bin 3,
  // 100 -> 80 -> bin 3 (overwrites, out of range), 190 -> -10 -> bin 2, 280 -> -100 -> bin 1.
  EXPECT_TRUE(std::isnan(ranges[0])) << "no sample fell in it: no measurement, not a return at 0 m";
  EXPECT_EQ(ranges[1], std::numeric_limits<float>::infinity()) << "no return (REP-117)";
  EXPECT_FLOAT_EQ(ranges[2], 2.5005f);
  EXPECT_EQ(ranges[3], std::numeric_limits<float>::infinity()) << "30 m is beyond the G6's 25 m";
  EXPECT_TRUE(intensities.empty()) << "G1's flag is not a return strength, and no unit has one";
}

// The cloud's points in order, with the lap's no-return sample left out.
void expect_returns(const test::CloudSeen& cloud, const Lap& lap, bool flags) {
  const std::vector<LapPoint> returns = test::returns_of(lap.points);
  ASSERT_EQ(cloud.points.size(), returns.size());
  for (std::size_t i = 0; i < returns.size(); ++i) {
    EXPECT_FLOAT_EQ(cloud.points[i].range_m, returns[i].range_mm / 1000.0f);
    EXPECT_EQ(cloud.points[i].angle_deg, returns[i].angle_deg);
    EXPECT_EQ(cloud.points[i].flag, flags ? static_cast<std::uint8_t>(returns[i].flag) : 0);
  }
}

TEST(PointCloud2, KeepsEveryReturnExactlyWithG1sFlagAsItsOwnField) {
  const Lap lap = four_point_lap();
  std::vector<std::uint8_t> out;
  encode_point_cloud(lap, RosFrameOptions{}, true, 5, out);
  test::CdrReader r(out);
  EXPECT_EQ(r.i32(), 0);
  EXPECT_EQ(r.u32(), 5u);
  EXPECT_EQ(r.str(), "laser");
  EXPECT_EQ(r.u32(), 1u);
  EXPECT_EQ(r.u32(), 3u) << "the sample without a return is no point";
  const std::uint32_t fields = r.u32();
  ASSERT_EQ(fields, 6u);
  std::vector<std::string> names;
  for (std::uint32_t i = 0; i < fields; ++i) {
    names.push_back(r.str());
    EXPECT_EQ(r.u32(), i < 5 ? 4 * i : 20u);
    EXPECT_EQ(r.u8(), i < 5 ? 7 : 2);  // FLOAT32, then UINT8
    EXPECT_EQ(r.u32(), 1u);
  }
  EXPECT_EQ(names, (std::vector<std::string>{"x", "y", "z", "range", "angle", "interference_flag"}));
  EXPECT_EQ(r.u8(), 0);  // is_bigendian
  EXPECT_EQ(r.u32(), kPointStep);
  EXPECT_EQ(r.u32(), 3 * kPointStep);
  ASSERT_EQ(r.u32(), 3 * kPointStep);
  const std::uint8_t* data = r.take(3 * kPointStep);
  EXPECT_EQ(r.u8(), 1);  // is_dense: no point is invalid
  EXPECT_TRUE(r.at_end());
  const std::vector<LapPoint> returns = test::returns_of(lap.points);
  for (std::size_t i = 0; i < 3; ++i) {
    float v[5];
    std::memcpy(v, data + i * kPointStep, sizeof v);
    EXPECT_FLOAT_EQ(v[3], returns[i].range_mm / 1000.0f);
    EXPECT_EQ(v[4], returns[i].angle_deg);
    EXPECT_EQ(data[i * kPointStep + 20], static_cast<std::uint8_t>(returns[i].flag));
    const double a = ros_angle_rad(returns[i].angle_deg, RosFrameOptions{});
    EXPECT_NEAR(v[0], v[3] * std::cos(a), 1e-5);
    EXPECT_NEAR(v[1], v[3] * std::sin(a), 1e-5);
    EXPECT_GT(std::hypot(v[0], v[1]), 0.5f) << "no point at the origin";
  }
  expect_returns(test::point_cloud(out), lap, true);
}

TEST(PointCloud2, AUnitWithoutInterferenceFlagsHasNoFlagField) {
  const Lap lap = four_point_lap();
  std::vector<std::uint8_t> out;
  encode_point_cloud(lap, RosFrameOptions{}, false, 5, out);
  const test::CloudSeen cloud = test::point_cloud(out);
  EXPECT_EQ(cloud.fields, (std::vector<std::string>{"x", "y", "z", "range", "angle"}));
  EXPECT_EQ(cloud.point_step, kPointStepWithoutFlag);
  EXPECT_TRUE(cloud.is_dense);
  expect_returns(cloud, lap, false);
}

// A G6 stream of `laps` laps, split into records of 100 bytes that are 1 ms apart.
std::vector<std::uint8_t> g6_stream(int laps) {
  std::vector<std::uint8_t> out;
  std::uint16_t value = 4000;
  for (int lap = 0; lap <= laps; ++lap) {
    append_scan_packet({kCtLapStart, encode_raw_angle(0), encode_raw_angle(0), std::vector<std::uint16_t>{0}}, out);
    if (lap == laps) break;
    for (int i = 0; i < 12; ++i) {
      std::vector<std::uint16_t> samples(30);
      for (auto& s : samples) s = value = static_cast<std::uint16_t>(value * 31 + 7);
      append_scan_packet({0, encode_raw_angle(i * 30.0 + 0.2), encode_raw_angle(i * 30.0 + 29.8), samples}, out);
    }
  }
  return out;
}

TEST(McapRecordingExport, CarriesExactlyTheLapsTheDecoderGives) {
  const auto stream = g6_stream(30);
  std::vector<Lap> expected;
  ScanDecoder decoder(profile_for(Model::G6));
  // The same records at the same times as the export below, so the laps' receive times agree.
  for (std::size_t at = 0; at < stream.size(); at += 100)
    decoder.feed(std::span(stream).subspan(at, std::min<std::size_t>(100, stream.size() - at)),
                 static_cast<std::int64_t>(at / 100) * 1'000'000, [&](const Lap& lap) { expected.push_back(lap); });
  decoder.finish([&](const Lap& lap) { expected.push_back(lap); });
  ASSERT_GE(expected.size(), 29u);

  constexpr std::uint64_t kWallStart = 1'796'155'200'500'000'000;  // 2026-12-01T20:00:00.5Z
  McapMemorySink sink;
  McapRecordingExport exporter(sink, {});
  RecordingMetadata metadata;
  metadata.model = "G6";
  metadata.start_wall_time = "2026-12-01T20:00:00.5Z";
  exporter.metadata(metadata, 0);
  std::int64_t t = 0;
  for (std::size_t at = 0; at < stream.size(); at += 100, t += 1'000'000)
    exporter.record(RecordType::DeviceToHost,
                    std::span(stream).subspan(at, std::min<std::size_t>(100, stream.size() - at)), t);
  exporter.record(RecordType::HostToDevice, std::vector<std::uint8_t>{0xA5, 0x65}, t);
  ASSERT_TRUE(exporter.finish()) << exporter.error();

  const auto contents = test::read_mcap(sink.bytes());
  ASSERT_TRUE(contents.complete);
  std::map<std::string, std::uint16_t> ids;
  for (const auto& [id, channel] : contents.channels) {
    ids[channel.topic] = id;
    EXPECT_EQ(channel.encoding, "cdr");
    EXPECT_TRUE(channel.metadata.count("offered_qos_profiles"));
    EXPECT_EQ(contents.schemas.at(channel.schema_id).encoding, "ros2msg");
  }
  std::size_t scans = 0, clouds = 0, diagnostics = 0, link_bytes = 0;
  std::vector<std::uint8_t> device_bytes;
  for (const auto& m : contents.messages) {
    EXPECT_GE(m.log_time, 1'796'155'200'500'000'000ull);  // 2026-12-01T20:00:00.5Z
    if (m.channel_id == ids["/points"]) {
      const Lap& lap = expected.at(clouds++);
      const test::CloudSeen cloud = test::point_cloud(m.data);
      const std::vector<LapPoint> returns = test::returns_of(lap.points);
      ASSERT_LT(returns.size(), lap.points.size()) << "each lap's zero packet holds a sample without a return";
      ASSERT_EQ(cloud.points.size(), returns.size());
      for (std::size_t i = 0; i < returns.size(); ++i) {
        EXPECT_EQ(cloud.points[i].angle_deg, returns[i].angle_deg);
        EXPECT_FLOAT_EQ(cloud.points[i].range_m, returns[i].range_mm / 1000.0f);
      }
      EXPECT_EQ(cloud.stamp_ns, kWallStart + static_cast<std::uint64_t>(lap.first_rx_ns)) << "as /scan";
      EXPECT_EQ(cloud.fields.back(), "angle") << "a G6 flags no interference";
      EXPECT_EQ(m.log_time, kWallStart + static_cast<std::uint64_t>(lap.last_rx_ns));
    } else if (m.channel_id == ids["/scan"]) {
      const Lap& lap = expected.at(scans++);
      const test::ScanSeen scan = test::laser_scan(m.data);
      // Stamped at the first ray, logged at the closing byte; the first lap is timed too.
      EXPECT_EQ(scan.stamp_ns, kWallStart + static_cast<std::uint64_t>(lap.first_rx_ns));
      EXPECT_EQ(m.log_time, kWallStart + static_cast<std::uint64_t>(lap.last_rx_ns));
      const double duration_s = static_cast<double>(lap.last_rx_ns - lap.first_rx_ns) / 1e9;
      EXPECT_GT(duration_s, 0.0);
      EXPECT_FLOAT_EQ(scan.scan_time, static_cast<float>(duration_s));
      EXPECT_FLOAT_EQ(scan.time_increment, static_cast<float>(duration_s / static_cast<double>(lap.points.size())));
      EXPECT_TRUE(scan.intensities.empty());
      for (const float range : scan.ranges)
        if (std::isfinite(range)) {
          EXPECT_GE(range, scan.range_min) << "no bin claims a return at 0 m";
          EXPECT_LE(range, scan.range_max);
        }
    } else if (m.channel_id == ids["/diagnostics"]) {
      ++diagnostics;
    } else if (m.channel_id == ids["/ydscope/device_bytes"]) {
      test::CdrReader r(m.data);
      EXPECT_EQ(r.u32(), 0u);
      EXPECT_EQ(r.u32(), 0u);
      const std::uint32_t n = r.u32();
      const std::uint8_t* p = r.take(n);
      device_bytes.insert(device_bytes.end(), p, p + n);
      ++link_bytes;
    }
  }
  EXPECT_EQ(clouds, expected.size());
  EXPECT_EQ(scans, expected.size());
  EXPECT_EQ(device_bytes, stream);  // the raw channel gives the bytes back exactly
  EXPECT_GE(diagnostics, 1u);
  EXPECT_EQ(contents.metadata.back().at("model"), "G6");
}

TEST(Iso8601, ParsesTheRecordingsStartTime) {
  EXPECT_EQ(parse_iso8601_utc_ns("1970-01-01T00:00:01.25Z"), 1'250'000'000ull);
  EXPECT_EQ(parse_iso8601_utc_ns("2026-12-01T20:00:00Z"), 1'796'155'200'000'000'000ull);
  EXPECT_FALSE(parse_iso8601_utc_ns("2026-12-01 20:00:00"));
  EXPECT_FALSE(parse_iso8601_utc_ns("yesterday"));
}

}  // namespace
}  // namespace ydscope
