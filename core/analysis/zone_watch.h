#pragma once
// Zones watched lap by lap: how many returns each zone holds, whether something is in it, and the
// moments something entered or left it. A zone is occupied once a lap puts kZoneMinPoints returns
// in it (a speck of noise is not a visitor) and clear again after kZoneClearLaps laps with fewer
// (a leg passing between two samples does not make it leave). Its rule says which of the two
// raises it (zone.h).
#include <cstdint>
#include <string>
#include <vector>

#include "core/analysis/zone.h"
#include "core/frame/pose.h"
#include "core/protocol/lap.h"

namespace ydscope {

inline constexpr std::size_t kZoneMinPoints = 3;
inline constexpr int kZoneClearLaps = 3;

struct ZoneState {
  bool occupied = false;
  bool raised = false;        // the rule's alarm: occupied for `enter`, clear for `empty`
  std::size_t points = 0;     // returns in the zone in the newest lap
  std::int64_t since_ns = 0;  // when it last became occupied or clear (lap time)
  std::uint64_t entries = 0;  // times something entered since the watch began
};

struct ZoneEvent {
  std::size_t zone = 0;  // index into the watch's zones
  bool entered = false;  // false: left
  std::int64_t t_ns = 0;
  std::size_t points = 0;
};

class ZoneWatch {
 public:
  explicit ZoneWatch(std::vector<Zone> zones = {}, Pose pose = {});

  // The lap's time is its last_rx_ns. Returns this lap's events (valid until the next call).
  const std::vector<ZoneEvent>& add_lap(const Lap& lap);
  void set_pose(const Pose& pose) { pose_ = pose; }
  void clear();

  const std::vector<Zone>& zones() const { return zones_; }
  const std::vector<ZoneState>& states() const { return states_; }
  bool any_raised() const;
  std::int64_t newest_ns() const { return newest_ns_; }

 private:
  std::vector<Zone> zones_;
  std::vector<ZoneState> states_;
  std::vector<int> quiet_laps_;  // laps in a row under kZoneMinPoints, per zone
  std::vector<ZoneEvent> events_;
  Pose pose_;
  std::int64_t newest_ns_ = 0;
};

// "door: something in it (14 points) for 3 s", "dock: empty for 12 s (it should not be)",
// "front: clear".
std::string describe_zone(const Zone& zone, const ZoneState& state, std::int64_t now_ns);
// "door entered (14 points)", "door left".
std::string describe_zone_event(const Zone& zone, const ZoneEvent& event);

}  // namespace ydscope
