#include "core/sim/host_compat.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "core/protocol/byte_access.h"
#include "core/protocol/reply.h"

namespace ydscope {

namespace {

constexpr std::uint8_t kTypeAnswer = 0x04;  // what YDLidar-SDK calls LIDAR_ANS_TYPE_DEVINFO
constexpr std::uint8_t kTypeHealth = 0x06;
constexpr double kQuarterDegrees = 4.0;  // the SDK's zero-offset angle scale for G1 and TG

// YDLidar-SDK 1.2.19, YDlidarDriver and CYdLidar start-up (see host_compat.h).
constexpr std::array kYdlidarSdkCommands{
    CompatCommand{0x00, CompatAnswer::Silent, 0, 0, "force stop, sent before every A5 65"},
    CompatCommand{0x92, CompatAnswer::Health, kTypeHealth, kHealthSize, "health (the SDK's only health request)"},
    CompatCommand{0x93, CompatAnswer::ZeroOffsetAngle, kTypeAnswer, 4, "zero-offset angle, added to every angle"},
};

}  // namespace

std::string_view host_compat_name(HostCompat compat) {
  switch (compat) {
    case HostCompat::Manual: return "manual";
    case HostCompat::YdlidarSdk: return "ydlidar-sdk";
  }
  return "manual";
}

std::optional<HostCompat> host_compat_from_name(std::string_view name) {
  for (const HostCompat compat : {HostCompat::Manual, HostCompat::YdlidarSdk})
    if (host_compat_name(compat) == name) return compat;
  return std::nullopt;
}

std::string_view host_compat_names() { return "manual, ydlidar-sdk"; }

std::span<const CompatCommand> compat_commands(HostCompat compat) {
  if (compat == HostCompat::YdlidarSdk) return kYdlidarSdkCommands;
  return {};
}

const CompatCommand* find_compat_command(HostCompat compat, const ModelProfile& profile, std::uint8_t code) {
  const std::optional<Command> manual = command_from_code(code);
  if (manual && profile.supports(*manual)) return nullptr;  // the manual's answer stands
  for (const CompatCommand& entry : compat_commands(compat))
    if (entry.code == code) return &entry;
  return nullptr;
}

std::vector<std::uint8_t> encode_compat_reply(const CompatCommand& command, std::span<const std::uint8_t> payload) {
  if (command.answer == CompatAnswer::Silent || payload.size() != command.payload_length)
    throw std::logic_error("encode_compat_reply: a silent entry or a payload of the wrong length");
  const auto header = encode_reply_header({command.payload_length, ReplyMode::Single, command.type_code});
  std::vector<std::uint8_t> out(header.size() + payload.size());
  std::copy(header.begin(), header.end(), out.begin());
  std::copy(payload.begin(), payload.end(), out.begin() + static_cast<std::ptrdiff_t>(header.size()));
  return out;
}

std::vector<std::uint8_t> encode_zero_offset_angle(double degrees) {
  std::vector<std::uint8_t> out(4);
  const auto quarters = static_cast<std::int32_t>(std::lround(degrees * kQuarterDegrees));
  write_u32_le(out.data(), static_cast<std::uint32_t>(quarters));
  return out;
}

bool sends_device_info_after_scan_header(HostCompat compat) { return compat == HostCompat::YdlidarSdk; }

std::uint32_t reported_scan_hz_offset_centihz(HostCompat compat, const ModelProfile& profile) {
  const bool tg = profile.model == Model::TG15 || profile.model == Model::TG30 || profile.model == Model::TG50;
  return compat == HostCompat::YdlidarSdk && tg ? 40 : 0;
}

}  // namespace ydscope
