#pragma once
// Getting a lidar out of the window while it runs: Share serves it to Foxglove (the server and
// topics `ydscope-cli serve` uses, core/bridge/session_share.h), and the Record tab writes .ydrec
// (the session's own file), MCAP (LiveTopics) or both. Both belong to one source at a time: a
// recording ends when the source changes; the share keeps its clients and serves the new source
// once it is up. What they do is shown in that source's panel model.
#include <chrono>
#include <cstdint>
#include <memory>
#include <string>

#include "app/gui/source_slot.h"
#include "core/bridge/live_topics.h"
#include "core/bridge/session_share.h"

namespace ydscope::gui {

class SourceOutputs {
 public:
  // share_port: Share's listening port (0: any); record_at_start: --record's format ("", "ydrec",
  // "mcap" or "both"), started once the first source connects.
  SourceOutputs(std::uint16_t share_port, std::string record_at_start)
      : share_port_(share_port), record_at_start_(std::move(record_at_start)) {}

  void start_share(SourceSlot& slot);
  void stop_share(SourceSlot& slot);
  bool sharing() const { return share_ != nullptr; }
  void start_recording(SourceSlot& slot, const ui::StartRecording& request);
  // `why` ends the sentence the user reads: " (the source changed)".
  void stop_recording(SourceSlot& slot, const std::string& why = {});
  // A new source (or none) is about to start on `slot`: its recordings end, the share waits.
  void leave_source(SourceSlot& slot);
  // Each frame: --record once connected, the MCAP file's size, the share's clients, and a share
  // that waits for the new source to scan before serving it.
  void follow(SourceSlot& slot);

 private:
  std::uint16_t share_port_;
  std::string record_at_start_;                         // emptied once started
  std::unique_ptr<SessionShare> share_;                 // while Share is on
  std::unique_ptr<LiveTopics> mcap_recording_;          // while an MCAP recording runs
  std::chrono::steady_clock::time_point share_polled_;  // clients are asked twice a second
};

}  // namespace ydscope::gui
