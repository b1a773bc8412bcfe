#pragma once
// The settings a user gave a lidar (scan frequency, ranging frequency, power-down protection),
// kept by the session so that a unit which lost power (a replugged cable) is set back to them
// before its scan resumes, instead of silently running at its power-on values. I/O thread only.
#include <cstdint>
#include <optional>
#include <string>
#include <utility>  // before asio's awaitable.hpp, which uses std::exchange without including it

#include <boost/asio/awaitable.hpp>

#include "core/session/command_sequencer.h"

namespace ydscope {

// What the user last set successfully; empty: never set (the unit's own value stands).
struct DeviceSettings {
  std::optional<double> scan_hz;
  std::optional<std::uint16_t> ranging_khz;
  std::optional<bool> power_down_protection;
  bool any() const { return scan_hz || ranging_khz || power_down_protection; }
};

// The outcome of putting them back on a freshly started unit.
struct RestoredSettings {
  DeviceSettings in_force;  // the values read back after re-applying (those re-applied)
  // "re-applied scan 10.00 Hz, ranging 18 kHz" and/or "could not re-apply ranging 18 kHz: why";
  // empty when there was nothing to re-apply.
  std::string said;
  std::string link_error;  // the link went on the way: the start-up fails with this
};

// Re-applies each of `wanted` that the unit does not already hold (`scan_hz` and `ranging_khz`
// as it reads them now, `power_down_protection` as it is after power-on: off, per the manuals).
// The unit must be stopped.
boost::asio::awaitable<RestoredSettings> restore_settings(CommandSequencer& sequencer, const ModelProfile& profile,
                                                          const DeviceSettings& wanted, std::optional<double> scan_hz,
                                                          std::optional<std::uint16_t> ranging_khz);

}  // namespace ydscope
