#pragma once
// What the view must say about the data it shows, so a frozen picture never passes for a live one:
// from the link state, the source and the age of the newest lap to "dim the cloud and say why".
// Plain code, tested without a display; the app draws the result (ui/panels/view_overlay.cpp).
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/snapshot/link_state.h"
#include "core/protocol/no_lap_reason.h"

namespace ydscope::ui {

enum class Severity { Ok, Info, Warning, Error };

struct ViewStateInput {
  LinkState state = LinkState::Idle;
  std::string_view link_message;  // the session's sentence for the state
  std::string_view address;       // what the link opens: "/dev/ttyUSB0", "recording demo.ydrec"
  bool has_source = false;        // false: nothing chosen yet, after Disconnect, or it did not start
  std::string_view start_error;   // why the chosen source did not start (has_source is then false)
  bool replay = false;            // the source is (or was to be) a recording
  bool replay_paused = false;
  std::uint64_t replay_passes = 0;  // times the replay went round to its start (loop)
  std::string_view model;           // the model the bytes are decoded as: "G6"
  LaplessCounts decoded;            // what the decoder counted so far: why no lap came, if none did
  // What is wrong with the source but does not stop it, one sentence each (a recording cut off
  // at its end): said whatever the state, since a live picture may rest on damaged data.
  std::span<const std::string> source_warnings;
  // Seconds since the newest lap arrived; empty when none has arrived from this source.
  std::optional<double> seconds_since_lap;
};

// Laps older than this while "scanning" mean the stream stopped, whatever the link thinks.
inline constexpr double kStaleLapSeconds = 1.5;

struct ViewState {
  bool live = false;  // laps are arriving: full brightness, no overlay
  bool dim = false;   // the cloud is old or absent: dim it and show the overlay
  Severity severity = Severity::Ok;
  std::string headline;              // large: "No data"
  std::string subtitle;              // "reconnecting to /dev/ttyUSB0, last lap 12 s ago"
  std::string detail;                // the session's own sentence, smaller
  std::string status;                // one word or two for the status line: "scanning", "no data"
  std::vector<std::string> notices;  // the source's warnings, a line each beside the status line
  bool give_up = false;              // going on cannot show anything (a replay without a lap in a whole pass)
};

ViewState describe_view_state(const ViewStateInput& in);

// "4 s", "2 min 5 s", "1 h 3 min": short enough for an overlay.
std::string format_age(double seconds);

}  // namespace ydscope::ui
