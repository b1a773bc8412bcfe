#pragma once
// Playing a recording through the Session: a LinkOpener that opens a ReplayLink, and a handle the
// UI keeps to pause, change speed and loop the replay the session currently reads.
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <vector>

#include "core/link/replay_link.h"
#include "core/session/session.h"

namespace ydscope::gui {

class ReplayHandle {
 public:
  void set(const std::shared_ptr<ReplayLink>& link);
  // Empty when no replay link is open.
  std::optional<ReplayStatus> status() const;
  void set_paused(bool paused);
  void set_speed(double speed);
  void set_loop(bool loop);

 private:
  std::shared_ptr<ReplayLink> lock() const;
  mutable std::mutex mutex_;
  std::weak_ptr<ReplayLink> link_;
};

// A session configuration that replays `path`, decoded as `model` (a name) or else as the
// recording says, as ydscope-cli replay would (core/record/recording_plan.h). Empty plus that
// plan's sentence in `error` when the recording cannot give a lap; `warnings` receives what is
// wrong with it but still plays, in the CLI's words.
std::optional<SessionConfig> replay_config(const std::string& path, const std::optional<std::string>& model,
                                           ReplayOptions options, std::shared_ptr<ReplayHandle> handle,
                                           std::string& error, std::vector<std::string>& warnings);

}  // namespace ydscope::gui
