#pragma once
// Getting the lidars out of the window while they run: Share serves them to Foxglove (the server
// and topics `ydscope-cli serve` uses, core/bridge/session_share.h), and the Record tab writes one
// .ydrec (core/session/sources_recording.h), one MCAP (LiveTopics) or both. Both cover every lidar
// shown, as `serve` and `record` cover every --port: one lidar is served and recorded as it always
// was (/scan, a version-1 file), several each under its name. A recording ends when a source
// changes or the list does; the share keeps its clients, stops serving a source while it changes
// and serves it again once it scans, and serves a changed list anew. What they do is shown in
// every source's panel model alike.
#include <atomic>
#include <chrono>
#include <cstdint>
#include <memory>
#include <string>
#include <thread>

#include "app/gui/source_list.h"
#include "core/bridge/live_topics.h"
#include "core/bridge/session_share.h"
#include "core/session/sources_recording.h"

namespace ydscope::gui {

class SourceOutputs {
 public:
  // share_port: Share's listening port (0: any); record_at_start: --record's format ("", "ydrec",
  // "mcap" or "both"), started once the first source connects.
  SourceOutputs(std::uint16_t share_port, std::string record_at_start)
      : share_port_(share_port), record_at_start_(std::move(record_at_start)) {}
  ~SourceOutputs();

  void start_share(SourceList& sources);
  void stop_share(SourceList& sources);
  bool sharing() const { return share_ != nullptr; }
  void start_recording(SourceList& sources, const ui::StartRecording& request);
  // `why` ends the sentence the user reads: " (the source changed)".
  void stop_recording(SourceList& sources, const std::string& why = {});
  // Source `index` is about to start anew (or stop): the recording ends, the share stops serving
  // it until it scans again.
  void leave_source(SourceList& sources, std::size_t index);
  // Around adding or removing a source: the recording ends, and a share serves the new list
  // (its clients reconnect: the channels name every source).
  void before_change(SourceList& sources);
  void after_change(SourceList& sources);
  // Each frame: --record once connected, the files' sizes, the share's clients, a changed source
  // served again once it scans; and every source's model told.
  void follow(SourceList& sources);

 private:
  bool recording() const { return ydrec_ != nullptr || mcap_recording_ != nullptr; }
  void stop_ydrec();
  void tell_models(SourceList& sources);

  std::uint16_t share_port_;
  std::string record_at_start_;  // emptied once started
  std::unique_ptr<SessionShare> share_;
  std::vector<bool> rejoining_;                 // by source: its share tap waits for it to scan again
  std::unique_ptr<LiveTopics> mcap_recording_;  // while an MCAP recording runs
  // While a .ydrec runs: the file of every source, written by a thread of its own.
  std::unique_ptr<SourcesRecording> ydrec_;
  std::vector<Session*> ydrec_sessions_;
  std::thread ydrec_pump_;
  std::atomic<bool> ydrec_stopping_{false};
  std::atomic<bool> ydrec_failed_{false};
  ui::McapRecordingState ydrec_state_;
  ui::McapRecordingState mcap_state_;
  double record_started_s_ = 0;
  std::chrono::steady_clock::time_point share_polled_;  // clients are asked twice a second
  std::size_t share_clients_ = 0;
  bool share_again_ = false;  // between before_change and after_change
};

}  // namespace ydscope::gui
