#pragma once
// ydscope-cli serve's running part, for one lidar or several: the lidars' sessions feed a
// SessionShare (core/bridge); this keeps their lap queues empty, says on stderr when a lidar's
// link goes bad, and ends cleanly. With several --port, serve_sources sets it all up: each lidar
// scans in a session of its own (reconnecting by itself) and is served under its name
// (/NAME/scan, NAME/scan_hz ...), with /tf_static holding every pose.
#include <atomic>
#include <optional>
#include <string>
#include <vector>

#include "app/common/arguments.h"
#include "core/bridge/foxglove_server.h"
#include "core/bridge/session_share.h"

namespace ydscope::cli {

struct ServedLidar {
  std::string name;  // empty: the only one
  Session* session = nullptr;
};

// Until `stop` or `seconds`: then the clients' counters, the share stopped (the MCAP file gets
// its summary), the sessions disconnected and what was written said. Throws with one sentence
// when writing the file failed.
void serve_until_stopped(SessionShare& share, const std::vector<ServedLidar>& lidars, std::optional<double> seconds,
                         const std::atomic<bool>& stop);

// Serves several --port until `stop` or --seconds; the exit status as `serve --help` gives it.
int serve_sources(const Arguments& args, foxglove::ServerOptions server_options, const std::atomic<bool>& stop);

// The warning for a share reachable from other machines: there is no authentication.
void warn_if_not_loopback(const SessionShare& share);

}  // namespace ydscope::cli
