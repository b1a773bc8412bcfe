#pragma once
// Start-up on a fresh connection, in the order the manuals give: open the link; find the baud at
// which the device answers device info (A5 90) and the model profile that goes with its answer;
// then read health, the set scan frequency and the ranging frequency, and put back the settings
// the user gave it (device_settings.h): a unit that lost power is back at its power-on values.
// Only device info is required: a device that does not answer the rest still scans. A replay
// asks nothing and takes the device from its recording. What it learns is posted as it learns
// it; the Session then starts the stream. I/O thread only.
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <utility>  // before asio's awaitable.hpp, which uses std::exchange without including it

#include <boost/asio/awaitable.hpp>
#include <boost/asio/io_context.hpp>

#include "core/session/command_sequencer.h"
#include "core/session/device_settings.h"
#include "core/session/session.h"
#include "core/session/session_io.h"
#include "core/session/snapshot_board.h"

namespace ydscope {

struct StartupOutcome {
  bool ok = false;
  std::string error;          // when not ok: one sentence saying what failed and what to try
  std::string note;           // when ok: what the user should know (the model guessed, health unreadable)
  std::string settings_note;  // when ok: the user's settings re-applied, or why not (RestoredSettings::said)
  const ModelProfile* profile = nullptr;
  const UnitConventions* conventions = nullptr;  // how its bytes are read
  std::optional<FirmwareVersion> sdk_firmware;   // as the vendor SDK reads A5 90's bytes
  bool accepts_commands = true;                  // false for a replay: it is decoded, never commanded
  // As re-applied, else off: the manuals' power-on default (A5 D9 only toggles; it cannot be read).
  std::optional<bool> power_down_protection;
};

struct StartupParts {
  boost::asio::io_context& io;
  SessionIo& link;  // the opened link is attached here
  CommandSequencer& sequencer;
  SnapshotBoard& board;             // the state, link, baud, device and set values, as they are learned
  std::function<bool()> cancelled;  // a disconnect was asked for
};

boost::asio::awaitable<StartupOutcome> start_device(const StartupParts& parts, const SessionConfig& config,
                                                    const DeviceSettings& wanted);

}  // namespace ydscope
