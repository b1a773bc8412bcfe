#include "core/analysis/acceptance_limits.h"

#include <algorithm>
#include <array>

namespace ydscope {

namespace {

constexpr std::array<LimitSource, 14> kLimitSources{{
    {"scan rate target", "the model's default (G1 9 Hz, G6 8 Hz, TG 10 Hz), within 5-12 Hz",
     "model profile; the 5-12 Hz span from the datasheets, the manuals give none", "--scan-hz"},
    {"scan rate tolerance", "2 % of the target", "default", "--scan-tolerance-pct"},
    {"scan jitter", "robust std-dev of the samples per lap at most 2 % of their median", "default", "--jitter-pct"},
    {"sample rate", "the ranging frequency in use (G1 4/5/8/9/10/16/18 kHz; G6, TG 4/8/9 kHz, default 9)",
     "the manuals' A5 D1 tables", "--ranging-khz"},
    {"sample rate tolerance", "2 %", "default", "--sample-rate-tolerance-pct"},
    {"checksum errors", "0", "default", "--max-checksum-errors"},
    {"resync bytes", "0", "default", "--max-resync-bytes"},
    {"CRC8 failures (G1)", "0", "default", "--max-crc8-failures"},
    {"queue drops", "0", "default", "--max-queue-drops"},
    {"lost samples", "0", "default", "--max-lost-samples"},
    {"valid returns, all points", "at least 50 % (depends on the room more than on the unit)", "default",
     "--min-valid-pct"},
    {"valid returns, in the sector", "at least 95 %", "default", "--min-sector-valid-pct"},
    {"range bias on the target", "2 % of the target distance, at least 20 mm", "default", "--tolerance-mm"},
    {"range noise on the target", "std-dev 1 % of the target distance, at least 10 mm", "default", "--noise-mm"},
}};

}  // namespace

AcceptanceLimits default_limits(const ModelProfile& profile) {
  AcceptanceLimits limits;
  limits.scan_hz_target = profile.default_scan_hz;
  limits.scan_hz_tolerance_pct = 2.0;
  limits.scan_jitter_max_pct = 2.0;
  limits.sample_rate_tolerance_pct = 2.0;
  limits.min_valid_share = 0.50;
  limits.min_sector_valid_share = 0.95;
  return limits;
}

double default_bias_tolerance_mm(double target_mm) { return std::max(20.0, 0.02 * target_mm); }
double default_noise_max_mm(double target_mm) { return std::max(10.0, 0.01 * target_mm); }

std::span<const LimitSource> limit_sources() { return kLimitSources; }

}  // namespace ydscope
