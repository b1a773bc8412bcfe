#pragma once
// The Foxglove parameters a shared session offers (`ydscope-cli serve`, the app's Share), mapped
// onto the session's commands: scan_hz, ranging_khz and power_down_protection go through the
// session's normal command sequencing and report what the device reads back; filter_specular and
// filter_ambient switch the G1 interference filter of the served /scan and /points.
#include <atomic>

#include "core/bridge/foxglove_server.h"
#include "core/link/session.h"
#include "core/protocol/interference_filter.h"

namespace ydscope::foxglove {

class SessionParameters final : public ParameterBackend {
 public:
  explicit SessionParameters(Session& session) : session_(session) {}
  std::vector<Parameter> current() override;
  void set(const Parameter& parameter, SetDone done) override;
  // The filter the clients asked for (any thread).
  InterferenceFilter filter() const { return {specular_.load(), ambient_.load()}; }

 private:
  Session& session_;
  std::atomic<bool> specular_{false};
  std::atomic<bool> ambient_{false};
};

}  // namespace ydscope::foxglove
