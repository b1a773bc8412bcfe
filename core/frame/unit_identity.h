#pragma once
// Identity by serial: which unit is which, whatever port it came up on. A lidar given a serial
// (--serial, or settings.ini's `unit = SERIAL; NAME` line for its name) is bound to that unit:
// once every port's unit has answered A5 90, the name, pose and frame follow the serial to the
// port it is on, and a unit that moved, two that swapped, or a stranger on a bound port is said
// in one sentence. A lidar with no serial bound stays bound by its port, as before serials.
// Plain values: the CLI runs it before it records or serves, the app when its lidars have answered.
#include <string>
#include <vector>

#include "core/frame/source_info.h"

namespace ydscope {

// What one port's unit said: its port as the user gave it and its serial (empty: not read).
struct UnitSeen {
  std::string port;
  std::string serial;
};

struct UnitIdentity {
  // Per port, in the order given: the source found there (name, pose, frame of the unit bound to
  // the serial read on it), `serial` the serial read (empty when none was), `model` the port's.
  std::vector<SourceInfo> sources;
  std::vector<std::string> notes;  // one sentence each: a swap, a move, a stranger, a repeated serial
  bool moved = false;              // some source is now on another port than it was given
};

// `given` per port (its `serial` the unit it is bound to, empty: bound by port), `seen` per port
// in the same order. A serial read on two ports binds neither (a note says so).
UnitIdentity identify_units(const std::vector<SourceInfo>& given, const std::vector<UnitSeen>& seen);

}  // namespace ydscope
