#include "ui/view/status/view_state.h"

#include <cmath>
#include <cstdio>

namespace ydscope::ui {

std::string format_age(double seconds) {
  const long s = std::lround(std::max(seconds, 0.0));
  char text[32];
  if (s < 60)
    std::snprintf(text, sizeof text, "%ld s", s);
  else if (s < 3600)
    std::snprintf(text, sizeof text, "%ld min %ld s", s / 60, s % 60);
  else
    std::snprintf(text, sizeof text, "%ld h %ld min", s / 3600, (s % 3600) / 60);
  return text;
}

namespace {

std::string last_lap_text(const std::optional<double>& age) {
  return age ? "last lap " + format_age(*age) + " ago" : "no lap yet from this source";
}

ViewState dimmed(Severity severity, std::string headline, std::string subtitle, std::string detail,
                 std::string status) {
  ViewState v;
  v.dim = true;
  v.severity = severity;
  v.headline = std::move(headline);
  v.subtitle = std::move(subtitle);
  v.detail = std::move(detail);
  v.status = std::move(status);
  return v;
}

ViewState no_data(Severity severity, std::string subtitle, const ViewStateInput& in, std::string status) {
  return dimmed(severity, "No data", std::move(subtitle) + ", " + last_lap_text(in.seconds_since_lap),
                std::string(in.link_message), std::move(status));
}

ViewState describe_link(const ViewStateInput& in) {
  const std::string where(in.address.empty() ? std::string_view("the lidar") : in.address);
  const bool fresh = in.seconds_since_lap && *in.seconds_since_lap <= kStaleLapSeconds;

  if (!in.has_source && !in.start_error.empty()) {
    // The same sentence ydscope-cli gives for that source (for a recording: recording_plan.h).
    if (in.replay)
      return dimmed(Severity::Error, "Cannot replay", std::string(in.start_error),
                    "choose another recording, or a model to decode it as, in the Connection panel (Replay)",
                    "cannot replay");
    return dimmed(Severity::Error, "Cannot connect", std::string(in.start_error),
                  "choose another source in the Connection panel", "cannot connect");
  }
  if (!in.has_source)
    return dimmed(Severity::Info, "Disconnected",
                  "choose a port, the virtual lidar or a recording in the Connection panel", "", "disconnected");
  if (in.replay && in.replay_passes > 0 && !in.seconds_since_lap) {
    // Going round again cannot help: its bytes hold no lap for this model.
    const std::string model = in.model.empty() ? std::string("the model chosen") : std::string(in.model);
    const bool packets = in.decoded.packets > 0;  // then the model is right and the recording short
    ViewState v = dimmed(Severity::Error, "No laps", where + " played through without one complete lap",
                         no_lap_reason(model, in.decoded) +
                             (packets ? " (counted over every pass so far); record at least one whole turn"
                                      : "; open it as another model in the Connection panel (Replay)"),
                         "no laps");
    v.give_up = true;
    return v;
  }
  if (in.replay && in.replay_paused)
    return dimmed(Severity::Info, "Replay paused", where + ", press Play to go on", "", "replay paused");
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
      if (!in.seconds_since_lap)
        return no_data(Severity::Info, "waiting for the first lap from " + where, in, "waiting");
      return no_data(Severity::Warning, where + " sends no laps", in, "no data");
    case LinkState::Idle:  // the connect is on its way to the I/O thread
    case LinkState::Connecting:
    case LinkState::Probing: return no_data(Severity::Info, "connecting to " + where, in, "connecting");
    case LinkState::Ready:
      return no_data(Severity::Info, "connected to " + where + ", not scanning", in, "not scanning");
    case LinkState::Stalled: return no_data(Severity::Warning, where + " stopped sending", in, "stalled");
    case LinkState::Reconnecting: return no_data(Severity::Warning, "reconnecting to " + where, in, "reconnecting");
    case LinkState::Failed:
      // A replay that gave laps and stopped played to its end (the link's own words would speak
      // of a device unplugged); one that gave none could not be played.
      if (in.replay && in.seconds_since_lap)
        return dimmed(Severity::Info, "Replay ended",
                      where + " played to the end, " + last_lap_text(in.seconds_since_lap), "", "replay ended");
      if (in.replay)
        return dimmed(Severity::Error, "Cannot replay", "no lap came from " + where, std::string(in.link_message),
                      "cannot replay");
      return no_data(Severity::Error, "gave up on " + where, in, "failed");
  }
  return no_data(Severity::Warning, "unknown link state", in, "unknown");
}

}  // namespace

ViewState describe_view_state(const ViewStateInput& in) {
  ViewState v = describe_link(in);
  v.notices.assign(in.source_warnings.begin(), in.source_warnings.end());
  return v;
}

}  // namespace ydscope::ui
