#pragma once
// Host compatibility: what the virtual lidar answers beyond its manual so that a particular host
// program starts against it as against a real unit. The default, HostCompat::Manual, is the
// manuals' behaviour and nothing more.
//
// HostCompat::YdlidarSdk follows what YDLIDAR's own SDK (YDLidar-SDK 1.2.19, which its ROS 2
// driver links) sends at start-up and what its source checks in each reply (facts read from its
// source, see docs/virtual-lidar.md, "As a vendor-SDK test double"):
//   A5 00  sent before every A5 65 ("force stop"); it waits for nothing, so nothing is answered.
//   A5 92  its only health request, on every model; G6/TG answer it as their A5 91 (type 06,
//          status 0/1/2 + u16 error code); without it the SDK waits 1 s and logs an error.
//   A5 93  zero-offset angle on G1 and TG: type 04, an i32 in quarter degrees that the SDK adds
//          to every angle; 0 here. Without it the SDK waits 2 s, twice.
//   A5 60  after the scan reply header the SDK waits up to 1 s for a device-info frame (type 04,
//          20 bytes) that units with a separate module board send; the virtual unit sends it.
//   TG     the SDK subtracts 0.4 Hz from every scan-frequency answer (its comment: TG units report
//          0.4 Hz high), so in this mode a TG reports its motor's rate + 0.4 Hz.
// The table of extra commands lives here; VirtualLidar consults it only for codes its manual does
// not answer, so the manual's replies are never changed.
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "core/protocol/model_profile.h"

namespace ydscope {

enum class HostCompat : std::uint8_t { Manual, YdlidarSdk };

// "manual", "ydlidar-sdk".
std::string_view host_compat_name(HostCompat compat);
std::optional<HostCompat> host_compat_from_name(std::string_view name);
// "manual, ydlidar-sdk" for messages and --help.
std::string_view host_compat_names();

// How an extra command is answered.
enum class CompatAnswer : std::uint8_t {
  Silent,           // accepted, never answered (also while scanning)
  Health,           // the model's status-code health reply under another code
  ZeroOffsetAngle,  // i32 little-endian, quarter degrees
};

struct CompatCommand {
  std::uint8_t code;
  CompatAnswer answer;
  std::uint8_t type_code;        // reply type the host checks (unused when Silent)
  std::uint32_t payload_length;  // exact payload length (0 when Silent)
  std::string_view why;          // what the host does with it, for logs and docs
};

// Every extra command of a mode (empty for Manual).
std::span<const CompatCommand> compat_commands(HostCompat compat);
// The entry for `code`, when the mode answers it and the model's manual does not.
const CompatCommand* find_compat_command(HostCompat compat, const ModelProfile& profile, std::uint8_t code);

// The reply bytes (header + payload) of a non-silent entry; payload must have its exact length.
std::vector<std::uint8_t> encode_compat_reply(const CompatCommand& command, std::span<const std::uint8_t> payload);
// The zero-offset angle payload: degrees to the i32 quarter degrees the SDK reads.
std::vector<std::uint8_t> encode_zero_offset_angle(double degrees);

// True when the mode sends a device-info frame right after the scan reply header.
bool sends_device_info_after_scan_header(HostCompat compat);
// Hundredths of a hertz added to every scan-frequency answer (TG in YdlidarSdk: 40).
std::uint32_t reported_scan_hz_offset_centihz(HostCompat compat, const ModelProfile& profile);

}  // namespace ydscope
