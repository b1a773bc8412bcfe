#include "core/session/device_settings.h"

#include <cmath>

#include "core/session/device_probe.h"

namespace ydscope {

namespace {

// "a, b" joined into one sentence's part.
void add(std::string& list, const std::string& item) { list += (list.empty() ? "" : ", ") + item; }

}  // namespace

boost::asio::awaitable<RestoredSettings> restore_settings(CommandSequencer& sequencer, const ModelProfile& profile,
                                                          const DeviceSettings& wanted, std::optional<double> scan_hz,
                                                          std::optional<std::uint16_t> ranging_khz) {
  RestoredSettings restored;
  std::string applied;
  std::string failed;
  // Each setting's step: the value read back on success, else why not.
  const auto settle = [&](const auto& step, const std::string& what, auto& in_force) {
    if (step.link_lost) restored.link_error = step.error;
    if (step.value) in_force = step.value;  // a unit that stopped short is where it stopped
    if (step.ok()) {
      add(applied, what);
    } else {
      add(failed, what + " (" + step.error + ")");
    }
  };
  if (wanted.scan_hz) {
    const std::string what = "scan " + hz_text(*wanted.scan_hz);
    if (scan_hz && std::lround(*scan_hz * 100) == std::lround(*wanted.scan_hz * 100)) {
      restored.in_force.scan_hz = scan_hz;
      add(applied, what);
    } else {
      settle(co_await sequencer.step_scan_hz(profile, *wanted.scan_hz), what, restored.in_force.scan_hz);
      if (!restored.link_error.empty()) co_return restored;
    }
  }
  if (wanted.ranging_khz) {
    const std::string what = "ranging " + std::to_string(*wanted.ranging_khz) + " kHz";
    if (ranging_khz == wanted.ranging_khz) {
      restored.in_force.ranging_khz = ranging_khz;
      add(applied, what);
    } else {
      settle(co_await sequencer.cycle_ranging_to(profile, *wanted.ranging_khz), what, restored.in_force.ranging_khz);
      if (!restored.link_error.empty()) co_return restored;
    }
  }
  // Only "on" needs a command: the protection is off after power-on, and A5 D9 can only toggle.
  if (wanted.power_down_protection.value_or(false)) {
    settle(co_await sequencer.power_down_protection(true), "power-down protection on",
           restored.in_force.power_down_protection);
    if (!restored.link_error.empty()) co_return restored;
  }
  if (!applied.empty()) restored.said = "re-applied " + applied;
  if (!failed.empty())
    restored.said += (restored.said.empty() ? "" : "; ") + std::string("could not re-apply ") + failed;
  co_return restored;
}

}  // namespace ydscope
