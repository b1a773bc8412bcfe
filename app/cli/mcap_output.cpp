#include "app/cli/mcap_output.h"

#include <filesystem>

#include "app/common/source_list_options.h"

namespace ydscope::cli {

std::set<std::string> with_mcap_value_options(std::set<std::string> own) {
  own.insert({"compression", "frame-id", "parent-frame"});
  return own;
}

std::set<std::string> with_mcap_flags(std::set<std::string> own) {
  own.insert("no-link-bytes");
  return own;
}

McapExportOptions mcap_options_from(const Arguments& args) {
  McapExportOptions options;
  if (const auto name = args.value("compression")) {
    const auto compression = parse_compression(*name);
    if (!compression) throw UsageError("--compression takes zstd, lz4 or none, not '" + *name + "'");
    options.mcap.compression = *compression;
  }
  // With several lidars each --frame-id is one lidar's (source_list_options.h); alone, the first.
  if (const auto frame = args.value("frame-id")) options.ros.frame.frame_id = checked_frame_id("frame-id", *frame);
  if (const auto parent = args.value("parent-frame"))
    options.ros.frame.parent_frame_id = checked_frame_id("parent-frame", *parent);
  options.ros.link_bytes = !args.has("no-link-bytes");
  return options;
}

void refuse_to_overwrite(const std::string& path, const Arguments& args, std::string_view option) {
  if (!args.has("force") && std::filesystem::exists(path))
    throw UsageError(path + " already exists; choose another " + std::string(option) +
                     " or add --force to overwrite it");
}

}  // namespace ydscope::cli
