#include "core/analysis/zone_watch.h"

#include <algorithm>

#include "core/analysis/text_format.h"

namespace ydscope {

ZoneWatch::ZoneWatch(std::vector<Zone> zones, Pose pose)
    : zones_(std::move(zones)), states_(zones_.size()), quiet_laps_(zones_.size(), 0), pose_(pose) {}

void ZoneWatch::clear() {
  states_.assign(zones_.size(), ZoneState{});
  quiet_laps_.assign(zones_.size(), 0);
  events_.clear();
  newest_ns_ = 0;
}

bool ZoneWatch::any_raised() const {
  return std::any_of(states_.begin(), states_.end(), [](const ZoneState& s) { return s.raised; });
}

const std::vector<ZoneEvent>& ZoneWatch::add_lap(const Lap& lap) {
  events_.clear();
  const std::int64_t t = lap.last_rx_ns;
  const bool first = newest_ns_ == 0;
  newest_ns_ = t;
  const PosedFrame posed(pose_);  // its turns once a lap, not at each point of each zone
  for (std::size_t z = 0; z < zones_.size(); ++z) {
    ZoneState& s = states_[z];
    s.points = 0;
    for (const LapPoint& p : lap.points) s.points += zones_[z].contains(p, posed) ? 1 : 0;
    if (first) s.since_ns = t;
    if (s.points >= kZoneMinPoints) {
      quiet_laps_[z] = 0;
      if (!s.occupied) {
        s.occupied = true;
        s.since_ns = t;
        ++s.entries;
        events_.push_back({z, true, t, s.points});
      }
    } else if (s.occupied && ++quiet_laps_[z] >= kZoneClearLaps) {
      s.occupied = false;
      s.since_ns = t;
      events_.push_back({z, false, t, s.points});
    }
    s.raised = zones_[z].rule == ZoneRule::Enter ? s.occupied : !s.occupied;
  }
  return events_;
}

std::string describe_zone(const Zone& zone, const ZoneState& s, std::int64_t now_ns) {
  const double for_s = static_cast<double>(now_ns - s.since_ns) * 1e-9;
  if (s.occupied)
    return format_text("%s: something in it (%zu points) for %.0f s%s", zone.name.c_str(), s.points, for_s,
                       zone.rule == ZoneRule::Enter ? "" : " (as it should be)");
  return format_text("%s: %s for %.0f s%s", zone.name.c_str(), zone.rule == ZoneRule::Enter ? "clear" : "empty", for_s,
                     zone.rule == ZoneRule::Empty ? " (it should not be)" : "");
}

std::string describe_zone_event(const Zone& zone, const ZoneEvent& event) {
  return event.entered ? format_text("%s entered (%zu points)", zone.name.c_str(), event.points) : zone.name + " left";
}

}  // namespace ydscope
