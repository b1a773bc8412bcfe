#pragma once
// What the view must say about the data it shows, so a frozen picture never passes for a live one:
// from the link state, the source and the age of the newest lap to "dim the cloud and say why".
// Plain code, tested without a display; the app draws the result (ui/panels/view_header.cpp).
#include <optional>
#include <string>
#include <string_view>

#include "core/link/link_state.h"

namespace ydscope::ui {

enum class Severity { Ok, Info, Warning, Error };

struct ViewStateInput {
  LinkState state = LinkState::Idle;
  std::string_view link_message;  // the session's sentence for the state
  std::string_view address;       // what the link opens: "/dev/ttyUSB0", "recording demo.ydrec"
  bool has_source = false;        // false: nothing chosen yet, or after Disconnect
  bool replay = false;            // the source is a recording
  bool replay_paused = false;
  // Seconds since the newest lap arrived; empty when none has arrived from this source.
  std::optional<double> seconds_since_lap;
};

// Laps older than this while "scanning" mean the stream stopped, whatever the link thinks.
inline constexpr double kStaleLapSeconds = 1.5;

struct ViewState {
  bool live = false;       // laps are arriving: full brightness, no overlay
  bool dim = false;        // the cloud is old or absent: dim it and show the overlay
  Severity severity = Severity::Ok;
  std::string headline;    // large: "No data"
  std::string subtitle;    // "reconnecting to /dev/ttyUSB0, last lap 12 s ago"
  std::string detail;      // the session's own sentence, smaller
  std::string status;      // one word or two for the status line: "scanning", "no data"
};

ViewState describe_view_state(const ViewStateInput& in);

// "4 s", "2 min 5 s", "1 h 3 min": short enough for an overlay.
std::string format_age(double seconds);

}  // namespace ydscope::ui
