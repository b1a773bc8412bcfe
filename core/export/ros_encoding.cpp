#include "core/export/ros_encoding.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>

#include "core/export/cdr_writer.h"

namespace ydscope {
namespace {

constexpr double kPi = std::numbers::pi;

void put_header(CdrWriter& cdr, std::uint64_t stamp_ns, std::string_view frame_id) {
  cdr.i32(static_cast<std::int32_t>(stamp_ns / 1'000'000'000u));
  cdr.u32(static_cast<std::uint32_t>(stamp_ns % 1'000'000'000u));
  cdr.string(frame_id);
}

void put_f32(std::uint8_t* at, float v) { std::memcpy(at, &v, 4); }

}  // namespace

RangeLimits range_limits(Model model) {
  switch (model) {
    case Model::G1: return {0.1f, 16.0f};
    case Model::G6: return {0.1f, 25.0f};
    case Model::TG15: return {0.05f, 15.0f};
    case Model::TG30: return {0.05f, 30.0f};
    case Model::TG50: return {0.05f, 50.0f};
    case Model::X4: return {0.12f, 10.0f};  // the vendor SDK's model table
    case Model::X2: return {0.10f, 8.0f};
  }
  return {0.1f, 16.0f};
}

double ros_angle_rad(float device_angle_deg, const RosFrameOptions& frame) {
  double angle = static_cast<double>(device_angle_deg) * kPi / 180.0;
  if (frame.reversion) angle += kPi;
  if (frame.inverted) angle = 2 * kPi - angle;
  // The SDK's normalize_angle: into [0, 2pi), then above pi wraps to the negative side.
  angle = std::fmod(std::fmod(angle, 2 * kPi) + 2 * kPi, 2 * kPi);
  if (angle > kPi) angle -= 2 * kPi;
  return angle;
}

ScanTimes scan_times(const Lap& lap, std::int64_t rx_to_epoch_ns) {
  ScanTimes times;
  times.stamp_ns = static_cast<std::uint64_t>(std::max<std::int64_t>(0, lap.first_rx_ns + rx_to_epoch_ns));
  times.scan_time_s = static_cast<double>(std::max<std::int64_t>(0, lap.last_rx_ns - lap.first_rx_ns)) / 1e9;
  if (!lap.points.empty()) times.time_increment_s = times.scan_time_s / static_cast<double>(lap.points.size());
  return times;
}

float scan_range(float range_mm, RangeLimits limits) {
  constexpr float kInf = std::numeric_limits<float>::infinity();
  const float range_m = static_cast<float>(static_cast<double>(range_mm) / 1000.0);
  if (range_mm == 0.0f || range_m > limits.max_m) return kInf;
  if (range_m < limits.min_m) return -kInf;
  return range_m;
}

void encode_laser_scan(const Lap& lap, const RosFrameOptions& frame, RangeLimits limits, const ScanTimes& times,
                       std::vector<float>& scratch, std::vector<std::uint8_t>& out) {
  // The SDK: angle_increment = field of view / (points - 1), one bin per point, a point goes to
  // bin ceil((angle - angle_min) / increment); later points overwrite earlier ones in a bin.
  const std::size_t count = lap.points.size();
  const std::size_t bins = count < 2 ? 2 : count;
  const double increment = 2 * kPi / static_cast<double>(bins - 1);
  // A bin no sample falls in: the SDK leaves it 0, which reads as a return at the sensor; NaN
  // says "no measurement" (REP-117).
  scratch.assign(bins, std::numeric_limits<float>::quiet_NaN());
  float* ranges = scratch.data();
  for (const LapPoint& p : lap.points) {
    const double index = std::ceil((ros_angle_rad(p.angle_deg, frame) + kPi) / increment);
    if (!(index >= 0 && index < static_cast<double>(bins))) continue;
    ranges[static_cast<std::size_t>(index)] = scan_range(p.range_mm, limits);
  }
  CdrWriter cdr(out);
  put_header(cdr, times.stamp_ns, frame.frame_id);
  cdr.f32(static_cast<float>(-kPi));
  cdr.f32(static_cast<float>(kPi));
  cdr.f32(static_cast<float>(increment));
  cdr.f32(static_cast<float>(times.time_increment_s));
  cdr.f32(static_cast<float>(times.scan_time_s));
  cdr.f32(limits.min_m);
  cdr.f32(limits.max_m);
  cdr.f32_sequence({ranges, bins});
  cdr.f32_sequence({});  // intensities: none (see the header)
}

void encode_point_cloud(const Lap& lap, const RosFrameOptions& frame, bool interference_flag, std::uint64_t stamp_ns,
                        std::vector<std::uint8_t>& out) {
  struct Field {
    std::string_view name;
    std::uint32_t offset;
    std::uint8_t datatype;  // sensor_msgs/PointField: 2 UINT8, 7 FLOAT32
  };
  static constexpr Field kFields[] = {{"x", 0, 7},      {"y", 4, 7},      {"z", 8, 7},
                                      {"range", 12, 7}, {"angle", 16, 7}, {"interference_flag", 20, 2}};
  const std::size_t fields = interference_flag ? std::size(kFields) : std::size(kFields) - 1;
  const std::uint32_t step = interference_flag ? kPointStep : kPointStepWithoutFlag;
  const auto width = static_cast<std::uint32_t>(
      std::count_if(lap.points.begin(), lap.points.end(), [](const LapPoint& p) { return p.range_mm != 0.0f; }));
  CdrWriter cdr(out);
  put_header(cdr, stamp_ns, frame.frame_id);
  cdr.u32(1);
  cdr.u32(width);
  cdr.u32(static_cast<std::uint32_t>(fields));
  for (const Field& f : std::span(kFields).first(fields)) {
    cdr.string(f.name);
    cdr.u32(f.offset);
    cdr.u8(f.datatype);
    cdr.u32(1);
  }
  cdr.boolean(false);
  cdr.u32(step);
  cdr.u32(step * width);
  cdr.u32(step * width);
  const std::size_t data = cdr.reserve_bytes(std::size_t{step} * width);
  std::uint8_t* p = cdr.at(data);
  for (const LapPoint& point : lap.points) {
    if (point.range_mm == 0.0f) continue;  // no return: no point here; /scan says it as +Inf
    const double angle = ros_angle_rad(point.angle_deg, frame);
    const double range_m = static_cast<double>(point.range_mm) / 1000.0;
    put_f32(p + 0, static_cast<float>(range_m * std::cos(angle)));
    put_f32(p + 4, static_cast<float>(range_m * std::sin(angle)));
    put_f32(p + 8, 0.0f);
    put_f32(p + 12, static_cast<float>(range_m));
    put_f32(p + 16, point.angle_deg);
    if (interference_flag) {
      p[20] = static_cast<std::uint8_t>(point.flag);
      p[21] = p[22] = p[23] = 0;
    }
    p += step;
  }
  cdr.boolean(true);  // every point is a return: no NaN, none at the origin
}

void encode_diagnostics(const DiagnosticReport& report, std::string_view frame_id, std::uint64_t stamp_ns,
                        std::vector<std::uint8_t>& out) {
  encode_diagnostics(std::span(&report, 1), frame_id, stamp_ns, out);
}

void encode_diagnostics(std::span<const DiagnosticReport> reports, std::string_view frame_id, std::uint64_t stamp_ns,
                        std::vector<std::uint8_t>& out) {
  CdrWriter cdr(out);
  put_header(cdr, stamp_ns, frame_id);
  cdr.u32(static_cast<std::uint32_t>(reports.size()));
  for (const DiagnosticReport& report : reports) {
    cdr.u8(report.level);
    cdr.string(report.name);
    cdr.string(report.message);
    cdr.string(report.hardware_id);
    cdr.u32(static_cast<std::uint32_t>(report.values.size()));
    for (const auto& [key, value] : report.values) {
      cdr.string(key);
      cdr.string(value);
    }
  }
}

void encode_link_bytes(std::span<const std::uint8_t> bytes, std::vector<std::uint8_t>& out) {
  CdrWriter cdr(out);
  cdr.u32(0);  // layout.dim: none
  cdr.u32(0);  // layout.data_offset
  cdr.u8_sequence(bytes);
}

}  // namespace ydscope
