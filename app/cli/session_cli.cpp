#include "app/cli/session_cli.h"

#include <charconv>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "app/common/device_connect.h"
#include "core/session/device_probe.h"
#include "app/common/source_list_options.h"
#include "core/link/link_address.h"

namespace ydscope::cli {

std::set<std::string> session_value_options(std::set<std::string> more) {
  more.insert({"port", "model", "baud", "conventions"});
  return more;
}

std::optional<Reading> reading_option(const Arguments& args) {
  const auto text = args.value("conventions");
  if (!text) return std::nullopt;
  const auto reading = parse_reading(*text);
  if (!reading)
    throw UsageError("unknown --conventions '" + *text +
                     "'; use field (as real units write) or manual (as the manual says)");
  return reading;
}

SessionConfig session_config_from(const Arguments& args, bool scan) {
  SessionConfig config = session_config_for(args.required("port"), args.value("model"), args.value("baud"), scan);
  config.reading = reading_option(args);
  return config;
}

SessionConfig session_config_awaiting(const Arguments& args, const std::string& address) {
  SessionConfig config =
      session_config_for(address, args.value("model"), args.value("baud"), /*scan=*/true, /*port_must_exist=*/false);
  config.reading = reading_option(args);
  return config;
}

SessionConfig session_config_for(const std::string& address, const std::optional<std::string>& model_option,
                                 const std::optional<std::string>& baud_option, bool scan, bool port_must_exist) {
  SessionConfig config;
  config.address = address;
  std::string error;
  // A port still to be found (check --loop without --port) has no address to judge yet.
  const auto link = port_must_exist || !address.empty() ? parse_link_address(config.address, error)
                                                        : std::optional<LinkAddress>(LinkAddress{});
  if (!link) throw UsageError(error);
  // A usage error like any other mistake in the command line (2), from every command alike.
  std::error_code ec;
  if (port_must_exist && link->kind == LinkAddress::Kind::Serial && !std::filesystem::exists(link->path, ec))
    throw UsageError("there is no port " + link->path +
                     "; is the lidar plugged in? `ydscope-cli ports` lists the ones attached");
  const std::string model = model_option.value_or("auto");
  if (model != "auto") {
    const ModelProfile* profile = find_profile(model);
    if (!profile)
      throw UsageError("unknown model '" + model + "'; valid models are auto, " + std::string(model_names()));
    config.model = profile->model;
  }
  const std::string baud = baud_option.value_or("");
  if (baud == "auto") {
    config.probe_baud = true;
  } else if (!baud.empty()) {
    config.baud = parse_baud_text(baud);
  }
  config.scan = scan;
  config.reconnect = false;  // a command-line run reports a fault instead of waiting it out
  return config;
}

SessionSnapshot connect_or_throw(Session& session, const SessionConfig& config) {
  const SessionSnapshot s = connect_and_wait(session, config);
  if (!s.message.empty()) std::fprintf(stderr, "ydscope-cli: warning: %s\n", s.message.c_str());
  return s;
}

void write_device_fields(JsonObject& device, const SessionSnapshot& s) {
  device.field("model", s.device && s.device->profile ? std::optional(s.device->profile->name) : std::nullopt);
  if (s.device) {
    device.field("model_code", s.device->model_code);
    device.field("firmware", std::to_string(s.device->firmware.major) + "." + std::to_string(s.device->firmware.minor));
    device.field("hardware", s.device->hardware).field("serial", s.device->serial);
  }
  if (s.health)
    device.object("health")
        .field("command", command_bytes_text(s.health->command))
        .field("status", s.health->status)
        .field("error_code", s.health->error_code)
        .field("summary", s.health->summary);
  else
    device.field("health", nullptr);
  device.field("scan_hz", s.scan_hz, 2).field("ranging_khz", s.ranging_khz);
  device.field("port", s.link).field("baud", s.baud).field("distance_scale", s.distance_scale, 6);
  if (s.conventions)
    device.object("conventions")
        .field("id", s.conventions->id)
        .field("reading", reading_name(s.conventions->reading))
        .field("label", s.conventions->label);
  else
    device.field("conventions", nullptr);
}

}  // namespace ydscope::cli
