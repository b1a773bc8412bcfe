#include "app/common/check_run.h"

#include <chrono>
#include <functional>
#include <future>
#include <stdexcept>

#include "app/common/arguments.h"
#include "app/common/device_connect.h"
#include "app/common/lap_bell.h"
#include "core/analysis/dropout_ring.h"
#include "core/analysis/lap_timing.h"
#include "core/analysis/text_format.h"
#include "core/session/device_probe.h"
#include "core/protocol/health_level.h"
#include "core/protocol/reply.h"

namespace ydscope {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t) { return std::chrono::duration<double>(Clock::now() - t).count(); }

// Posts an intent and waits for its result; the session answers every intent, this only bounds a hang.
CommandResult await_result(const std::function<void(CommandCallback)>& post, const char* what) {
  auto promise = std::make_shared<std::promise<CommandResult>>();
  auto result = promise->get_future();
  post([promise](const CommandResult& r) { promise->set_value(r); });
  if (result.wait_for(std::chrono::seconds(120)) != std::future_status::ready)
    throw std::runtime_error(std::string(what) + " did not finish within 120 s");
  return result.get();
}

// A warning counts as much as an error here: the unit under test must be clean.
bool health_problem(const HealthReport& h) {
  return health_level(h.command, h.status, h.error_code) != HealthLevel::Ok;
}

HealthObservation health_reading(const HealthReport& h, const char* when) {
  return {command_bytes_text(h.command) + " " + when, health_problem(h), h.summary};
}

// G1 reports its module bits in every lap's CT (index 3); only laps whose CRC8 held are trusted.
struct CtHealth {
  std::uint64_t laps = 0;
  std::uint64_t abnormal_laps = 0;
  std::uint8_t bits_seen = 0;
  void add(const Lap& lap) {
    if (!lap.health_bits || !lap.ct_info_trusted()) return;
    ++laps;
    const auto bits = static_cast<std::uint8_t>(*lap.health_bits & 0x3F);
    if (bits) ++abnormal_laps;
    bits_seen = static_cast<std::uint8_t>(bits_seen | bits);
  }
  HealthObservation observation() const {
    HealthObservation o{format_text("CT health in %llu laps", static_cast<unsigned long long>(laps)), abnormal_laps > 0,
                        "ok"};
    if (!abnormal_laps) return o;
    o.summary = format_text("abnormal in %llu laps:", static_cast<unsigned long long>(abnormal_laps));
    const char* separator = " ";
    for (unsigned bit = 0; bit < kG1HealthBitCount; ++bit) {
      if (!(bits_seen & (1u << bit))) continue;
      o.summary += separator + std::string(g1_health_bit_name(bit));
      separator = ", ";
    }
    return o;
  }
};

void show(const std::function<void(const std::string&)>& progress, const std::string& line) {
  if (progress) progress(line);
}

bool streaming(const SessionSnapshot& s) {
  return s.state == LinkState::Scanning || s.state == LinkState::CommandInProgress;
}

std::string stream_failure(const SessionSnapshot& s) {
  return s.message.empty() ? "the scan stopped (" + describe_snapshot(s) + ")" : s.message;
}

}  // namespace

