#pragma once
// ydscope-cli record with several --port: every lidar into one recording (format version 2), each
// with its own Session and its own reconnect. A lidar that stops is said in one sentence and the
// others keep recording; when it comes back that is said too.
#include <atomic>

#include "app/common/arguments.h"

namespace ydscope::cli {

// Runs the recording until Ctrl-C or --seconds; the exit status as `record --help` gives it.
int record_sources(const Arguments& args, const std::atomic<bool>& interrupted);

}  // namespace ydscope::cli
