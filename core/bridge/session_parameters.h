#pragma once
// The Foxglove parameters a shared session offers (`ydscope-cli serve`, the app's Share), mapped
// onto the session's commands: scan_hz, ranging_khz and power_down_protection go through the
// session's normal command sequencing and report what the device reads back; filter_specular and
// filter_ambient switch the G1 interference filter of the served /scan and /points.
#include <atomic>

#include "core/bridge/foxglove_server.h"
#include "core/session/session.h"
#include "core/protocol/interference_filter.h"

namespace ydscope::foxglove {

class SessionParameters final : public ParameterBackend {
 public:
  explicit SessionParameters(Session& session) : session_(session) {}
  std::vector<Parameter> current() override;
  void set(const Parameter& parameter, SetDone done) override;
  // The filter the clients asked for (any thread).
  InterferenceFilter filter() const { return {specular_.load(), ambient_.load()}; }
  // What subscribed clients should be told unasked, given the session's state `s`: every value
  // once a (re)connection has settled, so they learn the values in force after a replug; after
  // that, the values that changed (the app set the scan rate, a re-apply failed). Empty while
  // the link is not settled. One thread calls it (the topics').
  std::vector<Parameter> updates(const SessionSnapshot& s);

 private:
  std::vector<Parameter> values_of(const SessionSnapshot& s) const;
  // A set's read-back reached the clients already: not news for updates().
  void told(const std::vector<Parameter>& values);

  Session& session_;
  std::atomic<bool> specular_{false};
  std::atomic<bool> ambient_{false};
  std::mutex told_mutex_;  // updates() on the topics' thread, told() on the session's
  std::vector<Parameter> told_;
  std::optional<std::uint64_t> told_connection_;  // the session's reconnect count when all were told
};

}  // namespace ydscope::foxglove
