#pragma once
// Identity by serial on the command line: a lidar given --serial, or whose --name settings.ini
// binds to a serial (`unit = SERIAL; NAME`, what `align --apply` and the app write), is that unit
// wherever it is plugged in. Before a set starts, every port's unit is asked its serial (A5 90),
// and each name, pose and frame moves to the port its unit answered on (core/frame/unit_identity.h),
// so recordings, MCAP files and the bridge carry the right name from their first byte.
#include <string>
#include <vector>

#include "core/frame/source_info.h"
#include "core/session/source_set.h"

namespace ydscope::cli {

// Each info's serial: its --serial, else the one remembered for its name. Empty for a lone lidar.
void recall_serials(std::vector<SourceInfo>& infos);

// The serial each config's unit answers with (all asked at once, each within a few seconds;
// empty for one that did not answer). Their sessions are closed again before this returns.
std::vector<std::string> ask_serials(const std::vector<SessionConfig>& configs);

// The specs of a set of two or more, their serials recalled, bound by serial: when any is bound,
// every port is asked, names and poses follow the units, each move or swap is said on stderr as
// "ydscope-cli: ..." and every info's serial is the one read. Unbound sets are left as they are.
void bind_units_by_serial(std::vector<SourceSpec>& specs);

}  // namespace ydscope::cli
