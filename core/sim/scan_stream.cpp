#include "core/sim/scan_stream.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "core/protocol/angle_correction.h"
#include "core/protocol/g1_ct.h"
#include "core/protocol/scan_packet.h"
#include "core/sim/faults.h"
#include "core/sim/scene.h"

namespace ydscope {

namespace {
// Where the correction sits for distant targets; the first guess of the fixed-point iteration.
const double kFarCorrectionDeg = angle_correction_deg(1e9);
constexpr int kFixedPointSteps = 4;
constexpr int kBisectionSteps = 14;
constexpr double kConvergedDeg = 0.01;
}  // namespace

ScanStream::ScanStream(const ModelProfile& profile, const UnitConventions& conventions, double distance_scale,
                       const Scene& scene, std::int64_t scene_epoch_ns, std::uint8_t version_major,
                       std::uint8_t version_minor, std::uint64_t seed)
    : profile_(&profile),
      conventions_(&conventions),
      distance_scale_(distance_scale),
      max_range_mm_(static_cast<double>(0xFFFFu >> profile.flag_bits) * distance_scale),
      scene_(&scene),
      scene_epoch_ns_(scene_epoch_ns),
      version_major_(version_major),
      version_minor_(version_minor),
      debug_salt_(static_cast<std::uint8_t>(seed * 37u + 11u)) {
  samples_.reserve(kSamplesPerPacket);
}

void ScanStream::start(std::int64_t t_ns, std::uint32_t scan_centihz, std::uint16_t ranging_khz) {
  scan_hz_ = scan_centihz / 100.0;
  ranging_hz_ = conventions_->samples_per_s(*profile_, ranging_khz).value_or(ranging_khz * 1000.0);
  scan_start_ns_ = t_ns;
  lap_start_ns_ = t_ns;
  begin_lap_at_motor_rate();
  lap_ = 0;
  next_sample_ = 0;
  packet_index_ = 0;
  crc_ = 0;
  first_zero_ = true;
}

void ScanStream::begin_lap_at_motor_rate() {
  constexpr double kSlowestMotorHz = 0.5;  // a wild offset still turns, so laps still end
  const double phase = 2.0 * std::numbers::pi * static_cast<double>(lap_start_ns_ - scan_start_ns_) /
                       static_cast<double>(kScanWobblePeriodNs);
  motor_hz_ = std::max(kSlowestMotorHz, scan_hz_ + motor_offset_hz_ + motor_wobble_hz_ * std::sin(phase));
  samples_per_lap_ = std::max<std::uint32_t>(2, static_cast<std::uint32_t>(std::lround(ranging_hz_ / motor_hz_)));
  lap_period_ns_ = 1e9 / motor_hz_;
}

bool ScanStream::blocked(double direction_deg) const {
  return blocked_width_deg_ > 0.0 && normalize_degrees(direction_deg - blocked_from_deg_) < blocked_width_deg_;
}

std::int64_t ScanStream::sample_time_ns(std::uint32_t sample) const {
  return lap_start_ns_ + static_cast<std::int64_t>(std::llround(lap_period_ns_ * sample / samples_per_lap_));
}

std::int64_t ScanStream::next_ready_ns() const {
  if (next_sample_ == 0) return lap_start_ns_;
  const std::uint32_t last = std::min<std::uint32_t>(next_sample_ + kSamplesPerPacket - 1, samples_per_lap_ - 1);
  return sample_time_ns(last);
}

std::uint8_t ScanStream::packet_ct(std::uint32_t index) const {
  if (!profile_->ct_carries_info) return index == 0 ? zero_packet_ct() : 0;
  switch (index) {
    case kG1CtScanHzIndex: return g1_zero_packet_ct(motor_hz_);
    case kG1CtVersionIndex: return g1_version_ct(version_major_, version_minor_);
    case kG1CtHealthIndex: return g1_health_ct(health_);
    default:  // production debugging information: any value with the lap-start bit clear
      return static_cast<std::uint8_t>(((index * 29u + debug_salt_) & 0x7Fu) << 1);
  }
}

std::uint8_t ScanStream::zero_packet_ct() const {
  const ZeroPacketScanRate& rate = conventions_->zero_packet_scan_rate;
  if (!rate.present) return kCtLapStart;
  // CT[7:1] in 0.1 Hz from the offset, as real G6 and TG units send it.
  const long tenths = std::clamp(std::lround((motor_hz_ - rate.offset_hz) * 10.0), 1L, 127L);
  return static_cast<std::uint8_t>(tenths << 1 | kCtLapStart);
}

StreamPacket ScanStream::next(std::vector<std::uint8_t>& bytes, std::vector<LapPoint>* truth,
                              std::vector<float>* scene_angles) {
  const bool zero = next_sample_ == 0;
  const std::uint32_t first = next_sample_;
  const std::uint32_t last = zero ? 0 : std::min<std::uint32_t>(first + kSamplesPerPacket - 1, samples_per_lap_ - 1);
  const auto lsn = static_cast<std::uint8_t>(last - first + 1);

  StreamPacket packet;
  packet.ready_ns = sample_time_ns(last);
  packet.index = packet_index_;
  packet.ct = packet_ct(packet_index_);
  packet.lsn = lsn;

  if (zero) {
    if (!first_zero_) ++lap_;
    // G1's LastCRC; TG's byte of no documented meaning carries the same CRC8 here.
    if (conventions_->byte_before_zero != ByteBeforeZero::None) bytes.push_back(first_zero_ ? 0 : crc_);
    first_zero_ = false;
    crc_ = 0;
  }
  packet.lap = lap_;
  crc_ = ct_crc8_update(crc_, packet.ct);

  // First-level angles: evenly spaced raw angles, quantised to the protocol's 1/64 degree at the
  // ends; the host interpolates between the quantised ends, so this does too.
  const double step = 360.0 / samples_per_lap_;
  const std::uint16_t fsa = encode_raw_angle(first * step);
  const std::uint16_t lsa = encode_raw_angle(last * step);
  const double fsa_deg = raw_angle_degrees(fsa);
  double diff = raw_angle_degrees(lsa) - fsa_deg;
  if (diff < 0) diff += 360.0;

  samples_.clear();
  if (truth) truth->clear();
  if (scene_angles) scene_angles->clear();
  const bool flags = profile_->flag_bits > 0;
  for (std::uint32_t i = 0; i < lsn; ++i) {
    const double level1 = lsn > 1 ? fsa_deg + diff * i / (lsn - 1) : fsa_deg;
    const std::int64_t t = sample_time_ns(first + i) - scene_epoch_ns_;
    std::uint16_t word = 0;
    PointFlag flag = PointFlag::None;
    double range = 0.0;
    double sampled_at = 0.0;
    // The direction the host will compute for a range r is level1 + correction(r); find theta with
    // theta == level1 + correction(range at theta). Returns theta - that (0 at a solution).
    // A blocked direction is decided by where the window points (the first-level angle): the
    // obstruction sits on the unit, not out in the scene.
    const bool obstructed = blocked(level1);
    blocked_samples_ += obstructed;
    const auto residual = [&](double theta) {
      sampled_at = normalize_degrees(theta);
      const SceneReturn ret = obstructed ? SceneReturn{} : scene_->sample(sampled_at, t);
      range = ret.range_mm > 0.0 && ret.range_mm <= max_range_mm_ ? ret.range_mm : 0.0;
      flag = flags && range > 0.0 ? ret.flag : PointFlag::None;
      word = encode_sample(range, flag, profile_->flag_bits, distance_scale_);
      range = static_cast<double>(word >> profile_->flag_bits) * distance_scale_;
      return theta - (level1 + (conventions_->angle_correction ? angle_correction_deg(range) : 0.0));
    };
    // Fixed-point steps settle almost every sample; steep surfaces (where the range changes fast
    // with the direction) fall back to bisection over the correction's span.
    // Start from the previous sample's correction: neighbours usually see the same surface.
    double theta = level1 + last_correction_deg_;
    bool converged = false;
    for (int k = 0; k < kFixedPointSteps && !converged; ++k) {
      const double r = residual(theta);
      converged = range == 0.0 || std::fabs(r) < kConvergedDeg;
      theta -= r;
    }
    if (!converged) {
      double lo = level1 + kFarCorrectionDeg - 0.2;  // residual < 0: no correction is below -8 degrees
      double hi = level1 + 1.0;                      // residual > 0 for any range beyond ~140 mm
      if (residual(lo) < 0.0 && residual(hi) > 0.0) {
        for (int k = 0; k < kBisectionSteps; ++k) {
          const double mid = 0.5 * (lo + hi);
          (residual(mid) < 0.0 ? lo : hi) = mid;
        }
        const double r = residual(hi);
        converged = range > 0.0 && std::fabs(r) < kConvergedDeg;
        theta = hi - r;
      }
    }
    if (!converged) {
      // No solution: the direction straddles an edge (near and far surfaces trade places as the
      // correction moves it). Report no return, as real triangulation lidars drop mixed pixels.
      word = 0;
      range = 0.0;
      flag = PointFlag::None;
      theta = level1;
    } else if (range == 0.0) {
      theta = level1;  // no return: the host applies no correction
    } else {
      last_correction_deg_ = theta - level1;
    }
    samples_.push_back(word);
    if (truth) truth->push_back({static_cast<float>(normalize_degrees(theta)), static_cast<float>(range), flag});
    if (scene_angles) scene_angles->push_back(static_cast<float>(sampled_at));
  }

  packet.packet_offset = bytes.size();
  append_scan_packet({packet.ct, fsa, lsa, samples_}, bytes);

  ++packet_index_;
  next_sample_ = last + 1;
  if (next_sample_ >= samples_per_lap_) {
    next_sample_ = 0;
    packet_index_ = 0;
    lap_start_ns_ = sample_time_ns(samples_per_lap_);
    begin_lap_at_motor_rate();
  }
  return packet;
}

}  // namespace ydscope
