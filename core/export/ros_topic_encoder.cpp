#include "core/export/ros_topic_encoder.h"

#include "core/record/recorded_conventions.h"

#include <charconv>
#include <cstdio>
#include <ctime>

#include "core/export/lidar_condition.h"
#include "core/export/ros_schemas.h"
#include "core/export/zone_reports.h"

namespace ydscope {
namespace {

constexpr std::int64_t kDiagnosticsPeriodNs = 1'000'000'000;

const RosTopicInfo kTopics[kRosTopicCount] = {
    {RosTopic::Scan, "/scan", &laser_scan_schema()},
    {RosTopic::Points, "/points", &point_cloud2_schema()},
    {RosTopic::Diagnostics, "/diagnostics", &diagnostic_array_schema()},
    {RosTopic::DeviceBytes, "/ydscope/device_bytes", &uint8_multi_array_schema()},
    {RosTopic::HostBytes, "/ydscope/host_bytes", &uint8_multi_array_schema()},
    {RosTopic::Zones, "/zones", &diagnostic_array_schema()},
};

std::string fixed(double value, int decimals) {
  char text[64];
  std::snprintf(text, sizeof text, "%.*f", decimals, value);
  return text;
}

std::optional<int> digits(std::string_view text, std::size_t at, std::size_t n) {
  if (at + n > text.size()) return std::nullopt;
  int value = 0;
  const auto [end, ec] = std::from_chars(text.data() + at, text.data() + at + n, value);
  if (ec != std::errc() || end != text.data() + at + n) return std::nullopt;
  return value;
}

}  // namespace

std::span<const RosTopicInfo> ros_topics() { return kTopics; }

std::optional<std::uint64_t> parse_iso8601_utc_ns(std::string_view text) {
  // YYYY-MM-DDTHH:MM:SS[.fff...]Z
  const auto year = digits(text, 0, 4), month = digits(text, 5, 2), day = digits(text, 8, 2);
  const auto hour = digits(text, 11, 2), minute = digits(text, 14, 2), second = digits(text, 17, 2);
  if (!year || !month || !day || !hour || !minute || !second || text.size() < 20 || text[4] != '-' || text[7] != '-' ||
      text[10] != 'T' || text[13] != ':' || text[16] != ':' || text.back() != 'Z')
    return std::nullopt;
  std::tm tm{};
  tm.tm_year = *year - 1900;
  tm.tm_mon = *month - 1;
  tm.tm_mday = *day;
  tm.tm_hour = *hour;
  tm.tm_min = *minute;
  tm.tm_sec = *second;
  const std::time_t seconds = ::timegm(&tm);
  if (seconds < 0) return std::nullopt;
  std::uint64_t fraction_ns = 0;
  std::size_t at = 19;
  if (text[at] == '.') {
    std::uint64_t scale = 100'000'000;
    for (++at; at + 1 < text.size(); ++at) {
      if (text[at] < '0' || text[at] > '9') return std::nullopt;
      fraction_ns += static_cast<std::uint64_t>(text[at] - '0') * scale;
      scale /= 10;
    }
  }
  if (at != text.size() - 1) return std::nullopt;
  return static_cast<std::uint64_t>(seconds) * 1'000'000'000u + fraction_ns;
}

RosTopicEncoder::RosTopicEncoder(RosExportOptions options) : options_(std::move(options)), zones_(options_.zones) {
  if (options_.model) profile_ = &profile_for(*options_.model);
}

void RosTopicEncoder::make_decoder() {
  if (decoder_) return;
  if (!profile_ && metadata_.model) profile_ = find_profile(*metadata_.model);
  if (!profile_) return;
  // The recorded scale belonged to the recorded model: a forced model takes only a forced scale.
  const std::optional<double> scale = options_.distance_scale ? options_.distance_scale
                                      : options_.model        ? std::nullopt
                                                              : metadata_.distance_scale;
  decoder_ =
      std::make_unique<ScanDecoder>(*profile_, recorded_conventions(metadata_, *profile_, options_.reading), scale);
}

void RosTopicEncoder::record(RecordType type, std::span<const std::uint8_t> payload, std::int64_t t_ns,
                             MessageFn emit) {
  switch (type) {
    case RecordType::DeviceToHost: return device_bytes(payload, t_ns, emit);
    case RecordType::HostToDevice: return host_bytes(payload, t_ns, emit);
    case RecordType::Metadata:
      return metadata(RecordingMetadata::parse({reinterpret_cast<const char*>(payload.data()), payload.size()}));
  }
}

void RosTopicEncoder::metadata(const RecordingMetadata& changes) {
  metadata_.merge(changes);
  if (changes.start_wall_time)
    if (const auto ns = parse_iso8601_utc_ns(*changes.start_wall_time)) wall_start_ns_ = *ns;
}

std::uint64_t RosTopicEncoder::log_time(std::int64_t t_ns) const {
  return wall_start_ns_ + static_cast<std::uint64_t>(t_ns < 0 ? 0 : t_ns);
}

void RosTopicEncoder::device_bytes(std::span<const std::uint8_t> bytes, std::int64_t t_ns, MessageFn emit) {
  last_t_ns_ = t_ns;
  last_device_t_ns_ = t_ns;
  if (!seen_bytes_) {
    seen_bytes_ = true;
    next_diagnostics_ns_ = t_ns + kDiagnosticsPeriodNs;
  }
  if (options_.link_bytes) {
    encode_link_bytes(bytes, message_);
    emit(RosTopic::DeviceBytes, log_time(t_ns), message_);
  }
  make_decoder();
  if (decoder_) decoder_->feed(bytes, t_ns, [&](const Lap& lap) { on_lap(lap, emit); });
  maybe_diagnostics(t_ns, emit);
}

void RosTopicEncoder::host_bytes(std::span<const std::uint8_t> bytes, std::int64_t t_ns, MessageFn emit) {
  last_t_ns_ = t_ns;
  commands_.host_bytes(bytes, t_ns);
  if (options_.link_bytes) {
    encode_link_bytes(bytes, message_);
    emit(RosTopic::HostBytes, log_time(t_ns), message_);
  }
  maybe_diagnostics(t_ns, emit);
}

void RosTopicEncoder::finish(MessageFn emit) {
  if (decoder_) decoder_->finish([&](const Lap& lap) { on_lap(lap, emit); });
  if (!seen_bytes_) return;
  encode_diagnostics(diagnostics(), options_.frame.frame_id, log_time(last_t_ns_), message_);
  emit(RosTopic::Diagnostics, log_time(last_t_ns_), message_);
}

void RosTopicEncoder::idle(std::int64_t t_ns, MessageFn emit) {
  if (!link_down() || t_ns <= last_t_ns_) return;
  last_t_ns_ = t_ns;
  maybe_diagnostics(t_ns, emit);
}

bool RosTopicEncoder::link_down() const {
  const auto it = metadata_.extra.find("link_fault");  // core/session/link_outage.h writes it
  return it != metadata_.extra.end() && !it->second.empty();
}

void RosTopicEncoder::on_lap(const Lap& decoded, MessageFn emit) {
  ++laps_;
  if (decoded.scan_hz && decoded.ct_info_trusted()) reported_scan_hz_ = decoded.scan_hz;
  if (!window_first_close_ns_) window_first_close_ns_ = decoded.last_rx_ns;
  window_last_close_ns_ = decoded.last_rx_ns;
  ++window_laps_;
  commands_.lap_closed(decoded.last_rx_ns);
  dropouts_.add_lap(decoded);
  zones_.set_pose(metadata_.pose.value_or(Pose{}));
  const bool zone_news = !zones_.add_lap(decoded).empty();
  // Stamped at the first ray (REP-117), logged when the lap was complete: at its closing byte.
  const ScanTimes times = scan_times(decoded, static_cast<std::int64_t>(wall_start_ns_));
  const std::uint64_t logged = log_time(decoded.last_rx_ns);

  const Lap* lap = &decoded;
  if (options_.filter.any()) {
    filtered_.points = decoded.points;
    filter_interference(filtered_, options_.filter);
    lap = &filtered_;
  }
  encode_laser_scan(*lap, options_.frame, range_limits(profile_->model), times, scan_scratch_, message_);
  emit(RosTopic::Scan, logged, message_);
  encode_point_cloud(*lap, options_.frame, profile_->flag_bits > 0, times.stamp_ns, message_);
  emit(RosTopic::Points, logged, message_);
  if (zone_news) emit_zones(logged, emit);  // an entry or exit is news now, not at the next report
}

void RosTopicEncoder::emit_zones(std::uint64_t log_time_ns, MessageFn emit) {
  if (zones_.zones().empty()) return;
  const std::vector<DiagnosticReport> reports =
      zone_reports(zones_, options_.frame.frame_id, metadata_.port.value_or(metadata_.serial.value_or("")));
  encode_diagnostics(reports, options_.frame.frame_id, log_time_ns, message_);
  emit(RosTopic::Zones, log_time_ns, message_);
}

void RosTopicEncoder::maybe_diagnostics(std::int64_t t_ns, MessageFn emit) {
  if (t_ns < next_diagnostics_ns_) return;
  next_diagnostics_ns_ = t_ns + kDiagnosticsPeriodNs;
  // Laps closed in the window since the last report: (n - 1) intervals between n closes.
  if (window_laps_ >= 2 && window_last_close_ns_ > *window_first_close_ns_)
    measured_scan_hz_ = static_cast<double>(window_laps_ - 1) * 1e9 /
                        static_cast<double>(window_last_close_ns_ - *window_first_close_ns_);
  else if (window_laps_ == 0)
    measured_scan_hz_.reset();
  window_first_close_ns_.reset();
  window_laps_ = 0;
  count_recent_errors(t_ns);
  std::vector<DiagnosticReport> reports{diagnostics()};
  if (!zones_.zones().empty()) {
    std::vector<DiagnosticReport> zones = zone_reports(zones_, options_.frame.frame_id, reports[0].hardware_id);
    reports.insert(reports.end(), zones.begin(), zones.end());
  }
  encode_diagnostics(reports, options_.frame.frame_id, log_time(t_ns), message_);
  emit(RosTopic::Diagnostics, log_time(t_ns), message_);
  emit_zones(log_time(t_ns), emit);
}

void RosTopicEncoder::count_recent_errors(std::int64_t t_ns) {
  const auto c = counters();
  if (!c) return;
  error_samples_.push_back({t_ns, c->checksum_errors, c->crc_mismatches});
  // Keep one sample at or before the window's start: the errors since it are the recent ones.
  while (error_samples_.size() >= 2 && error_samples_[1].t_ns <= t_ns - kConditionWindowNs) error_samples_.pop_front();
  const bool whole_window = error_samples_.front().t_ns <= t_ns - kConditionWindowNs;
  const ErrorSample before = whole_window ? error_samples_.front() : ErrorSample{0, 0, 0};
  recent_checksum_errors_ = c->checksum_errors - before.checksum_errors;
  recent_crc_mismatches_ = c->crc_mismatches - before.crc_mismatches;
}

std::optional<DecoderCounters> RosTopicEncoder::counters() const {
  if (!decoder_) return std::nullopt;
  return decoder_->counters();
}

DiagnosticReport RosTopicEncoder::diagnostics() const {
  DiagnosticReport report;
  const auto extra = [this](const char* key) -> std::optional<std::string> {
    const auto it = metadata_.extra.find(key);
    if (it == metadata_.extra.end()) return std::nullopt;
    return it->second;
  };
  const std::string model = profile_ ? std::string(profile_->name) : metadata_.model.value_or("unknown model");
  // Keyed by what is known from the first report on and never changes: the lidar's name (its
  // frame) and its port. A name from the model or serial would file the reports before the
  // device info came under a lidar of their own ("unknown model lidar").
  report.name = "ydscope: " + options_.frame.frame_id;
  report.hardware_id = metadata_.port.value_or(metadata_.serial.value_or(""));
  const auto health = extra("health");
  LidarCondition condition;
  if (link_down()) {
    condition.link_fault = extra("link_fault");
    if (last_device_t_ns_) condition.quiet_ns = last_t_ns_ - *last_device_t_ns_;
  }
  condition.health = health;
  condition.recent_checksum_errors = recent_checksum_errors_;
  condition.recent_crc_mismatches = recent_crc_mismatches_;
  condition.no_recent_lap = !measured_scan_hz_ && seen_bytes_ && profile_;
  condition.settling = commands_.settling(last_t_ns_);
  const std::vector<BlockedSector> blocked = dropouts_.blocked();
  for (const BlockedSector& sector : blocked) condition.blocked_sectors.push_back(describe_blocked_sector(sector));
  const LidarVerdict verdict = judge_lidar(condition);
  report.level = verdict.level;
  report.message = verdict.message;
  const auto c = counters();
  auto& v = report.values;
  v.emplace_back("model", model);
  if (metadata_.model_code) v.emplace_back("model_code", std::to_string(*metadata_.model_code));
  if (metadata_.firmware) v.emplace_back("firmware", *metadata_.firmware);
  if (metadata_.hardware) v.emplace_back("hardware", std::to_string(*metadata_.hardware));
  if (metadata_.serial) v.emplace_back("serial", *metadata_.serial);
  if (metadata_.port) v.emplace_back("port", *metadata_.port);
  v.emplace_back("health", health.value_or("unknown"));
  v.emplace_back("scan_hz_set", extra("scan_hz").value_or("unknown"));
  v.emplace_back("scan_hz_measured", measured_scan_hz_ ? fixed(*measured_scan_hz_, 2) : "none");
  if (reported_scan_hz_) v.emplace_back("scan_hz_reported", fixed(*reported_scan_hz_, 1));
  v.emplace_back("ranging_khz", extra("ranging_khz").value_or("unknown"));
  if (const auto pdp = extra("power_down_protection")) v.emplace_back("power_down_protection", *pdp);
  if (decoder_) {
    v.emplace_back("distance_scale_mm", fixed(decoder_->distance_scale(), 4));
    v.emplace_back("conventions", std::string(decoder_->conventions().id));
  }
  v.emplace_back("laps", std::to_string(laps_));
  v.emplace_back("blocked_sectors", blocked.empty() ? "none" : describe_blocked_sectors(blocked));
  if (c) {
    v.emplace_back("packets", std::to_string(c->packets));
    v.emplace_back("checksum_errors", std::to_string(c->checksum_errors));
    if (profile_ && profile_->last_crc_before_zero) {
      v.emplace_back("crc8_ok", std::to_string(c->crc_ok));
      v.emplace_back("crc8_mismatches", std::to_string(c->crc_mismatches));
    }
    v.emplace_back("resync_bytes", std::to_string(c->resync_bytes));
    v.emplace_back("discarded_packets", std::to_string(c->discarded_packets));
    v.emplace_back("overflow_points", std::to_string(c->overflow_points));
  }
  for (const auto& kv : extra_) v.push_back(kv);
  return report;
}

}  // namespace ydscope
