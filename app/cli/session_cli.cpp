#include "app/cli/session_cli.h"

#include <charconv>
#include <cstdio>
#include <filesystem>
#include <stdexcept>

#include "app/common/device_connect.h"
#include "core/link/device_probe.h"
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

void write_device_fields(JsonOut& out, const SessionSnapshot& s) {
  out.raw(R"("model":)");
  if (s.device && s.device->profile)
    out.string(s.device->profile->name);
  else
    out.raw("null");
  if (s.device) {
    out.raw(R"(,"model_code":)");
    out.integer(s.device->model_code);
    out.raw(R"(,"firmware":)");
    out.string(std::to_string(s.device->firmware.major) + "." + std::to_string(s.device->firmware.minor));
    out.raw(R"(,"hardware":)");
    out.integer(s.device->hardware);
    out.raw(R"(,"serial":)");
    out.string(s.device->serial);
  }
  out.raw(R"(,"health":)");
  if (s.health) {
    out.raw(R"({"command":)");
    out.string(command_bytes_text(s.health->command));
    out.raw(R"(,"status":)");
    out.integer(s.health->status);
    out.raw(R"(,"error_code":)");
    out.integer(s.health->error_code);
    out.raw(R"(,"summary":)");
    out.string(s.health->summary);
    out.raw("}");
  } else {
    out.raw("null");
  }
  out.raw(R"(,"scan_hz":)");
  out.fixed_or_null(s.scan_hz, 2);
  out.raw(R"(,"ranging_khz":)");
  out.integer_or_null(s.ranging_khz);
  out.raw(R"(,"port":)");
  out.string(s.link);
  out.raw(R"(,"baud":)");
  out.integer(s.baud);
  out.raw(R"(,"distance_scale":)");
  out.fixed(s.distance_scale, 6);
  out.raw(R"(,"conventions":)");
  if (s.conventions) {
    out.raw(R"({"id":)");
    out.string(s.conventions->id);
    out.raw(R"(,"reading":)");
    out.string(reading_name(s.conventions->reading));
    out.raw(R"(,"label":)");
    out.string(s.conventions->label);
    out.raw("}");
  } else {
    out.raw("null");
  }
}

}  // namespace ydscope::cli
