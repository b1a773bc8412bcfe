#include "app/cli/source_options.h"

#include <cctype>
#include <filesystem>
#include <optional>

#include "app/cli/session_cli.h"
#include "core/link/link_address.h"

namespace ydscope::cli {
namespace {

// Each port's value of --`option`: none, one for all (when `shared`), or one per port.
std::vector<std::optional<std::string>> per_port(const Arguments& args, const std::string& option, std::size_t ports,
                                                 bool shared) {
  const std::vector<std::string> given = args.values(option);
  if (given.empty()) return std::vector<std::optional<std::string>>(ports);
  if (given.size() == 1 && shared) return std::vector<std::optional<std::string>>(ports, given.front());
  if (given.size() != ports)
    throw UsageError("give --" + option + (shared ? " once for all ports or" : "") + " once per --port (" +
                     std::to_string(ports) + " ports), not " + std::to_string(given.size()) + " times");
  return {given.begin(), given.end()};
}

bool valid_name(const std::string& name) {
  if (name.empty() || name.size() > 64 || !std::isalpha(static_cast<unsigned char>(name.front()))) return false;
  for (const char c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') return false;
  return true;
}

}  // namespace

std::set<std::string> source_repeatable_options() { return {"port", "name", "pose", "model", "baud"}; }

std::vector<SourceSpec> source_specs_from(const Arguments& args, bool scan) {
  const std::vector<std::string> ports = args.values("port");
  if (ports.empty()) throw UsageError("missing required option --port (see --help)");
  const auto names = per_port(args, "name", ports.size(), false);
  const auto poses = per_port(args, "pose", ports.size(), false);
  const auto models = per_port(args, "model", ports.size(), true);
  const auto bauds = per_port(args, "baud", ports.size(), true);
  std::vector<SourceSpec> specs;
  std::set<std::string> seen_names;
  std::set<std::string> seen_ports;
  for (std::size_t i = 0; i < ports.size(); ++i) {
    SourceSpec spec;
    spec.config = session_config_for(ports[i], models[i], bauds[i], scan);
    std::string error;
    const auto address = parse_link_address(ports[i], error);
    if (!seen_ports.insert(address->text()).second) throw UsageError("--port " + ports[i] + " is given twice");
    std::error_code ec;
    if (address->kind == LinkAddress::Kind::Serial && !std::filesystem::exists(address->path, ec))
      throw UsageError("there is no port " + address->path + "; `ydscope-cli ports` lists the ones attached");
    spec.name = names[i].value_or("lidar" + std::to_string(i));
    if (!valid_name(spec.name))
      throw UsageError("--name '" + spec.name + "' must be letters, digits and _, starting with a letter (up to 64)");
    if (!seen_names.insert(spec.name).second) throw UsageError("--name " + spec.name + " is given to two ports");
    if (poses[i]) {
      const auto pose = parse_pose(*poses[i], error);
      if (!pose) throw UsageError("--pose: " + error);
      spec.pose = *pose;
    }
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
