#pragma once
// The options every command that writes MCAP shares (export, decode --mcap, record --mcap, serve
// --mcap): the chunk compression, the ROS frame id, whether the link bytes go in, and the
// overwrite check.
#include <set>
#include <string>
#include <string_view>

#include "app/common/arguments.h"
#include "core/export/mcap_recording_export.h"

namespace ydscope::cli {

// The value options and flags below, added to a command's own.
std::set<std::string> with_mcap_value_options(std::set<std::string> own);
std::set<std::string> with_mcap_flags(std::set<std::string> own);

// --compression zstd|lz4|none, --frame-id ID, --parent-frame ID, --no-link-bytes. UsageError on
// mistakes (a frame name tf2 would not take).
McapExportOptions mcap_options_from(const Arguments& args);

// UsageError when `path` exists and --force was not given.
void refuse_to_overwrite(const std::string& path, const Arguments& args, std::string_view option);

// The lines of these options in --help texts (a literal, so help texts can splice it in).
#define YDSCOPE_MCAP_OPTIONS_HELP                                                                     \
  "  --compression C    MCAP chunk compression: zstd (default), lz4 or none\n"                        \
  "  --frame-id ID      frame_id of /scan, /points and /diagnostics (default: laser); with several\n" \
  "                     --port, once per --port (default: each lidar's --name)\n"                     \
  "  --parent-frame ID  the robot's frame /tf_static places each lidar in (default: base_link)\n"     \
  "  --no-link-bytes    leave out /ydscope/device_bytes and /ydscope/host_bytes (a smaller file,\n"   \
  "                     but it can no longer be decoded again like a recording)\n"

}  // namespace ydscope::cli
