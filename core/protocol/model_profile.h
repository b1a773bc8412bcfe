#pragma once
// What differs between the G1, G6 and TG-series lidars, in one table: codes, baud, distance
// formula, flags, which commands exist, ranging tables and scan-frequency limits.
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

#include "core/protocol/commands.h"

namespace ydscope {

// G1, G6 and TG are the lidars ydscope drives; X4 and X2 share their packet layout and are decoded
// from their bytes (decode_only_profiles): they are not offered where a lidar is driven.
enum class Model : std::uint8_t { G1, G6, TG15, TG30, TG50, X4, X2 };

// The distance scales (mm per raw count) any source may ask for: --distance-scale, a
// recording's metadata, the app. Wide enough for every firmware seen; anything else (0, negative,
// NaN, 1e300) would turn ranges into nonsense or invalid JSON.
inline constexpr double kMinDistanceScale = 1e-6;
inline constexpr double kMaxDistanceScale = 1e6;
// False for NaN and infinities too.
constexpr bool distance_scale_in_range(double mm_per_count) {
  return mm_per_count >= kMinDistanceScale && mm_per_count <= kMaxDistanceScale;
}

struct ModelProfile {
  Model model;
  std::string_view name;    // "G1", "G6", "TG15", ...
  std::uint8_t model_code;  // device-info model byte seen in the field
  std::uint32_t default_baud;
  // Range in mm = (S >> flag_bits) * a scale that depends on the unit's firmware and on how it
  // is read (unit_conventions.h). G1 keeps its interference flag in S & 3.
  unsigned flag_bits;
  bool ct_carries_info;       // G1: CT[7:1] holds scan frequency, version, health by packet index
  bool last_crc_before_zero;  // G1: one CRC8 byte precedes every zero packet
  Command health_command;     // the manual's health command (the other one is the fallback)
  Command restart_command;
  std::span<const std::uint16_t> ranging_khz;  // reply byte -> kHz
  std::uint16_t default_ranging_khz;
  bool ranging_settable;  // A5 D0 cycles through the table
  double min_scan_hz;
  double max_scan_hz;
  double default_scan_hz;
  std::span<const Command> commands;  // every command the model's manual lists

  bool supports(Command command) const;
  // Index of kHz in the ranging table, if the model has that value.
  std::optional<std::uint8_t> ranging_index(std::uint16_t khz) const;
};

// The lidars ydscope drives (G1, G6, TG15, TG30, TG50).
std::span<const ModelProfile> all_profiles();
// Units of the same packet family whose bytes ydscope decodes but does not drive (X4, X2).
std::span<const ModelProfile> decode_only_profiles();
// A driven or decode-only model by name, for reading bytes (decode).
const ModelProfile* find_decodable_profile(std::string_view name);
const ModelProfile& profile_for(Model model);
// Case-insensitive name lookup ("g1", "TG30").
const ModelProfile* find_profile(std::string_view name);
const ModelProfile* find_profile_by_code(std::uint8_t model_code);
// "G1, G6, TG15, TG30, TG50" for messages and --help.
std::string_view model_names();

}  // namespace ydscope
