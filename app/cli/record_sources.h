#pragma once
// ydscope-cli record's running part, for one lidar or several alike: a SourceSet (one Session per
// --port, each reconnecting by itself) recorded into one .ydrec (version 1 for one lidar, 2 for
// several), one live MCAP, or both. A lidar that stops is said in one sentence and the others keep
// recording; when it comes back that is said too.
#include <atomic>

#include "app/common/arguments.h"

namespace ydscope::cli {

// Runs the recording until Ctrl-C or --seconds; the exit status as `record --help` gives it.
int record_sources(const Arguments& args, const std::atomic<bool>& interrupted);

}  // namespace ydscope::cli
