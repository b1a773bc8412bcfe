#include "core/session/recording_control.h"

#include <cstdio>

#include "core/session/record_tap.h"
#include "core/session/session_io.h"

namespace ydscope {

CommandResult RecordingControl::start_file(const std::string& path, const RecordingMetadata& start) {
  CommandResult result;
  result.what = "record to " + path;
  recorder_.stop();
  std::string error;
  result.ok = recorder_.start(path, start, error);
  result.message = result.ok ? "recording every byte to " + path : error;
  update_wire_hook();
  return result;
}

CommandResult RecordingControl::stop_file() {
  CommandResult result;
  result.what = "stop recording";
  result.ok = true;
  result.message = recorder_.active() ? "recording saved to " + recorder_.path() : "was not recording";
  recorder_.stop();
  update_wire_hook();
  return result;
}

CommandResult RecordingControl::start_tap(std::shared_ptr<RecordTap> tap, const RecordingMetadata& start) {
  CommandResult result;
  result.what = "tap the session's records";
  recorder_.start_tap(std::move(tap), start);
  update_wire_hook();
  result.ok = true;
  result.message = "every record goes to the tap";
  return result;
}

CommandResult RecordingControl::stop_tap(const std::shared_ptr<RecordTap>& tap) {
  CommandResult result;
  result.what = "stop the record tap";
  result.ok = true;
  result.message = tap && recorder_.stop_tap(*tap) ? "tap closed" : "that tap was not open";
  update_wire_hook();
  return result;
}

std::optional<std::string> RecordingControl::flush_file() {
  if (!recorder_.active()) return std::nullopt;
  recorder_.flush();
  if (recorder_.active() || recorder_.error().empty()) return std::nullopt;
  update_wire_hook();
  return recorder_.error();
}

void RecordingControl::record_metadata(const RecordingMetadata& metadata) {
  recorder_.metadata(metadata);  // to the file and the tap, whichever are open
}

void RecordingControl::update_wire_hook() {
  if (!recorder_.capturing()) return link_.on_wire({});
  link_.on_wire([this](bool outgoing, std::span<const std::uint8_t> bytes, std::int64_t ns) {
    recorder_.bytes(outgoing, bytes, ns);
  });
}

RecordingMetadata recording_metadata_of(const SessionSnapshot& s, const std::optional<std::string>& port,
                                        std::optional<double> distance_scale) {
  RecordingMetadata metadata;
  metadata.port = port;
  if (s.baud) metadata.baud = s.baud;
  metadata.distance_scale = distance_scale;
  if (s.conventions) metadata.conventions = std::string(s.conventions->id);
  if (s.device && s.device->profile) {
    metadata.model = std::string(s.device->profile->name);
    if (s.device->model_code) {
      metadata.model_code = s.device->model_code;
      metadata.firmware = std::to_string(s.device->firmware.major) + "." + std::to_string(s.device->firmware.minor);
      metadata.hardware = s.device->hardware;
      metadata.serial = s.device->serial;
    }
  }
  if (s.scan_hz) {
    char hz[32];
    std::snprintf(hz, sizeof hz, "%.2f", *s.scan_hz);
    metadata.extra["scan_hz"] = hz;
  }
  if (s.ranging_khz) metadata.extra["ranging_khz"] = std::to_string(*s.ranging_khz);
  if (s.health) metadata.extra["health"] = s.health->summary;
  if (s.power_down_protection) metadata.extra["power_down_protection"] = *s.power_down_protection ? "on" : "off";
  return metadata;
}

}  // namespace ydscope
