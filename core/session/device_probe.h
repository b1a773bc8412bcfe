#pragma once
// The pure decisions of talking to a lidar, kept apart from the I/O so they are tested directly:
// the words of each failure, what a health answer means, which model a device-info code names,
// and the next step toward a scan-frequency target.
#include <chrono>
#include <cstdint>
#include <optional>
#include <string>

#include "core/snapshot/session_snapshot.h"
#include "core/protocol/commands.h"
#include "core/protocol/model_profile.h"
#include "core/protocol/reply.h"

namespace ydscope {

// "A5 90"
std::string command_bytes_text(Command command);

// "no reply to A5 90 within 1 s on /dev/ttyUSB0 at 230400 baud: wrong baud or model?" and, when
// bytes did arrive but none formed the reply, a sentence that points at the baud instead.
std::string no_reply_sentence(Command command, std::chrono::milliseconds timeout, const std::string& link,
                              std::size_t bytes_seen);

// What the health answer means for this model and command: "ok", "warning (error code 0x0012)",
// "abnormal: sensor, encoder".
HealthReport make_health_report(Command command, const HealthReply& reply);

// The device details from A5 90 with the profile in use.
DeviceDetails make_device_details(const DeviceInfo& info, const ModelProfile& profile);

// The profile for a device-info code when the configured model is `configured` (empty = auto).
// Null when the model is auto and the code is unknown; `note` then says what to do. A configured
// model wins over a disagreeing code (note says so).
const ModelProfile* choose_profile(std::optional<Model> configured, std::uint8_t model_code, std::string& note);

// The command that moves the set scan frequency from `current_hz` toward `target_hz` (steps of
// 1 Hz and 0.1 Hz), or empty when they agree to within 0.05 Hz.
std::optional<Command> next_scan_hz_step(double current_hz, double target_hz);

// "10.00 Hz"
std::string hz_text(double hz);

}  // namespace ydscope
