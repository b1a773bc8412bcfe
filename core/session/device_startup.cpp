#include "core/session/device_startup.h"

#include <algorithm>
#include <vector>

#include "core/session/device_probe.h"
#include "core/session/device_settings.h"
#include "core/link/link_address.h"
#include "core/session/recorded_device.h"
#include "core/record/recorded_conventions.h"

namespace ydscope {

namespace {

std::string baud_list(const std::vector<std::uint32_t>& bauds) {
  std::string text;
  for (std::size_t i = 0; i < bauds.size(); ++i) text += (i ? ", " : "") + std::to_string(bauds[i]);
  return text;
}

std::vector<std::uint32_t> candidate_bauds(const SessionConfig& config) {
  std::vector<std::uint32_t> bauds;
  const auto add = [&](std::uint32_t baud) {
    if (std::find(bauds.begin(), bauds.end(), baud) == bauds.end()) bauds.push_back(baud);
  };
  if (config.baud) add(*config.baud);
  if (config.probe_baud) {
    for (const auto baud : kProbeBauds) add(baud);
  } else if (!config.baud) {
    if (config.model) {
      add(profile_for(*config.model).default_baud);
    } else {  // unknown model: the default bauds of every model
      for (const auto& profile : all_profiles()) add(profile.default_baud);
    }
  }
  return bauds;
}

void post_link(const StartupParts& parts, std::uint32_t baud) {
  const std::string text = parts.link.link() ? parts.link.link()->describe() : std::string();
  parts.board.publish([&](SessionSnapshot& s) {
    s.link = text;
    s.baud = baud;
  });
}

// A replay: decode what comes with the configured model, and show the recorded device.
StartupOutcome start_replay(const StartupParts& parts, const SessionConfig& config) {
  StartupOutcome outcome;
  outcome.ok = true;
  outcome.accepts_commands = false;
  outcome.profile = &profile_for(config.model.value_or(Model::G6));
  DeviceDetails device;
  device.profile = outcome.profile;
  const RecordingMetadata* recorded = parts.link.link()->recording_metadata();
  if (recorded) device = recorded_device(*recorded, *outcome.profile);
  // Kept for a later switch of reading (Session::set_reading): an old TG's firmware still counts.
  if (recorded) outcome.sdk_firmware = recorded_sdk_firmware(*recorded);
  outcome.conventions =
      &recorded_conventions(recorded ? *recorded : RecordingMetadata{}, *outcome.profile, config.reading);
  parts.board.publish([&device](SessionSnapshot& s) { s.device = device; });
  return outcome;
}

// The model bytes at `baud` should come from: the one asked for, else the one whose baud it is.
const ModelProfile& expected_at(const SessionConfig& config, std::uint32_t baud) {
  if (config.model) return profile_for(*config.model);
  return profile_for(baud == profile_for(Model::G1).default_baud ? Model::G1 : Model::G6);
}

// The first baud at which the device answers A5 90, with its answer; an error when none does.
boost::asio::awaitable<std::optional<DeviceInfo>> find_device(const StartupParts& parts, const SessionConfig& config,
                                                              const std::vector<std::uint32_t>& bauds,
                                                              std::uint32_t& baud, std::string& error) {
  Step<DeviceInfo> info;
  std::string bytes_say;  // why bytes that came made no sense, at the last baud they came at
  for (std::size_t i = 0; i < bauds.size(); ++i) {
    if (parts.cancelled()) co_return std::nullopt;
    if (i > 0) {
      if (!parts.link.link()->set_baud(bauds[i], error)) co_return std::nullopt;
      post_link(parts, bauds[i]);
    }
    parts.link.forget_unsolicited();
    co_await parts.sequencer.pause_scan(true);  // a device left scanning answers nothing else
    info = co_await parts.sequencer.device_info();
    if (info.ok()) {
      baud = bauds[i];
      co_return info.value;
    }
    if (const auto why = parts.link.unsolicited().verdict(expected_at(config, bauds[i]), bauds[i])) bytes_say = *why;
    if (info.link_lost) break;
  }
  if (!bytes_say.empty() && !info.link_lost)
    error = "no device-info reply (A5 90) on " + config.address + "; " + bytes_say;
  else if (bauds.size() > 1 && !info.link_lost)
    error = "no device-info reply (A5 90) at any of " + baud_list(bauds) + " baud on " + config.address +
            ": is it a G1, G6 or TG lidar, powered, on this port?";
  else
    error = info.error;
  co_return std::nullopt;
}

}  // namespace

boost::asio::awaitable<StartupOutcome> start_device(const StartupParts& parts, const SessionConfig& config,
                                                    const DeviceSettings& wanted) {
  StartupOutcome outcome;
  parts.board.set_state(LinkState::Connecting, "opening " + config.address);
  const std::vector<std::uint32_t> bauds = candidate_bauds(config);
  std::unique_ptr<ByteLink> opened;
  if (config.open_link)
    opened = config.open_link(parts.io, bauds.front(), outcome.error);
  else
    opened = co_await open_byte_link(parts.io, config.address, bauds.front(), outcome.error);
  if (!opened) {
    if (outcome.error.empty()) outcome.error = "cannot open " + config.address;
    co_return outcome;
  }
  const bool commands = opened->accepts_commands();
  parts.link.attach(std::move(opened));
  post_link(parts, bauds.front());
  if (!commands) co_return start_replay(parts, config);

  parts.board.set_state(LinkState::Probing, "asking " + parts.link.link()->describe() + " for its device info");
  parts.sequencer.reset_device();
  std::uint32_t baud = bauds.front();
  const std::optional<DeviceInfo> info = co_await find_device(parts, config, bauds, baud, outcome.error);
  if (!info) co_return outcome;
  outcome.profile = choose_profile(config.model, info->model_code, outcome.note);
  if (!outcome.profile) {
    outcome.error = outcome.note;
    co_return outcome;
  }
  const DeviceDetails details = make_device_details(*info, *outcome.profile);
  outcome.sdk_firmware = firmware_as_sdk_reads(info->firmware_major, info->firmware_minor);
  outcome.conventions =
      &conventions_for(*outcome.profile, outcome.sdk_firmware, config.reading.value_or(Reading::Field));
  parts.board.publish([&](SessionSnapshot& s) {
    s.device = details;
    s.baud = baud;
  });

  // The rest is informative: a model without an answer still scans, unless the link went.
  const auto lost = [&outcome](const auto& step) {
    if (step.link_lost) outcome.error = step.error;
    return step.link_lost;
  };
  const auto health = co_await parts.sequencer.health(*outcome.profile);
  if (lost(health)) co_return outcome;
  const auto scan_hz = co_await parts.sequencer.scan_hz();
  if (lost(scan_hz)) co_return outcome;
  const auto ranging = co_await parts.sequencer.ranging_khz(*outcome.profile);
  if (lost(ranging)) co_return outcome;
  // Before the values are posted, so nobody is told the power-on ones in between.
  const RestoredSettings restored =
      co_await restore_settings(parts.sequencer, *outcome.profile, wanted, scan_hz.value, ranging.value);
  if (!restored.link_error.empty()) {
    outcome.error = restored.link_error;
    co_return outcome;
  }
  outcome.settings_note = restored.said;
  outcome.power_down_protection = restored.in_force.power_down_protection.value_or(false);
  const std::optional<double> scan_hz_now = restored.in_force.scan_hz ? restored.in_force.scan_hz : scan_hz.value;
  const std::optional<std::uint16_t> ranging_now =
      restored.in_force.ranging_khz ? restored.in_force.ranging_khz : ranging.value;
  parts.board.publish([&](SessionSnapshot& s) {
    s.health = health.value;
    s.scan_hz = scan_hz_now;
    s.ranging_khz = ranging_now;
    s.power_down_protection = outcome.power_down_protection;
  });
  if (!health.ok() && outcome.note.empty()) outcome.note = "health: " + health.error;
  outcome.ok = true;
  co_return outcome;
}

}  // namespace ydscope
