#pragma once
// Several lidars on one command line (record, serve), as app/common/source_list_options.h spells
// them, turned into sessions' configurations.
#include <set>
#include <string>
#include <vector>

#include "app/common/arguments.h"
#include "app/common/source_list_options.h"
#include "core/frame/pose.h"
#include "core/link/session.h"
#include "core/record/recording_metadata.h"

namespace ydscope::cli {

using ydscope::source_repeatable_options;

struct SourceSpec {
  std::string name;  // letters, digits and _, starting with a letter: a ROS namespace and a CSV field as is
  Pose pose;
  SessionConfig config;
};

// One spec per --port. UsageError, one sentence, on a mistake: a count of --name/--pose/--model/
// --baud that does not match the ports, a bad or repeated name, a bad pose, a port given twice, or
// a serial port that does not exist.
std::vector<SourceSpec> source_specs_from(const Arguments& args, bool scan);

// What a recording says about the source before it connects: name, pose, port, model if given.
RecordingMetadata source_metadata(const SourceSpec& spec);

}  // namespace ydscope::cli
