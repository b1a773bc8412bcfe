#pragma once
// ScanStream: the scan packets of one scan, in order, each with the time its last sample was
// measured. Laps hold N = round(ranging Hz / scan Hz) samples evenly spaced over 360 degrees; the
// zero packet carries sample 0 alone, then packets of up to kSamplesPerPacket samples.
//
// Angles: the host computes first-level angles by interpolating FSA..LSA, then adds the manuals'
// distance-dependent correction. Each sample's range is therefore taken from the scene at the
// direction the host will compute for it: a fixed point of theta = first_level + correction(range
// (theta)), reached in a few iterations. The truth reported is exactly what a correct decoder
// computes from the bytes (up to float rounding).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "core/protocol/lap.h"
#include "core/protocol/model_profile.h"
#include "core/protocol/unit_conventions.h"

namespace ydscope {

class Scene;

struct StreamPacket {
  std::int64_t ready_ns = 0;
  std::uint64_t lap = 0;
  std::uint32_t index = 0;  // within the lap; 0 = zero packet
  std::uint8_t ct = 0;
  std::size_t packet_offset = 0;  // where AA 55 starts in the bytes (G1 zero packet: after LastCRC)
  std::uint8_t lsn = 0;
};

class ScanStream {
 public:
  static constexpr std::size_t kSamplesPerPacket = 40;

  // scene_epoch_ns: the device time the scene's clock counts from.
  // conventions: how a real unit of this model and firmware writes its stream (the scale may be
  // another: distance_scale).
  ScanStream(const ModelProfile& profile, const UnitConventions& conventions, double distance_scale, const Scene& scene,
             std::int64_t scene_epoch_ns, std::uint8_t version_major, std::uint8_t version_minor, std::uint64_t seed);

  // ranging_khz names the ranging code (A5 D1); the conventions say how many samples it gives.
  void start(std::int64_t t_ns, std::uint32_t scan_centihz, std::uint16_t ranging_khz);
  void set_health(std::uint8_t bits) { health_ = bits; }
  // The motor's error against the set rate (FaultConfig::scan_hz_offset / scan_hz_wobble); takes
  // effect from the next lap.
  void set_motor_error(double offset_hz, double wobble_hz) {
    motor_offset_hz_ = offset_hz;
    motor_wobble_hz_ = wobble_hz;
  }
  // Directions from from_deg clockwise over width_deg give no return (FaultConfig's blocked
  // sector); width 0 clears it.
  void set_blocked_sector(double from_deg, double width_deg) {
    blocked_from_deg_ = from_deg;
    blocked_width_deg_ = width_deg;
  }
  std::int64_t next_ready_ns() const;
  // Appends the next packet's bytes to `bytes`. When truth is not null, fills it (cleared first)
  // with what the host decodes, and scene_angles with the directions the scene was sampled at.
  StreamPacket next(std::vector<std::uint8_t>& bytes, std::vector<LapPoint>* truth,
                    std::vector<float>* scene_angles = nullptr);
  std::uint32_t samples_per_lap() const { return samples_per_lap_; }
  // Samples the blocked sector has emptied so far (FaultCounters::blocked_samples).
  std::uint64_t blocked_samples() const { return blocked_samples_; }

 private:
  std::int64_t sample_time_ns(std::uint32_t sample) const;
  std::uint8_t packet_ct(std::uint32_t index) const;
  std::uint8_t zero_packet_ct() const;
  // The motor's rate for the lap starting at lap_start_ns_: sets its period and sample count.
  void begin_lap_at_motor_rate();
  bool blocked(double direction_deg) const;

  const ModelProfile* profile_;
  const UnitConventions* conventions_;
  double distance_scale_;
  double max_range_mm_;
  const Scene* scene_;
  std::int64_t scene_epoch_ns_;
  std::uint8_t version_major_;
  std::uint8_t version_minor_;
  std::uint8_t debug_salt_;
  std::uint8_t health_ = 0;

  double scan_hz_ = 10.0;   // set rate
  double motor_hz_ = 10.0;  // actual rate of the current lap
  double motor_offset_hz_ = 0.0;
  double motor_wobble_hz_ = 0.0;
  double blocked_from_deg_ = 0.0;
  double blocked_width_deg_ = 0.0;
  std::uint64_t blocked_samples_ = 0;
  double ranging_hz_ = 9000.0;
  std::int64_t scan_start_ns_ = 0;
  std::uint32_t samples_per_lap_ = 1;
  std::int64_t lap_start_ns_ = 0;
  double lap_period_ns_ = 1e8;
  std::uint64_t lap_ = 0;
  std::uint32_t next_sample_ = 0;  // 0 = the next packet is a zero packet
  std::uint32_t packet_index_ = 0;
  std::uint8_t crc_ = 0;  // G1 CRC8 over this lap's CT bytes so far
  bool first_zero_ = true;
  double last_correction_deg_ = -8.0;  // first guess of the next sample's angle correction
  std::vector<std::uint16_t> samples_;
};

}  // namespace ydscope
