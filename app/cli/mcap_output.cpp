#include "app/cli/mcap_output.h"

#include <filesystem>

namespace ydscope::cli {

std::set<std::string> with_mcap_value_options(std::set<std::string> own) {
  own.insert({"compression", "frame-id"});
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
  if (const auto frame = args.value("frame-id")) {
    if (frame->empty()) throw UsageError("--frame-id needs a name, e.g. --frame-id laser");
    options.ros.frame.frame_id = *frame;
  }
  options.ros.link_bytes = !args.has("no-link-bytes");
  return options;
}

void refuse_to_overwrite(const std::string& path, const Arguments& args, std::string_view option) {
  if (!args.has("force") && std::filesystem::exists(path))
    throw UsageError(path + " already exists; choose another " + std::string(option) +
                     " or add --force to overwrite it");
}

}  // namespace ydscope::cli
