#include "ui/view/view_state.h"

#include <cmath>
#include <cstdio>

namespace ydscope::ui {

std::string format_age(double seconds) {
  const long s = std::lround(std::max(seconds, 0.0));
  char text[32];
  if (s < 60) std::snprintf(text, sizeof text, "%ld s", s);
  else if (s < 3600) std::snprintf(text, sizeof text, "%ld min %ld s", s / 60, s % 60);
  else std::snprintf(text, sizeof text, "%ld h %ld min", s / 3600, (s % 3600) / 60);
  return text;
}

namespace {

std::string last_lap_text(const std::optional<double>& age) {
  return age ? "last lap " + format_age(*age) + " ago" : "no lap yet from this source";
}

ViewState no_data(Severity severity, std::string subtitle, const ViewStateInput& in, std::string status) {
  ViewState v;
  v.dim = true;
  v.severity = severity;
  v.headline = "No data";
  v.subtitle = std::move(subtitle) + ", " + last_lap_text(in.seconds_since_lap);
  v.detail = std::string(in.link_message);
  v.status = std::move(status);
  return v;
}

}  // namespace

ViewState describe_view_state(const ViewStateInput& in) {
  const std::string where(in.address.empty() ? std::string_view("the lidar") : in.address);
  const bool fresh = in.seconds_since_lap && *in.seconds_since_lap <= kStaleLapSeconds;

  if (!in.has_source) {
    ViewState v;
    v.dim = true;
    v.severity = Severity::Info;
    v.headline = "Disconnected";
    v.subtitle = "choose a port, the virtual lidar or a recording in the Connection panel";
    v.status = "disconnected";
    return v;
  }
  if (in.replay && in.replay_paused) {
    ViewState v;
    v.dim = true;
    v.severity = Severity::Info;
    v.headline = "Replay paused";
    v.subtitle = where + ", press Play to go on";
    v.status = "replay paused";
    return v;
  }
  switch (in.state) {
    case LinkState::Scanning:
    case LinkState::CommandInProgress:
      // A command stops the scan for a moment; only a long gap is news.
      if (fresh) {
        ViewState v;
        v.live = true;
        v.status = in.state == LinkState::Scanning ? "scanning" : "command in progress";
        return v;
      }
      if (!in.seconds_since_lap) return no_data(Severity::Info, "waiting for the first lap from " + where, in, "waiting");
      return no_data(Severity::Warning, where + " sends no laps", in, "no data");
    case LinkState::Idle:  // the connect is on its way to the I/O thread
    case LinkState::Connecting:
    case LinkState::Probing:
      return no_data(Severity::Info, "connecting to " + where, in, "connecting");
    case LinkState::Ready:
      return no_data(Severity::Info, "connected to " + where + ", not scanning", in, "not scanning");
    case LinkState::Stalled:
      return no_data(Severity::Warning, where + " stopped sending", in, "stalled");
    case LinkState::Reconnecting:
      return no_data(Severity::Warning, "reconnecting to " + where, in, "reconnecting");
    case LinkState::Failed:
      if (in.replay) {
        ViewState v;
        v.dim = true;
        v.severity = Severity::Info;
        v.headline = "Replay ended";
        v.subtitle = where + " played to the end, " + last_lap_text(in.seconds_since_lap);
        v.detail = std::string(in.link_message);
        v.status = "replay ended";
        return v;
      }
      return no_data(Severity::Error, "gave up on " + where, in, "failed");
  }
  return no_data(Severity::Warning, "unknown link state", in, "unknown");
}

}  // namespace ydscope::ui
