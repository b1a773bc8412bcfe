#include "core/analysis/acceptance.h"

#include <algorithm>
#include <cmath>

#include "core/analysis/blockage_criterion.h"
#include "core/analysis/text_format.h"

namespace ydscope {

namespace {

double deviation_pct(double measured, double expected) {
  return expected != 0 ? 100.0 * std::fabs(measured - expected) / expected : INFINITY;
}

// Limits are inclusive; the slack keeps a value printed as exactly the limit from failing on the
// last bit of a double.
bool within(double value, double limit) { return value <= limit * (1.0 + 1e-9) + 1e-12; }

CriterionResult identity(const CheckObservations& o) {
  CriterionResult r{"identity", "identity", "", "", Verdict::Fail, std::nullopt};
  const ModelProfile* p = o.profile;
  r.limit = p ? format_text("model code %u (%.*s); firmware and serial read", p->model_code,
                            static_cast<int>(p->name.size()), p->name.data())
              : "a known model";
  if (!o.identity.answered) {
    r.measured = "no answer to A5 90";
    return r;
  }
  const ModelProfile* reported = find_profile_by_code(o.identity.model_code);
  const std::string_view reported_name = reported ? reported->name : std::string_view("unknown");
  r.measured = format_text("model code %u (%.*s), firmware %s, serial %s", o.identity.model_code,
                           static_cast<int>(reported_name.size()), reported_name.data(),
                           o.identity.firmware.empty() ? "?" : o.identity.firmware.c_str(),
                           o.identity.serial.empty() ? "?" : o.identity.serial.c_str());
  const bool ok =
      p && o.identity.model_code == p->model_code && !o.identity.firmware.empty() && !o.identity.serial.empty();
  r.verdict = ok ? Verdict::Pass : Verdict::Fail;
  return r;
}

CriterionResult health(const CheckObservations& o) {
  CriterionResult r{"health", "health", "", "no error or warning over the run", Verdict::Fail, std::nullopt};
  if (o.health.empty()) {
    r.measured = "not read";
    return r;
  }
  bool problem = false;
  for (const HealthObservation& h : o.health) {
    if (!r.measured.empty()) r.measured += "; ";
    r.measured += h.source + ": " + h.summary;
    problem = problem || h.problem;
  }
  r.verdict = problem ? Verdict::Fail : Verdict::Pass;
  return r;
}

CriterionResult scan_rate(const CheckObservations& o, const AcceptanceLimits& l) {
  const LapTimingStatistics& t = o.timing;
  CriterionResult r{
      "scan_rate",   "scan rate", "", format_text("%.2f Hz ± %.1f %%", l.scan_hz_target, l.scan_hz_tolerance_pct),
      Verdict::Fail, std::nullopt};
  if (t.normal_laps < 2) {
    r.measured = format_text("too few laps (%llu)", static_cast<unsigned long long>(t.normal_laps));
    return r;
  }
  r.value = t.mean_hz;
  r.measured = format_text("%.3f Hz (%+.2f %%; mean of %llu laps, %.2f-%.2f Hz)", t.mean_hz,
                           100.0 * (t.mean_hz - l.scan_hz_target) / l.scan_hz_target,
                           static_cast<unsigned long long>(t.normal_laps), t.min_hz, t.max_hz);
  if (o.reported_scan_hz) r.measured += format_text("; the unit reports %.2f Hz", *o.reported_scan_hz);
  r.verdict =
      within(deviation_pct(t.mean_hz, l.scan_hz_target), l.scan_hz_tolerance_pct) ? Verdict::Pass : Verdict::Fail;
  return r;
}

CriterionResult scan_jitter(const CheckObservations& o, const AcceptanceLimits& l) {
  const LapTimingStatistics& t = o.timing;
  CriterionResult r{"scan_jitter", "scan jitter", "", format_text("at most %.2f %%", l.scan_jitter_max_pct),
                    Verdict::Fail, std::nullopt};
  if (t.normal_laps < 3) {
    r.measured = format_text("too few laps (%llu)", static_cast<unsigned long long>(t.normal_laps));
    return r;
  }
  r.value = t.jitter_pct;
  r.measured =
      format_text("%.2f %% (robust std-dev of the samples per lap, %.1f on average)", t.jitter_pct, t.samples_per_lap);
  r.verdict = within(t.jitter_pct, l.scan_jitter_max_pct) ? Verdict::Pass : Verdict::Fail;
  return r;
}

// What the unit should emit at its ranging code: the conventions' table, else the code's name.
double expected_samples_per_s(const CheckObservations& o) {
  if (o.conventions && o.profile)
    if (const auto rate = o.conventions->samples_per_s(*o.profile, o.ranging_khz)) return *rate;
  return o.ranging_khz * 1000.0;
}

CriterionResult sample_rate(const CheckObservations& o, const AcceptanceLimits& l) {
  const double expected = expected_samples_per_s(o);
  CriterionResult r{"sample_rate",
                    "sample rate",
                    "",
                    format_text("%.0f samples/s ± %.1f %% (ranging code %u kHz, %s conventions)", expected,
                                l.sample_rate_tolerance_pct, o.ranging_khz,
                                o.conventions ? std::string(o.conventions->id).c_str() : "the manual's"),
                    Verdict::Fail,
                    std::nullopt};
  if (o.ranging_khz == 0) r.limit = "the ranging frequency in use (not read)";
  if (o.timing.normal_laps == 0) {
    r.measured = "no complete lap";
    return r;
  }
  r.value = o.timing.sample_rate_hz;
  r.measured = format_text("%.0f samples/s (%.1f per lap)", o.timing.sample_rate_hz, o.timing.samples_per_lap);
  r.verdict = o.ranging_khz && within(deviation_pct(o.timing.sample_rate_hz, expected), l.sample_rate_tolerance_pct)
                  ? Verdict::Pass
                  : Verdict::Fail;
  return r;
}

CriterionResult link(const CheckObservations& o, const AcceptanceLimits& l) {
  const LinkObservation& k = o.link;
  const bool g1 = o.profile && o.profile->last_crc_before_zero;
  const auto count = [](std::uint64_t n) { return static_cast<unsigned long long>(n); };
  const auto most = [](double n) { return static_cast<unsigned long long>(n); };
  CriterionResult r{"link", "link", "", "", Verdict::Fail, std::nullopt};
  r.measured = format_text(
      "checksum errors %llu, resync bytes %llu, CRC8 failures %s, queue drops %llu, "
      "lost samples %llu",
      count(k.checksum_errors), count(k.resync_bytes), g1 ? std::to_string(k.crc8_failures).c_str() : "n/a",
      count(k.queue_drops), count(k.lost_samples));
  r.limit = format_text("at most %llu, %llu, %llu, %llu, %llu", most(l.max_checksum_errors), most(l.max_resync_bytes),
                        most(l.max_crc8_failures), most(l.max_queue_drops), most(l.max_lost_samples));
  const bool ok = static_cast<double>(k.checksum_errors) <= l.max_checksum_errors &&
                  static_cast<double>(k.resync_bytes) <= l.max_resync_bytes &&
                  static_cast<double>(k.crc8_failures) <= l.max_crc8_failures &&
                  static_cast<double>(k.queue_drops) <= l.max_queue_drops &&
                  static_cast<double>(k.lost_samples) <= l.max_lost_samples;
  r.verdict = ok ? Verdict::Pass : Verdict::Fail;
  return r;
}

CriterionResult share(std::string id, std::string title, std::uint64_t valid, std::uint64_t points, double min_share) {
  CriterionResult r{std::move(id), std::move(title), "", format_text("at least %.1f %%", 100.0 * min_share),
                    Verdict::Fail, std::nullopt};
  if (points == 0) {
    r.measured = "no points";
    return r;
  }
  const double s = static_cast<double>(valid) / static_cast<double>(points);
  r.value = s;
  r.measured = format_text("%.2f %% (%llu of %llu points)", 100.0 * s, static_cast<unsigned long long>(valid),
                           static_cast<unsigned long long>(points));
  r.verdict = s >= min_share ? Verdict::Pass : Verdict::Fail;
  return r;
}

void range_criteria(const CheckObservations& o, const AcceptanceLimits& l, std::vector<CriterionResult>& out) {
  const double target = *o.target_mm;
  const ValueSummary& d = o.sector->flat_distance_mm;
  const double bias_limit = l.bias_tolerance_mm.value_or(default_bias_tolerance_mm(target));
  const double noise_limit = l.noise_max_mm.value_or(default_noise_max_mm(target));
  CriterionResult bias{
      "range_bias",  "range bias", "", format_text("|bias| at most %.1f mm from %.1f mm", bias_limit, target),
      Verdict::Fail, std::nullopt};
  CriterionResult noise{"range_noise", "range noise", "", format_text("std-dev at most %.1f mm", noise_limit),
                        Verdict::Fail, std::nullopt};
  if (d.count < 2) {
    bias.measured = noise.measured = "fewer than two valid returns in the sector";
  } else {
    bias.value = d.mean - target;
    bias.measured =
        format_text("%+.1f mm (mean %.1f mm, median %.1f mm, %zu returns)", d.mean - target, d.mean, d.median, d.count);
    bias.verdict = within(std::fabs(d.mean - target), bias_limit) ? Verdict::Pass : Verdict::Fail;
    noise.value = d.stddev;
    noise.measured = format_text("%.1f mm (range %.1f-%.1f mm)", d.stddev, d.min, d.max);
    noise.verdict = within(d.stddev, noise_limit) ? Verdict::Pass : Verdict::Fail;
  }
  out.push_back(std::move(bias));
  out.push_back(std::move(noise));
}

}  // namespace

std::vector<CriterionResult> evaluate_acceptance(const CheckObservations& o, const AcceptanceLimits& l) {
  std::vector<CriterionResult> out;
  out.push_back(identity(o));
  out.push_back(health(o));
  out.push_back(scan_rate(o, l));
  out.push_back(scan_jitter(o, l));
  out.push_back(sample_rate(o, l));
  out.push_back(link(o, l));
  out.push_back(share("valid_returns", "valid returns", o.valid_points, o.points, l.min_valid_share));
  out.push_back(blockage_criterion(o.blocked_sectors, DropoutOptions{}));
  if (o.sector) {
    out.push_back(share("sector_valid", "valid returns in " + o.sector_name.value_or("the sector"), o.sector->valid,
                        o.sector->points, l.min_sector_valid_share));
    if (o.target_mm) range_criteria(o, l, out);
  }
  return out;
}

bool all_passed(const std::vector<CriterionResult>& results) {
  return std::all_of(results.begin(), results.end(),
                     [](const CriterionResult& r) { return r.verdict == Verdict::Pass; });
}

}  // namespace ydscope
