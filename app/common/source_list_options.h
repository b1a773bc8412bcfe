#pragma once
// Several lidars on one command line, as every program that takes them spells it (ydscope-cli
// record and serve, and ydscope): --port once per lidar, and per lidar a --name, a --pose, a
// --frame-id (its ROS frame) and a --serial (the unit it is, core/frame/unit_identity.h), each
// given once per --port in the same order (or not at all:
// lidar0, lidar1, ... at the origin, each lidar's frame its name). --model and --baud are given
// once for all or once per --port.
#include <cstdint>
#include <optional>
#include <set>
#include <string>
#include <vector>

#include "app/common/arguments.h"
#include "core/frame/pose.h"

namespace ydscope {

struct SourceText {
  std::string port;
  std::string name;          // letters, digits and _, starting with a letter: a ROS namespace and a CSV field as is
  std::optional<Pose> pose;  // empty: no --pose (a recording puts it at the origin; the app spreads them)
  std::optional<std::string> model;     // as typed: "auto", "G6", ...; checked by the caller
  std::optional<std::string> baud;      // as typed: a number or "auto"; parse_baud_text checks a number
  std::optional<std::string> frame_id;  // its ROS frame (valid_frame_id); empty: its name, or laser alone
  std::optional<std::string> serial;    // the unit (A5 90 serial) this name and pose belong to, on any port
};

// The options above, repeatable (Arguments' last parameter).
std::set<std::string> source_repeatable_options();

// One per --port, in order (none without --port). UsageError, one sentence, on a mistake: a count
// of --name/--pose/--frame-id/--model/--baud that does not match the ports, a bad or repeated
// name, a bad pose or frame name.
std::vector<SourceText> source_texts_from(const Arguments& args);

// Whether `name` is a source name as above.
bool valid_source_name(const std::string& name);

// Whether `serial` is a unit's serial as the session renders it (letters and digits, up to 32).
bool valid_unit_serial(const std::string& serial);

// Whether `frame` is a ROS frame name tf2 takes as is (base_link, front_laser, robot1/laser).
bool valid_frame_id(const std::string& frame);
// `frame` when valid, else UsageError naming --`option`.
std::string checked_frame_id(const std::string& option, const std::string& frame);

// A baud rate as typed after --baud: a whole number from 50 to 4000000, else UsageError.
std::uint32_t parse_baud_text(const std::string& text);

}  // namespace ydscope
