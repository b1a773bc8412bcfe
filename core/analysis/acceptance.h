#pragma once
// The verdict of an acceptance run: what was observed, held against AcceptanceLimits, one line per
// criterion with the measured value, the limit and PASS/FAIL. Plain data in, plain data out: the
// CLI gathers the observations from a live session, tests can build them by hand.
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/analysis/acceptance_limits.h"
#include "core/analysis/dropout_ring.h"
#include "core/analysis/lap_timing.h"
#include "core/analysis/sector_statistics.h"
#include "core/protocol/model_profile.h"
#include "core/protocol/unit_conventions.h"

namespace ydscope {

struct IdentityObservation {
  bool answered = false;  // A5 90 answered
  std::uint8_t model_code = 0;
  std::string firmware;  // "1.2"
  std::string serial;
};

// One health reading: an A5 91/92 answer or G1's CT health bits in the laps.
struct HealthObservation {
  std::string source;    // "A5 91 before the run", "CT health in 3 of 120 laps"
  bool problem = false;  // any error or warning
  std::string summary;   // "ok", "error (code 0x0004)", "encoder abnormal"
};

struct LinkObservation {
  std::uint64_t checksum_errors = 0;
  std::uint64_t resync_bytes = 0;
  std::uint64_t crc8_failures = 0;
  std::uint64_t queue_drops = 0;
  std::uint64_t lost_samples = 0;
};

struct CheckObservations {
  const ModelProfile* profile = nullptr;
  IdentityObservation identity;
  std::vector<HealthObservation> health;
  LapTimingStatistics timing;
  // The scan rate the unit reports in its CT bytes (G1's channel, a G6/TG zero packet read as the
  // field reads it), averaged over the laps that carried it; shown beside the measured rate.
  std::optional<double> reported_scan_hz;
  std::uint16_t ranging_khz = 0;  // in use (A5 D1 read-back): the ranging code's name
  // How the unit's bytes were read: what it should emit per ranging code (unit_conventions.h).
  const UnitConventions* conventions = nullptr;
  LinkObservation link;
  std::uint64_t points = 0;  // all points received while measuring
  std::uint64_t valid_points = 0;
  std::optional<SectorStatistics> sector;
  std::optional<std::string> sector_name;  // "260:280"
  std::optional<double> target_mm;
  // Sectors empty at the end of the run while the rest of the turn saw returns (dropout_ring.h).
  std::vector<BlockedSector> blocked_sectors;
};

enum class Verdict : std::uint8_t { Pass, Fail };

struct CriterionResult {
  std::string id;        // stable, for scripts: identity, health, scan_rate, scan_jitter, sample_rate,
                         // link, valid_returns, blockage, sector_valid, range_bias, range_noise
  std::string title;     // "scan rate"
  std::string measured;  // "8.01 Hz (mean of 80 laps)"
  std::string limit;     // "8.00 Hz ± 2.0 %"
  Verdict verdict = Verdict::Fail;
  std::optional<double> value;  // the number compared, when there is one
};

// Sector criteria appear only when a sector was measured; range ones only with a target distance.
std::vector<CriterionResult> evaluate_acceptance(const CheckObservations& observed, const AcceptanceLimits& limits);

bool all_passed(const std::vector<CriterionResult>& results);

}  // namespace ydscope
