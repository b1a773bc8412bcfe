#include "core/export/zone_reports.h"

namespace ydscope {

std::vector<DiagnosticReport> zone_reports(const ZoneWatch& watch, std::string_view lidar,
                                           const std::string& hardware_id) {
  std::vector<DiagnosticReport> reports;
  for (std::size_t z = 0; z < watch.zones().size(); ++z) {
    const Zone& zone = watch.zones()[z];
    const ZoneState& state = watch.states()[z];
    DiagnosticReport r;
    r.level = state.raised ? 1 : 0;
    r.name = "ydscope zone: " + zone.name + " (" + std::string(lidar) + ")";
    r.message = describe_zone(zone, state, watch.newest_ns());
    r.hardware_id = hardware_id;
    r.values = {{"zone", zone_spec(zone)},
                {"rule", zone_rule_name(zone.rule)},
                {"occupied", state.occupied ? "true" : "false"},
                {"raised", state.raised ? "true" : "false"},
                {"points", std::to_string(state.points)},
                {"entries", std::to_string(state.entries)}};
    reports.push_back(std::move(r));
  }
  return reports;
}

}  // namespace ydscope
