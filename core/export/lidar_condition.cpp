#include "core/export/lidar_condition.h"

#include <cstdio>
#include <vector>

namespace ydscope {

namespace {

std::string seconds_text(std::int64_t ns) {
  char text[32];
  std::snprintf(text, sizeof text, "%.1f s", static_cast<double>(ns) * 1e-9);
  return text;
}

}  // namespace

LidarVerdict judge_lidar(const LidarCondition& c) {
  std::vector<std::string> errors, warnings;
  if (c.link_fault) {
    // Everything else is from before the outage: only the outage is true now.
    errors.push_back((c.quiet_ns ? "no data for " + seconds_text(*c.quiet_ns) : std::string("no data yet")) + "; " +
                     *c.link_fault);
  } else {
    if (c.health && *c.health != "ok") errors.push_back("health: " + *c.health);
    const std::string window = " in the last " + seconds_text(kConditionWindowNs);
    if (c.recent_checksum_errors)
      warnings.push_back(std::to_string(c.recent_checksum_errors) + " checksum errors" + window);
    if (c.recent_crc_mismatches)
      warnings.push_back(std::to_string(c.recent_crc_mismatches) + " CRC8 mismatches" + window);
    if (c.settling)
      warnings.push_back(*c.settling);
    else if (c.no_recent_lap)
      warnings.push_back("no complete lap in the last second");
    warnings.insert(warnings.end(), c.blocked_sectors.begin(), c.blocked_sectors.end());
  }
  LidarVerdict verdict;
  verdict.level = !errors.empty() ? 2 : !warnings.empty() ? 1 : 0;
  if (verdict.level == 0) {
    verdict.message = c.health ? "ok; health: ok" : "ok; health not read";
    return verdict;
  }
  for (const auto* list : {&errors, &warnings})
    for (const std::string& reason : *list) verdict.message += (verdict.message.empty() ? "" : "; ") + reason;
  return verdict;
}

}  // namespace ydscope
