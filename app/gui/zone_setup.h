#pragma once
// The zones the app watches: settings.ini's `zone = ...` lines, then each --zone (a spec that does
// not parse is said on stderr and left out, as a bad settings line is), given to every source's
// panel model; and the bell when a zone's rule is raised, if asked (--zone-beep, the Zones
// section's checkbox).
#include <string>
#include <vector>

#include "core/analysis/zone_watch.h"

namespace ydscope::gui {

std::vector<Zone> zones_to_watch(const std::vector<std::string>& remembered,
                                 const std::vector<std::string>& command_line);

// True when one of `events` just raised its zone's rule (something entered a zone that should be
// clear, or left one that should hold something).
bool raises_a_zone(const ZoneWatch& watch, const std::vector<ZoneEvent>& events);

// The terminal's bell: the app has no sound of its own, and a robot's bench has a terminal.
void ring_bell();

}  // namespace ydscope::gui
