#include "app/cli/source_options.h"

#include "app/cli/session_cli.h"
#include "app/cli/units_by_serial.h"
#include "core/link/link_address.h"

namespace ydscope::cli {

std::vector<SourceSpec> source_specs_from(const Arguments& args, bool scan) {
  if (!args.has("port")) throw UsageError("missing required option --port (see --help)");
  if (args.values("port").size() == 1) {
    for (const std::string& option : source_repeatable_options())
      if (args.values(option).size() > 1) throw UsageError("option --" + option + " is given twice");
    if (args.value("name") || args.value("pose"))
      throw UsageError("--name and --pose place one of several lidars; give them with two or more --port");
    if (args.value("serial"))
      throw UsageError("--serial binds the name of one of several lidars; give it with two or more --port");
  }
  std::vector<SourceSpec> specs;
  std::set<std::string> seen_ports;
  for (SourceText& text : source_texts_from(args)) {
    SourceSpec spec;
    spec.config = session_config_for(text.port, text.model, text.baud, scan);
    spec.config.reading = reading_option(args);
    std::string error;
    const auto address = parse_link_address(text.port, error);
    if (!seen_ports.insert(address->text()).second) throw UsageError("--port " + text.port + " is given twice");
    spec.info.name = std::move(text.name);
    spec.info.pose = text.pose.value_or(Pose{});      // no --pose: the common frame's origin
    spec.info.frame_id = text.frame_id.value_or("");  // no --frame-id: its name (alone: laser)
    spec.info.model = spec.config.model;
    spec.info.serial = text.serial.value_or("");  // bound to this unit, wherever it is plugged in
    specs.push_back(std::move(spec));
  }
  // Names and poses follow the units' serials before anything is recorded or served under them.
  bind_units_by_serial(specs);
  return specs;
}

std::string who(const SourceSet& set, std::size_t id) {
  return named_apart(set.infos()) ? set.info(id).name + " (" + set.config(id).address + ")" : set.config(id).address;
}

}  // namespace ydscope::cli
