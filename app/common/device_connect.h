#pragma once
// Connecting a Session and waiting until the device is Ready (or Scanning), for the programs that
// run one job on one unit and then stop: the CLI's commands and the app's "Run check".
#include <chrono>

#include "core/session/session.h"

namespace ydscope {

// Baud probing at 4 rates with retries and start-up commands stays well inside this.
inline constexpr std::chrono::seconds kConnectPatience{60};

// Connects and waits for the device to be Ready (or Scanning when config.scan); throws
// std::runtime_error with the session's sentence when it fails. A snapshot's non-empty message
// on success explains something odd on the way (a forced model the device disagrees with, a
// health question it did not answer): the caller shows it as a warning.
SessionSnapshot connect_and_wait(Session& session, const SessionConfig& config);

}  // namespace ydscope
