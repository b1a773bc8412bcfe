#include "app/common/source_list_options.h"

#include <cctype>
#include <charconv>

namespace ydscope {
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

}  // namespace

bool valid_source_name(const std::string& name) {
  if (name.empty() || name.size() > 64 || !std::isalpha(static_cast<unsigned char>(name.front()))) return false;
  for (const char c : name)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_') return false;
  return true;
}

bool valid_unit_serial(const std::string& serial) {
  if (serial.empty() || serial.size() > 32) return false;
  for (const char c : serial)
    if (!std::isalnum(static_cast<unsigned char>(c))) return false;
  return true;
}

bool valid_frame_id(const std::string& frame) {
  // What tf2 takes as is: no leading '/', no spaces; letters, digits, _ and / between parts.
  if (frame.empty() || frame.size() > 128 || !std::isalpha(static_cast<unsigned char>(frame.front())) ||
      frame.back() == '/')
    return false;
  for (const char c : frame)
    if (!std::isalnum(static_cast<unsigned char>(c)) && c != '_' && c != '/') return false;
  return true;
}

std::string checked_frame_id(const std::string& option, const std::string& frame) {
  if (!valid_frame_id(frame))
    throw UsageError("--" + option + " '" + frame +
                     "' must be a ROS frame name: letters, digits, _ and /, starting with a letter (e.g. base_link)");
  return frame;
}

std::set<std::string> source_repeatable_options() {
  return {"port", "name", "pose", "model", "baud", "frame-id", "serial"};
}

std::vector<SourceText> source_texts_from(const Arguments& args) {
  const std::vector<std::string> ports = args.values("port");
  const auto names = per_port(args, "name", ports.size(), false);
  const auto poses = per_port(args, "pose", ports.size(), false);
  const auto models = per_port(args, "model", ports.size(), true);
  const auto bauds = per_port(args, "baud", ports.size(), true);
  // One frame for several lidars would put their clouds on top of each other: once per --port.
  const auto frames = per_port(args, "frame-id", ports.size(), false);
  // A serial names one unit: once per --port, like its name.
  const auto serials = per_port(args, "serial", ports.size(), false);
  std::vector<SourceText> sources;
  std::set<std::string> seen_names;
  for (std::size_t i = 0; i < ports.size(); ++i) {
    SourceText source;
    source.port = ports[i];
    source.model = models[i];
    source.baud = bauds[i];
    source.name = names[i].value_or("lidar" + std::to_string(i));
    if (!valid_source_name(source.name))
      throw UsageError("--name '" + source.name + "' must be letters, digits and _, starting with a letter (up to 64)");
    if (!seen_names.insert(source.name).second) throw UsageError("--name " + source.name + " is given to two ports");
    if (frames[i]) source.frame_id = checked_frame_id("frame-id", *frames[i]);
    if (serials[i]) {
      if (!valid_unit_serial(*serials[i]))
        throw UsageError("--serial '" + *serials[i] +
                         "' must be the unit's serial as `ydscope-cli info` prints it: letters and digits (up to 32)");
      source.serial = *serials[i];
    }
    if (poses[i]) {
      std::string error;
      const auto pose = parse_pose(*poses[i], error);
      if (!pose) throw UsageError("--pose: " + error);
      source.pose = *pose;
    }
    sources.push_back(std::move(source));
  }
  return sources;
}

std::uint32_t parse_baud_text(const std::string& text) {
  std::uint32_t parsed = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), parsed);
  if (ec != std::errc() || end != text.data() + text.size() || parsed < 50 || parsed > 4'000'000)
    throw UsageError("--baud must be a whole number from 50 to 4000000, not '" + text + "'");
  return parsed;
}

}  // namespace ydscope
