#include "app/gui/zone_setup.h"

#include <cstdio>

namespace ydscope::gui {

std::vector<Zone> zones_to_watch(const std::vector<std::string>& remembered,
                                 const std::vector<std::string>& command_line) {
  std::vector<Zone> zones;
  for (const auto* list : {&remembered, &command_line})
    for (const std::string& spec : *list) {
      std::string error;
      if (auto zone = parse_zone(spec, error))
        zones.push_back(std::move(*zone));
      else
        std::fprintf(stderr, "ydscope: %s; it is left out\n", error.c_str());
    }
  return zones;
}

bool raises_a_zone(const ZoneWatch& watch, const std::vector<ZoneEvent>& events) {
  for (const ZoneEvent& e : events)
    if (e.zone < watch.states().size() && watch.states()[e.zone].raised) return true;
  return false;
}

void ring_bell() {
  std::fputs("\a", stderr);
  std::fflush(stderr);
}

}  // namespace ydscope::gui