CheckRecord run_check(const CheckPlan& plan, const std::atomic<bool>& stop) {
  CheckRecord record;
  LapBell bell;
  Session session(64, [&bell] { bell.ring(); });
  show(plan.progress, "connecting to " + plan.session.address + " ...");
  record.started_unix_s =
      std::chrono::duration_cast<std::chrono::seconds>(std::chrono::system_clock::now().time_since_epoch()).count();
  record.context = plan.context;
  record.started = connect_and_wait(session, plan.session);
  if (!record.started.message.empty() && plan.warning) plan.warning(record.started.message);
  if (plan.connected) plan.connected(record.started);
  if (plan.distance_scale) session.set_distance_scale(plan.distance_scale);
  const SessionSnapshot& s0 = record.started;
  if (!s0.device || !s0.device->profile) throw std::runtime_error("the device's model is not known");
  const ModelProfile& profile = *s0.device->profile;

  record.limits = default_limits(profile);
  if (plan.scan_hz) {
    if (*plan.scan_hz < profile.min_scan_hz || *plan.scan_hz > profile.max_scan_hz)
      throw UsageError(format_text("--scan-hz %.2f is outside the %.*s's %.0f-%.0f Hz", *plan.scan_hz,
                                   static_cast<int>(profile.name.size()), profile.name.data(), profile.min_scan_hz,
                                   profile.max_scan_hz));
    record.limits.scan_hz_target = *plan.scan_hz;
  }
  for (const auto& [field, value] : plan.limit_overrides) record.limits.*field = value;
  record.limits.bias_tolerance_mm = plan.bias_tolerance_mm;
  record.limits.noise_max_mm = plan.noise_max_mm;

  show(plan.progress, format_text("setting the scan rate to %.2f Hz ...", record.limits.scan_hz_target));
  const CommandResult hz =
      await_result([&](CommandCallback done) { session.set_scan_hz(record.limits.scan_hz_target, std::move(done)); },
                   "setting the scan rate");
  if (!hz.ok) throw std::runtime_error(hz.message);
  if (plan.ranging_khz) {
    if (!profile.ranging_index(*plan.ranging_khz))
      throw UsageError(format_text("the %.*s has no %u kHz ranging frequency", static_cast<int>(profile.name.size()),
                                   profile.name.data(), *plan.ranging_khz));
    const std::optional<std::uint16_t> now = session.snapshot().ranging_khz;
    if (!profile.ranging_settable && now != plan.ranging_khz)
      throw UsageError(format_text("the %.*s's ranging frequency cannot be set (it reads %s); leave out --ranging-khz",
                                   static_cast<int>(profile.name.size()), profile.name.data(),
                                   now ? (std::to_string(*now) + " kHz").c_str() : "nothing"));
    if (profile.ranging_settable) {
      show(plan.progress, format_text("setting the ranging frequency to %u kHz ...", *plan.ranging_khz));
      const CommandResult khz =
          await_result([&](CommandCallback done) { session.set_ranging_khz(*plan.ranging_khz, std::move(done)); },
                       "setting the ranging frequency");
      if (!khz.ok) throw std::runtime_error(khz.message);
    }
  }

  // Let the motor settle at the new rate; these laps are not judged.
  Lap lap;
  const auto settle_start = Clock::now();
  while (seconds_since(settle_start) < plan.settle_seconds && !stop.load()) {
    while (session.laps().try_pop(lap)) {
    }
    const SessionSnapshot s = session.snapshot();
    if (!streaming(s)) throw std::runtime_error(stream_failure(s));
    show(plan.progress, format_text("settling: %.1f of %.1f s", seconds_since(settle_start), plan.settle_seconds));
    bell.wait(std::chrono::milliseconds(100));
  }
  while (session.laps().try_pop(lap)) {
  }

  const SessionSnapshot before = session.snapshot();
  CheckObservations& o = record.observations;
  o.profile = &profile;
  o.identity = {true, s0.device->model_code,
                std::to_string(s0.device->firmware.major) + "." + std::to_string(s0.device->firmware.minor),
                s0.device->serial};
  if (s0.health) o.health.push_back(health_reading(*s0.health, "before the run"));
  o.ranging_khz = before.ranging_khz.value_or(0);
  o.conventions = before.conventions;
  o.sector_name = plan.sector ? std::optional(plan.sector->name) : std::nullopt;
  o.target_mm = plan.target_mm;

  LapTimingAccumulator timing;
  DropoutRing dropouts;
  std::optional<SectorAccumulator> sector;
  if (plan.sector) sector.emplace(*plan.sector);
  record.sector_region = plan.sector;
  CtHealth ct_health;
  double reported_hz_sum = 0;
  std::uint64_t reported_laps = 0;
  const auto start = Clock::now();
  auto last_progress = start;
  while (seconds_since(start) < plan.seconds) {
    if (stop.load()) {
      record.interrupted = true;
      break;
    }
    bool any = false;
    while (session.laps().try_pop(lap)) {
      any = true;
      timing.add(lap);
      dropouts.add_lap(lap);
      if (sector) sector->add(lap);
      ct_health.add(lap);
      if (lap.scan_hz && lap.ct_info_trusted()) {
        reported_hz_sum += *lap.scan_hz;
        ++reported_laps;
      }
      for (const LapPoint& p : lap.points) o.valid_points += is_valid_return(p) ? 1 : 0;
      o.points += lap.points.size();
      record.last_lap = lap;
    }
    if (!any) {
      const SessionSnapshot s = session.snapshot();
      if (!streaming(s)) {
        record.failure = stream_failure(s);
        break;
      }
    }
    if (plan.progress && Clock::now() - last_progress > std::chrono::milliseconds(250)) {
      last_progress = Clock::now();
      const LapTimingStatistics t = timing.statistics();
      const CounterSnapshot c = session.snapshot().counters;
      show(plan.progress,
           format_text("measuring: %.1f of %.1f s, %llu laps, %.2f Hz, %llu checksum errors", seconds_since(start),
                       plan.seconds, static_cast<unsigned long long>(t.laps), t.mean_hz,
                       static_cast<unsigned long long>(c.checksum_errors - before.counters.checksum_errors)));
    }
    bell.wait(std::chrono::milliseconds(100));
  }
  record.measured_seconds = seconds_since(start);
  const SessionSnapshot after = session.snapshot();

  o.timing = timing.statistics();
  o.blocked_sectors = dropouts.blocked();
  if (reported_laps > 0) o.reported_scan_hz = reported_hz_sum / static_cast<double>(reported_laps);
  o.link.checksum_errors = after.counters.checksum_errors - before.counters.checksum_errors;
  o.link.resync_bytes = after.counters.resync_bytes - before.counters.resync_bytes;
  o.link.crc8_failures = after.counters.crc8_failures - before.counters.crc8_failures;
  o.link.queue_drops = after.queue_dropped - before.queue_dropped;
  o.link.lost_samples = o.timing.lost_samples;
  if (profile.ct_carries_info) o.health.push_back(ct_health.observation());
  if (sector) o.sector = record.sector = sector->statistics();

  // Health once more at the end (the session stops the scan for it), unless the user is leaving.
  if (!record.interrupted && record.failure.empty()) {
    show(plan.progress, "reading the health once more ...");
    const CommandResult h =
        await_result([&](CommandCallback done) { session.refresh_health(std::move(done)); }, "the health question");
    if (h.ok && h.health)
      o.health.push_back(health_reading(*h.health, "after the run"));
    else
      o.health.push_back({"health after the run", true, "no answer: " + h.message});
  }
  show(plan.progress, "stopping the lidar ...");
  session.disconnect();
  session.wait_until(
      [](const SessionSnapshot& s) { return s.state == LinkState::Idle || s.state == LinkState::Failed; },
      std::chrono::seconds(3));
  record.results = evaluate_acceptance(o, record.limits);
  return record;
}

CheckOutcome check_outcome(const CheckRecord& record) {
  if (record.interrupted || !record.failure.empty()) return CheckOutcome::Incomplete;
  return all_passed(record.results) ? CheckOutcome::Pass : CheckOutcome::Fail;
}

const char* outcome_word(CheckOutcome outcome) {
  switch (outcome) {
    case CheckOutcome::Pass: return "pass";
    case CheckOutcome::Fail: return "fail";
    case CheckOutcome::Incomplete: return "incomplete";
  }
  return "incomplete";
}

std::string incomplete_reason(const CheckRecord& record) {
  if (!record.failure.empty())
    return format_text("the link failed after %.1f s: %s", record.measured_seconds, record.failure.c_str());
  return format_text("interrupted after %.1f s", record.measured_seconds);
}

}  // namespace ydscope
