#pragma once
// LapAssembler: valid scan packets -> complete laps, with the manuals' formulas.
//
// - Angles: first level (FSA>>1)/64 and (LSA>>1)/64, interpolated over LSN-1 steps along the
//   clockwise difference (LSA < FSA crosses 360); second level adds the distance-only correction
//   (angle_correction.h); results are normalised to [0, 360).
// - Ranges: (S >> flag_bits) * distance_scale mm; G1's flag is S & 3. The scale, whether the
//   correction applies and where a scan rate sits come from the unit's conventions.
// - G1: CT information by packet index (scan frequency, version, health) and the CRC8 verdict from
//   the LastCRC of the zero packet that closes the lap. G6/TG read as the field reads them: the
//   zero packet's CT[7:1] is the scan rate.
// - A lap runs from a zero packet (inclusive) to the next (exclusive). Packets before the first
//   zero packet form a partial lap that is discarded. A lap is published when the next zero packet
//   arrives; it stays readable through lap() until the following add_packet call.
// - A lap is cut short, and the packets up to the next zero packet dropped, when its angle comes
//   round past its start again (a lost zero packet) or when the stream stalls and resumes
//   somewhere that does not follow on (Lap::end says which): no lap holds more than one turn.
// Two preallocated laps are swapped, so steady state allocates nothing.
#include <cstdint>
#include <optional>

#include "core/protocol/angle_correction.h"
#include "core/protocol/lap.h"
#include "core/protocol/model_profile.h"
#include "core/protocol/packet_decoder.h"
#include "core/protocol/unit_conventions.h"

namespace ydscope {

struct LapCounters {
  std::uint64_t laps = 0;               // complete laps published
  std::uint64_t discarded_packets = 0;  // packets outside a lap: before the first zero packet, after a cut
  std::uint64_t crc_ok = 0;             // G1 laps whose CRC8 matched the LastCRC
  std::uint64_t crc_mismatches = 0;     // G1 laps whose CRC8 did not match
  std::uint64_t crc_unknown = 0;        // G1 laps closed without a LastCRC byte
  std::uint64_t overflow_points = 0;    // points dropped because a lap exceeded Lap::kMaxPoints
  std::uint64_t cut_laps = 0;           // laps closed without their zero packet (Lap::end)
};

class LapAssembler {
 public:
  // distance_scale: mm per raw unit after the flag bits (the conventions' unless overridden).
  LapAssembler(const ModelProfile& profile, const UnitConventions& conventions, double distance_scale);

  // Returns true when this packet (a zero packet) closed a complete lap, now in lap().
  bool add_packet(const PacketView& packet);
  // A packet dropped for a bad checksum: counted in the lap being built.
  void add_checksum_error();

  const Lap& lap() const { return done_; }
  const LapCounters& counters() const { return counters_; }
  double distance_scale() const { return distance_scale_; }
  void reset();

 private:
  void start_lap(const PacketView& zero);
  void add_points(const PacketView& packet);
  void take_ct_info(const PacketView& packet);
  void take_zero_packet_scan_rate(std::uint8_t ct);
  // Why the lap being built must end before this (not zero) packet, if it must.
  std::optional<LapEnd> cut_before(const PacketView& packet) const;
  void follow(const PacketView& packet);  // the angle and time this packet reached
  void publish();                         // the lap being built becomes lap()

  const ModelProfile* profile_;
  const UnitConventions* conventions_;
  bool lap_crc8_;  // G1's LastCRC is checked
  double distance_scale_;
  AngleCorrectionTable corrections_;
  Lap building_;
  Lap done_;
  bool in_lap_ = false;             // a zero packet has been seen
  std::uint32_t packet_index_ = 0;  // index of the next packet within the lap being built
  std::uint8_t crc_ = 0;            // G1 CRC8 over the CT bytes of the lap being built
  double turned_deg_ = 0;           // first-level angle from the lap's zero packet to the last packet
  double last_fsa_deg_ = 0;         // the last packet's first-level start and end angles
  double last_lsa_deg_ = 0;
  std::uint64_t next_index_ = 0;
  LapCounters counters_;
};

}  // namespace ydscope
