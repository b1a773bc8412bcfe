#include "core/session/command_sequencer.h"

#include <cmath>
#include <span>

#include "core/session/device_probe.h"

namespace ydscope {

namespace asio = boost::asio;

void CommandSequencer::configure(std::chrono::milliseconds reply_timeout, int attempts) {
  reply_timeout_ = reply_timeout;
  attempts_ = attempts < 1 ? 1 : attempts;
}

std::string CommandSequencer::link_text() {
  return io_.link() ? io_.link()->describe() : std::string("the closed link");
}

asio::awaitable<bool> CommandSequencer::pause_scan(bool force) {
  const bool was_scanning = io_.device_scanning();
  if (!was_scanning && !force) co_return false;
  io_.stop_stream();
  io_.send(Command::Stop);
  co_await io_.drain(kDrainQuiet, kDrainLimit);
  co_return was_scanning;
}

bool CommandSequencer::resume_scan(bool was_scanning) {
  if (!was_scanning) return true;
  return io_.start_stream();
}

asio::awaitable<Step<Exchange>> CommandSequencer::command(Command command) {
  Step<Exchange> step;
  Exchange last;
  for (int attempt = 0; attempt < attempts_; ++attempt) {
    if (attempt > 0) co_await io_.drain(kDrainQuiet, kDrainLimit);  // let a late answer pass first
    last = co_await io_.exchange(command, reply_timeout_);
    if (last.ok()) {
      step.value = last;
      co_return step;
    }
    if (last.outcome == Exchange::Outcome::LinkLost) {
      step.link_lost = true;
      step.error =
          io_.fault().empty() ? "the link closed while waiting for " + command_bytes_text(command) : io_.fault();
      co_return step;
    }
    if (last.outcome == Exchange::Outcome::Refused) {
      step.error = "refused to send " + command_bytes_text(command) + " while the device is scanning (a ydscope bug)";
      co_return step;
    }
  }
  step.error = no_reply_sentence(command, reply_timeout_, link_text(), last.bytes_seen);
  co_return step;
}

template <class T, class Parse>
asio::awaitable<Step<T>> CommandSequencer::query(Command query_command, Parse parse, std::string what,
                                                 std::string wrong) {
  const Step<Exchange> reply = co_await command(query_command);
  if (!reply.ok()) co_return failure_of<T>(reply);
  Step<T> step;
  step.value = parse(reply.value->bytes());
  if (!step.value) step.error = "the " + what + " reply on " + link_text() + " " + wrong;
  co_return step;
}

asio::awaitable<Step<DeviceInfo>> CommandSequencer::device_info() {
  return query<DeviceInfo>(Command::DeviceInfo, &parse_device_info, "device-info", "has the wrong size");
}

asio::awaitable<Step<HealthReport>> CommandSequencer::health(const ModelProfile& profile) {
  Step<HealthReport> step;
  const Command first = health_command_.value_or(profile.health_command);
  const Command other = first == Command::HealthStatusCode ? Command::HealthStatusBits : Command::HealthStatusCode;
  std::string first_error;
  for (const Command candidate : {first, other}) {
    auto reply = co_await command(candidate);
    if (reply.link_lost) {
      step.link_lost = true;
      step.error = reply.error;
      co_return step;
    }
    if (reply.ok()) {
      if (const auto health = parse_health(reply.value->bytes())) {
        health_command_ = candidate;
        step.value = make_health_report(candidate, *health);
        co_return step;
      }
    }
    if (first_error.empty()) first_error = reply.error;
  }
  step.error = first_error + " (the other health command " + command_bytes_text(other) + " did not answer either)";
  co_return step;
}

asio::awaitable<Step<double>> CommandSequencer::scan_hz() {
  const auto hz = [](std::span<const std::uint8_t> bytes) -> std::optional<double> {
    const auto frequency = parse_scan_frequency(bytes);
    return frequency ? std::optional(frequency->hz()) : std::nullopt;
  };
  return query<double>(Command::ScanHzGet, hz, "scan-frequency", "has the wrong size");
}

asio::awaitable<Step<double>> CommandSequencer::step_scan_hz(const ModelProfile& profile, double target_hz) {
  Step<double> step;
  if (!(target_hz >= profile.min_scan_hz - 1e-9 && target_hz <= profile.max_scan_hz + 1e-9)) {
    step.error = "scan frequency " + hz_text(target_hz) + " is outside " + std::string(profile.name) + "'s " +
                 hz_text(profile.min_scan_hz) + " to " + hz_text(profile.max_scan_hz);
    co_return step;
  }
  step = co_await scan_hz();
  if (!step.ok()) co_return step;
  double current = *step.value;
  for (int i = 0; i < kMaxScanHzSteps; ++i) {
    const auto next = next_scan_hz_step(current, target_hz);
    if (!next) break;
    auto reply = co_await command(*next);
    if (!reply.ok()) co_return failure_of<double>(reply);
    const auto answered = parse_scan_frequency(reply.value->bytes());
    if (!answered) break;
    if (std::lround(answered->hz() * 100) == std::lround(current * 100)) break;  // the device stopped moving
    current = answered->hz();
  }
  // The read-back is the truth, whatever the step answers said.
  step = co_await scan_hz();
  if (step.ok() && next_scan_hz_step(*step.value, target_hz)) {
    step.error = "the scan frequency reads back " + hz_text(*step.value) + ", not the target " + hz_text(target_hz) +
                 " (the device stopped short)";
  }
  co_return step;
}

asio::awaitable<Step<std::uint16_t>> CommandSequencer::ranging_khz(const ModelProfile& profile) {
  const auto khz = [&profile](std::span<const std::uint8_t> bytes) { return parse_ranging_khz(profile, bytes); };
  return query<std::uint16_t>(Command::RangingGet, khz, "ranging-frequency",
                              "is not in " + std::string(profile.name) + "'s table");
}

asio::awaitable<Step<std::uint16_t>> CommandSequencer::cycle_ranging_to(const ModelProfile& profile,
                                                                        std::uint16_t target_khz) {
  Step<std::uint16_t> step;
  if (!profile.ranging_index(target_khz)) {
    std::string table;
    for (const auto khz : profile.ranging_khz) table += (table.empty() ? "" : ", ") + std::to_string(khz);
    step.error = std::to_string(target_khz) + " kHz is not a ranging frequency of " + std::string(profile.name) + " (" +
                 table + " kHz)";
    co_return step;
  }
  if (!profile.ranging_settable) {
    step.error = std::string(profile.name) + " has no command to set the ranging frequency (it is read-only)";
    co_return step;
  }
  step = co_await ranging_khz(profile);
  // One cycle per table entry reaches any value; one more tolerates a slow first answer.
  for (std::size_t i = 0; step.ok() && *step.value != target_khz && i <= profile.ranging_khz.size(); ++i) {
    auto reply = co_await command(Command::RangingCycle);
    if (!reply.ok()) co_return failure_of<std::uint16_t>(reply);
    step = co_await ranging_khz(profile);
  }
  if (step.ok() && *step.value != target_khz)
    step.error = "the ranging frequency reads back " + std::to_string(*step.value) + " kHz after cycling, not " +
                 std::to_string(target_khz) + " kHz";
  co_return step;
}

asio::awaitable<Step<bool>> CommandSequencer::power_down_protection(bool on) {
  Step<bool> step;
  for (int toggle = 0; toggle < 2; ++toggle) {
    auto reply = co_await command(Command::PowerDownProtection);
    if (!reply.ok()) co_return failure_of<bool>(reply);
    step.value = parse_power_down_protection(reply.value->bytes());
    if (!step.value) {
      step.error = "the power-down protection reply on " + link_text() + " is not 00 or 01";
      co_return step;
    }
    if (*step.value == on) co_return step;
  }
  step.error = std::string("power-down protection stays ") + (*step.value ? "on" : "off") + " after two toggles";
  co_return step;
}

}  // namespace ydscope
