#include "core/session/device_probe.h"

#include <cmath>
#include <cstdio>

namespace ydscope {

std::string command_bytes_text(Command command) {
  char text[8];
  std::snprintf(text, sizeof text, "A5 %02X", static_cast<unsigned>(command));
  return text;
}

namespace {
std::string seconds_text(std::chrono::milliseconds timeout) {
  char text[32];
  if (timeout.count() % 1000 == 0)
    std::snprintf(text, sizeof text, "%lld s", static_cast<long long>(timeout.count() / 1000));
  else
    std::snprintf(text, sizeof text, "%.2f s", static_cast<double>(timeout.count()) / 1000.0);
  return text;
}
}  // namespace

std::string no_reply_sentence(Command command, std::chrono::milliseconds timeout, const std::string& link,
                              std::size_t bytes_seen) {
  const std::string head = command_bytes_text(command) + " (" + std::string(command_name(command)) + ")";
  if (bytes_seen == 0)
    return "no reply to " + head + " within " + seconds_text(timeout) + " on " + link +
           ": wrong baud or model, or the lidar is not powered?";
  return std::to_string(bytes_seen) + " bytes but no valid reply to " + head + " within " + seconds_text(timeout) +
         " on " + link + ": wrong baud? (try --baud auto)";
}

HealthReport make_health_report(Command command, const HealthReply& reply) {
  HealthReport report;
  report.command = command;
  report.status = reply.status;
  report.error_code = reply.error_code;
  char code[16];
  std::snprintf(code, sizeof code, "0x%04X", static_cast<unsigned>(reply.error_code));
  if (command == Command::HealthStatusBits) {
    if ((reply.status & 0x3F) == 0) {
      report.summary = "ok";
    } else {
      report.summary = "abnormal:";
      const char* separator = " ";
      for (unsigned bit = 0; bit < kG1HealthBitCount; ++bit) {
        if (reply.status & (1u << bit)) {
          report.summary += separator;
          report.summary += g1_health_bit_name(bit);
          separator = ", ";
        }
      }
    }
    return report;
  }
  const auto status = device_status(reply.status);
  if (!status) {
    report.summary = "unknown status " + std::to_string(reply.status) + " (error code " + code + ")";
  } else if (*status == DeviceStatus::Normal && reply.error_code == 0) {
    report.summary = "ok";
  } else {
    report.summary = std::string(device_status_name(*status)) + " (error code " + code + ")";
  }
  return report;
}

DeviceDetails make_device_details(const DeviceInfo& info, const ModelProfile& profile) {
  DeviceDetails details;
  details.profile = &profile;
  details.model_code = info.model_code;
  details.firmware = {info.firmware_major, info.firmware_minor};
  details.hardware = info.hardware;
  details.serial = serial_string(info);
  return details;
}

const ModelProfile* choose_profile(std::optional<Model> configured, std::uint8_t model_code, std::string& note) {
  note.clear();
  const ModelProfile* detected = find_profile_by_code(model_code);
  if (configured) {
    const ModelProfile& chosen = profile_for(*configured);
    if (detected != &chosen)
      note = "the device reports model code " + std::to_string(model_code) + " (" +
             (detected ? std::string(detected->name) : std::string("unknown")) + ") but " + std::string(chosen.name) +
             " was asked for; decoding as " + std::string(chosen.name);
    return &chosen;
  }
  if (!detected)
    note = "the device reports model code " + std::to_string(model_code) +
           ", which ydscope does not know; pass the model explicitly (" + std::string(model_names()) + ")";
  return detected;
}

std::optional<Command> next_scan_hz_step(double current_hz, double target_hz) {
  const long difference = std::lround((target_hz - current_hz) * 100.0);  // centihertz
  if (difference >= 100) return Command::ScanHzUpOne;
  if (difference <= -100) return Command::ScanHzDownOne;
  if (difference > 5) return Command::ScanHzUpTenth;
  if (difference < -5) return Command::ScanHzDownTenth;
  return std::nullopt;
}

std::string hz_text(double hz) {
  char text[32];
  std::snprintf(text, sizeof text, "%.2f Hz", hz);
  return text;
}

}  // namespace ydscope
