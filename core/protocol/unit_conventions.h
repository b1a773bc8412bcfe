#pragma once
// How a unit's scan bytes are to be read: the conventions that differ between the manuals and the
// units in the field, in one table chosen by model, firmware and reading (docs/conventions.md
// gives every row's source).
//
// - Reading::Field is what real units emit, as the vendor SDK (which their owners run) reads them:
//   G6 is an "octave" unit (S/2 mm, twice the manual's sample rates, scan rate in the zero packet's
//   CT), a TG is a time-of-flight unit (no triangulation correction, S mm on firmware above 1.2,
//   S/2 before it, CT scan rate + 3 Hz on newer firmware, one byte before each zero packet).
// - Reading::Manual is the manuals' literal text, kept so the decoder can still be held to them.
// G1's units follow its manual, so its two readings are the same row.
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

#include "core/protocol/lap.h"
#include "core/protocol/model_profile.h"

namespace ydscope {

enum class Reading : std::uint8_t { Field, Manual };

// What lies between a lap's last packet and the next zero packet.
enum class ByteBeforeZero : std::uint8_t {
  None,         // nothing (the G6 and TG manuals)
  LapCrc8,      // G1's LastCRC: a CRC8 of the lap's CT bytes, checked
  Unexplained,  // one byte real TG units send, of no documented meaning: taken, not counted as noise
};

// Where a scan rate in the CT byte is, besides G1's channel by packet index (g1_ct.h).
struct ZeroPacketScanRate {
  bool present = false;    // CT[7:1] of the zero packet is the scan rate in 0.1 Hz (0: not sent)
  double offset_hz = 0.0;  // added to it (newer TG firmware counts from 3 Hz)
};

struct UnitConventions {
  Reading reading;
  std::string_view id;     // stable, for files and scripts: "g6-field", "tg-field-fw1.2", "manual"
  std::string_view label;  // for people: "field (vendor SDK): S/2 mm, 18 kHz at code 2"
  double distance_scale;   // mm per count after the flag bits
  bool angle_correction;   // the manuals' triangulation correction, on the range in mm
  // Samples per second a host receives, in thousands, by the A5 D1 code (parallel to the
  // profile's ranging_khz, which names the codes).
  std::span<const std::uint16_t> samples_khz;
  ZeroPacketScanRate zero_packet_scan_rate;
  ByteBeforeZero byte_before_zero;

  // Samples per second at a ranging code's name in kHz (as A5 D1 reads it back), if the model has it.
  std::optional<double> samples_per_s(const ModelProfile& profile, std::uint16_t ranging_khz) const;
  bool operator==(const UnitConventions& other) const { return id == other.id; }
};

// The row for a unit. `firmware` is in the vendor SDK's byte order (firmware_as_sdk_reads); when
// unknown, a TG is taken to run current firmware (units sold since 2021 do).
const UnitConventions& conventions_for(const ModelProfile& profile, std::optional<FirmwareVersion> firmware,
                                       Reading reading);
// A row by its id, for recordings; null when the id is unknown.
const UnitConventions* find_conventions(std::string_view id);
// Whether a row belongs to the profile's model family (a recording could pair them wrongly).
bool conventions_fit(const UnitConventions& conventions, const ModelProfile& profile);

// The A5 90 reply's two firmware bytes as the vendor SDK reads them: a little-endian u16 whose
// high byte is the major version. The manuals say the opposite (first byte major); the SDK's order
// is the one its firmware rules (TG "above 1.2") are written in, so conventions use it.
constexpr FirmwareVersion firmware_as_sdk_reads(std::uint8_t first_byte, std::uint8_t second_byte) {
  return FirmwareVersion{second_byte, first_byte};
}

std::string_view reading_name(Reading reading);  // "field", "manual"
std::optional<Reading> parse_reading(std::string_view text);
inline constexpr std::string_view kReadingNames = "field, manual";

}  // namespace ydscope
