// How the virtual lidar answers each command: the model's manual first, then, in a host
// compatibility mode, the extra commands of core/sim/host_compat.h. The rest of VirtualLidar
// (power, stream, pacing, faults) is in virtual_lidar.cpp.
#include <algorithm>
#include <cmath>
#include <cstdio>

#include "core/protocol/scan_packet.h"
#include "core/sim/host_compat.h"
#include "core/sim/line_pacer.h"
#include "core/sim/virtual_lidar.h"

namespace ydscope {

namespace {

std::string hex_command(std::uint8_t code) {
  char text[8];
  std::snprintf(text, sizeof text, "A5 %02X", code);
  return text;
}

}  // namespace

void VirtualLidar::handle_command(std::uint8_t code, std::int64_t now_ns) {
  ++counters_.commands;
  const std::optional<Command> command = command_from_code(code);
  const std::string name = hex_command(code) + (command ? " (" + std::string(command_name(*command)) + ")" : "");

  const CompatCommand* extra = find_compat_command(config_.host_compat, *profile_, code);
  if (extra && extra->answer == CompatAnswer::Silent) {
    log(now_ns, "received " + hex_command(code) + " (" + std::string(extra->why) + "): no reply");
    return;
  }

  if (mode_ == DeviceMode::Scanning) {
    if (command == Command::Stop) {
      log(now_ns, "received " + name);
      stop_scan(now_ns, "stopped by A5 65");
    } else if (command == Command::Scan && protection_) {
      ++counters_.keepalives;
      last_keepalive_ns_ = now_ns;
      log(now_ns, "received " + name + ": power-down protection keep-alive");
    } else {
      ++counters_.ignored_during_scan;
      log(now_ns, "ignored " + name + ": only A5 65 is accepted while scanning");
    }
    return;
  }

  bool supported = command && profile_->supports(*command);
  if (supported && config_.health_quirk) {
    // The unit answers the other health command than its manual's, and not the manual's one.
    const bool is_health = command == Command::HealthStatusBits || command == Command::HealthStatusCode;
    if (is_health) supported = *command != profile_->health_command;
  } else if (!supported && config_.health_quirk &&
             (command == Command::HealthStatusBits || command == Command::HealthStatusCode)) {
    supported = true;
  }
  if (!supported && extra) {
    answer_compat(*extra, now_ns);
    return;
  }
  if (!supported) {
    ++counters_.unsupported;
    log(now_ns, "no reply to " + name + ": the " + std::string(profile_->name) + " manual does not list it");
    return;
  }
  log(now_ns, "received " + name);

  const auto step_hz = [&](int centihz) {
    const auto min = static_cast<long>(std::lround(profile_->min_scan_hz * 100.0));
    const auto max = static_cast<long>(std::lround(profile_->max_scan_hz * 100.0));
    scan_centihz_ = static_cast<std::uint32_t>(std::clamp(static_cast<long>(scan_centihz_) + centihz, min, max));
    answer(*command,
           encode_scan_frequency({scan_centihz_ + reported_scan_hz_offset_centihz(config_.host_compat, *profile_)}),
           now_ns);
  };

  switch (*command) {
    case Command::Scan: start_scan(now_ns); break;
    case Command::Stop: break;  // already idle: nothing to stop, and A5 65 never answers
    case Command::DeviceInfo: answer(*command, encode_device_info(info_), now_ns); break;
    case Command::HealthStatusBits:
    case Command::HealthStatusCode: answer(*command, encode_health(health_reply()), now_ns); break;
    case Command::ScanHzUpTenth: step_hz(10); break;
    case Command::ScanHzDownTenth: step_hz(-10); break;
    case Command::ScanHzUpOne: step_hz(100); break;
    case Command::ScanHzDownOne: step_hz(-100); break;
    case Command::ScanHzGet: step_hz(0); break;
    case Command::RangingCycle:
      ranging_index_ = static_cast<std::uint8_t>((ranging_index_ + 1) % profile_->ranging_khz.size());
      log(now_ns, "ranging frequency now " + std::to_string(ranging_khz()) + " kHz");
      answer(*command, encode_one_byte(ranging_index_), now_ns);
      break;
    case Command::RangingGet: answer(*command, encode_one_byte(ranging_index_), now_ns); break;
    case Command::PowerDownProtection:
      protection_ = !protection_;
      log(now_ns, std::string("power-down protection ") + (protection_ ? "on" : "off"));
      answer(*command, encode_power_down_protection(protection_), now_ns);
      break;
    case Command::LowPowerOn:
    case Command::LowPowerOff:
      low_power_ = *command == Command::LowPowerOn;
      answer(*command, encode_low_power(low_power_), now_ns);
      break;
    case Command::ModuleStatus:  // TG "low-power query": 01 while low power is on
      answer(*command, encode_one_byte(low_power_ ? 1 : 0), now_ns);
      break;
    case Command::MotorClockwise: direction_ = MotorDirection::Clockwise; [[fallthrough]];
    case Command::MotorDirection: answer(*command, encode_motor_direction(direction_), now_ns); break;
    case Command::MotorCounterClockwise:
      direction_ = MotorDirection::CounterClockwise;
      answer(*command, encode_motor_direction(direction_), now_ns);
      break;
    case Command::ConstantHzOn:
    case Command::ConstantHzOff:
      constant_hz_ = *command == Command::ConstantHzOn;
      answer(*command, encode_constant_frequency(constant_hz_), now_ns);
      break;
    case Command::RestartG1:
    case Command::RestartG6TG:
      ++counters_.restarts;
      reset_to_power_on();
      log(now_ns, "restarted: idle, power-on defaults");
      break;
  }
}

HealthReply VirtualLidar::health_reply() const {
  HealthReply health;
  if (profile_->health_command == Command::HealthStatusBits) {
    health.status = faults().health_bits;
  } else {
    health.status = faults().health_bits ? static_cast<std::uint8_t>(DeviceStatus::Error) : 0;
    health.error_code = faults().health_bits;
  }
  return health;
}

void VirtualLidar::answer_compat(const CompatCommand& extra, std::int64_t now_ns) {
  log(now_ns, "received " + hex_command(extra.code) + " (" + std::string(extra.why) + ", " +
                  std::string(host_compat_name(config_.host_compat)) + " host)");
  if (extra.answer == CompatAnswer::Health) {
    send_reply(encode_compat_reply(extra, encode_health(health_reply())), now_ns);
  } else {
    send_reply(encode_compat_reply(extra, encode_zero_offset_angle(0.0)), now_ns);
  }
}

void VirtualLidar::answer(Command command, std::span<const std::uint8_t> payload, std::int64_t now_ns) {
  send_reply(encode_reply(command, payload), now_ns);
}

void VirtualLidar::send_reply(std::span<const std::uint8_t> reply, std::int64_t now_ns) {
  reply_bytes_.clear();
  if (!line_.frame_reply(reply, now_ns, reply_bytes_)) return;  // a stall discarded it
  ++counters_.replies;
  pacer_->enqueue(now_ns, reply_bytes_);
}

}  // namespace ydscope
