#pragma once
// What info, scan and set share: --port/--model/--baud into a SessionConfig, connecting with one
// clear sentence on failure, and the device's details as JSON fields.
#include <chrono>
#include <set>
#include <string>

#include "app/common/arguments.h"
#include "core/session/session.h"
#include "core/text/json_writer.h"

namespace ydscope::cli {

// The options every device subcommand takes (value options).
std::set<std::string> session_value_options(std::set<std::string> more);

// --conventions field|manual: how a unit's bytes are read (unit_conventions.h); empty when not given.
std::optional<Reading> reading_option(const Arguments& args);

// --port PATH|tcp://host:port (required), --model auto|MODEL, --baud B|auto, --conventions.
// UsageError on mistakes.
SessionConfig session_config_from(const Arguments& args, bool scan);
// The same for a port that may not be there yet (check --loop waits for each unit): --port's
// absence is no mistake, `address` is the path to wait for.
SessionConfig session_config_awaiting(const Arguments& args, const std::string& address);
// The same from the texts of one port's options (several lidars: source_options.h).
SessionConfig session_config_for(const std::string& address, const std::optional<std::string>& model,
                                 const std::optional<std::string>& baud, bool scan, bool port_must_exist = true);

// Connects and waits for the device to be Ready (or Scanning when config.scan); throws
// std::runtime_error with the session's sentence when it fails.
SessionSnapshot connect_or_throw(Session& session, const SessionConfig& config);

// "model":...,"model_code":...,"firmware":...,"hardware":...,"serial":...,"health":{...}|null,
// "scan_hz":...|null,"ranging_khz":...|null,"port":...,"baud":...,"distance_scale":...,
// "conventions":{...}|null, into an object the caller opened.
void write_device_fields(JsonObject& device, const SessionSnapshot& snapshot);

}  // namespace ydscope::cli
