#pragma once
// The limits a unit must meet in `ydscope-cli check`, per model. Where the vendor manuals give a
// value it is taken from them (the ranging frequencies, hence the sample rate); the scan-frequency
// span comes from the model profile (the datasheets' 5-12 Hz); everything else is a documented
// default of ours, because neither the manuals nor the datasheets we have give one. Each limit has
// a command-line flag; kLimitSources lists value, source and flag for docs/check.md and --help.
#include <optional>
#include <span>
#include <string_view>

#include "core/protocol/model_profile.h"

namespace ydscope {

struct AcceptanceLimits {
  double scan_hz_target = 0;             // the rate set before measuring
  double scan_hz_tolerance_pct = 0;      // |mean - target| / target
  double scan_jitter_max_pct = 0;        // robust std-dev of the samples per lap, % of their median
  double sample_rate_tolerance_pct = 0;  // |samples/s - ranging kHz * 1000| / that
  double max_checksum_errors = 0;
  double max_resync_bytes = 0;
  double max_crc8_failures = 0;
  double max_queue_drops = 0;
  double max_lost_samples = 0;
  double min_valid_share = 0;         // 0..1, all points
  double min_sector_valid_share = 0;  // 0..1, points in the sector
  // Range against a flat target at target_mm: |bias| and std-dev, in mm. Defaults scale with the
  // distance (see range_defaults_for); a flag replaces them with a fixed value.
  std::optional<double> bias_tolerance_mm;
  std::optional<double> noise_max_mm;
};

// The defaults for a model: its default scan rate as the target and the table below.
AcceptanceLimits default_limits(const ModelProfile& profile);

// Default |bias| and noise limits for a flat target at `target_mm`: 2 % of it (at least 20 mm) and
// 1 % of it (at least 10 mm).
double default_bias_tolerance_mm(double target_mm);
double default_noise_max_mm(double target_mm);

struct LimitSource {
  std::string_view limit;   // "scan rate tolerance"
  std::string_view value;   // "2 % of the target"
  std::string_view source;  // "default" / "G6 manual, A5 D0 / D1 table" ...
  std::string_view flag;    // "--scan-tolerance-pct"
};
std::span<const LimitSource> limit_sources();

}  // namespace ydscope
