#pragma once
// Playing a recording through the Session: a LinkOpener that opens a ReplayLink, and a handle the
// UI keeps to pause, change speed and loop the replay the session currently reads.
#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include "core/link/replay_link.h"
#include "core/link/session.h"

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

// A session configuration that replays `path` (model and scale from the recording's metadata).
// Empty plus one sentence in `error` when the file is not a readable recording.
std::optional<SessionConfig> replay_config(const std::string& path, ReplayOptions options,
                                           std::shared_ptr<ReplayHandle> handle, std::string& error);

}  // namespace ydscope::gui
