#pragma once
// ydscope-cli serve with several --port: each lidar scans in a session of its own (reconnecting by
// itself) and is served under its name (/NAME/scan, /NAME/points, /NAME/diagnostics and its link
// bytes), with /tf_static holding every pose; its parameters are NAME/scan_hz and so on. With
// --mcap, the file gets the same topics (McapRecordingExport with sources).
#include <atomic>

#include "app/common/arguments.h"
#include "core/bridge/foxglove_server.h"

namespace ydscope::cli {

// Serves until `stop` or --seconds; the exit status as `serve --help` gives it.
int serve_sources(const Arguments& args, foxglove::ServerOptions server_options, const std::atomic<bool>& stop);

}  // namespace ydscope::cli
