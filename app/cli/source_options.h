#pragma once
// The lidars on one command line (record, serve), as app/common/source_list_options.h spells
// them, turned into a set's specs.
#include <set>
#include <string>
#include <vector>

#include "app/common/arguments.h"
#include "app/common/source_list_options.h"
#include "core/frame/pose.h"
#include "core/session/source_set.h"

namespace ydscope::cli {

using ydscope::source_repeatable_options;

// One spec (core/session/source_set.h) per --port: one lidar is a set of one. UsageError, one
// sentence, on a mistake: a count of --name/--pose/--model/--baud that does not match the ports, a
// bad or repeated name, a bad pose, a port given twice, a serial port that does not exist, or a
// --name or --pose for a lone lidar (they place one of several).
std::vector<SourceSpec> source_specs_from(const Arguments& args, bool scan);

// "NAME (PORT)" for one of several, "PORT" for a lone lidar: how every line names it.
std::string who(const SourceSet& set, std::size_t id);

}  // namespace ydscope::cli
