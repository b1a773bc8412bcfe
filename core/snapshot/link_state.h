#pragma once
// Where the device link stands, as the UI and the CLI show it. The I/O thread moves between these;
// every state comes with a sentence (SessionSnapshot::message) a user can act on.
#include <cstdint>
#include <string_view>

namespace ydscope {

enum class LinkState : std::uint8_t {
  Idle,               // no connection asked for
  Connecting,         // opening the port
  Probing,            // stop, drain, device info, health, frequencies (and baud probing)
  Ready,              // connected and answering, not scanning (info / set without a scan)
  Scanning,           // laps are flowing
  CommandInProgress,  // a scan was interrupted for a command (stop, drain, command, resume)
  Stalled,            // scanning but no byte for the stall timeout; about to reconnect
  Reconnecting,       // waiting out the backoff before the next attempt
  Failed,             // gave up (reconnect off); the message says why
};

constexpr std::string_view link_state_name(LinkState state) {
  switch (state) {
    case LinkState::Idle: return "idle";
    case LinkState::Connecting: return "connecting";
    case LinkState::Probing: return "probing";
    case LinkState::Ready: return "ready";
    case LinkState::Scanning: return "scanning";
    case LinkState::CommandInProgress: return "command in progress";
    case LinkState::Stalled: return "stalled";
    case LinkState::Reconnecting: return "reconnecting";
    case LinkState::Failed: return "failed";
  }
  return "unknown";
}

// True while the session holds an open port.
constexpr bool link_state_connected(LinkState state) {
  return state == LinkState::Probing || state == LinkState::Ready || state == LinkState::Scanning ||
         state == LinkState::CommandInProgress || state == LinkState::Stalled;
}

}  // namespace ydscope
