#include "app/cli/source_options.h"

#include "app/cli/session_cli.h"
#include "core/link/link_address.h"

namespace ydscope::cli {

std::vector<SourceSpec> source_specs_from(const Arguments& args, bool scan) {
  if (!args.has("port")) throw UsageError("missing required option --port (see --help)");
  std::vector<SourceSpec> specs;
  std::set<std::string> seen_ports;
  for (SourceText& text : source_texts_from(args)) {
    SourceSpec spec;
    spec.config = session_config_for(text.port, text.model, text.baud, scan);
    spec.config.reading = reading_option(args);
    std::string error;
    const auto address = parse_link_address(text.port, error);
    if (!seen_ports.insert(address->text()).second) throw UsageError("--port " + text.port + " is given twice");
    spec.name = std::move(text.name);
    spec.pose = text.pose.value_or(Pose{});  // no --pose: the common frame's origin
    specs.push_back(std::move(spec));
  }
  return specs;
}

RecordingMetadata source_metadata(const SourceSpec& spec) {
  RecordingMetadata metadata;
  metadata.name = spec.name;
  metadata.pose = spec.pose;
  metadata.port = spec.config.address;
  if (spec.config.model) metadata.model = std::string(profile_for(*spec.config.model).name);
  return metadata;
}

}  // namespace ydscope::cli
