#pragma once
// Several lidars on one command line (record, serve): --port once per lidar, and per lidar a
// --name and a --pose, each given once per --port in the same order (or not at all: lidar0,
// lidar1, ... at the origin). --model and --baud are given once for all or once per --port.
#include <set>
#include <string>
#include <vector>

#include "app/common/arguments.h"
#include "core/frame/pose.h"
#include "core/link/session.h"
#include "core/record/recording_metadata.h"

namespace ydscope::cli {

struct SourceSpec {
  std::string name;  // letters, digits and _, starting with a letter: a ROS namespace and a CSV field as is
  Pose pose;
  SessionConfig config;
};

// The options above, repeatable (Arguments' last parameter).
std::set<std::string> source_repeatable_options();

// One spec per --port. UsageError, one sentence, on a mistake: a count of --name/--pose/--model/
// --baud that does not match the ports, a bad or repeated name, a bad pose, a port given twice, or
// a serial port that does not exist.
std::vector<SourceSpec> source_specs_from(const Arguments& args, bool scan);

// What a recording says about the source before it connects: name, pose, port, model if given.
RecordingMetadata source_metadata(const SourceSpec& spec);

}  // namespace ydscope::cli
