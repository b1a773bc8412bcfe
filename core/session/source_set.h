#pragma once
// SourceSet: the lidars one command drives together, one or more, each a Session of its own (its
// own I/O thread, its own reconnects) with what it is (SourceInfo). It connects them all, records
// them all into one .ydrec, and tells when their start has settled: every one scanning, or in
// trouble before it ever scanned. One lidar is a set of one: `record` and `serve` take a set, and
// the bridge's topics take its sessions (core/bridge/live_topics.h).
//
// Thread contract: the creator's thread calls every method; the sessions are thread-safe as ever.
#include <chrono>
#include <cstddef>
#include <future>
#include <memory>
#include <string>
#include <vector>

#include "core/frame/source_info.h"
#include "core/session/session.h"
#include "core/session/sources_recording.h"

namespace ydscope {

// One lidar of a set: what it is and how to reach it.
struct SourceSpec {
  SourceInfo info;
  SessionConfig config;
};

// How a set's start stands, looked at now.
struct SetStart {
  bool settled = false;      // every source scanned at least once or is in trouble
  bool any_scanned = false;  // at least one source has scanned
  std::string failure;       // the first source in trouble before it ever scanned: why
};

// One .ydrec of `sessions` (by source id), each beginning with its entry (source_entry_of):
// version 1 for one session, 2 for several. Each session is tapped in turn (waiting for each), so
// a session tapped before its connect has its start-up exchange in the file. Null plus one
// sentence in `error` when the file cannot be made.
std::unique_ptr<SourcesRecording> record_sessions(const std::string& path, const std::vector<Session*>& sessions,
                                                  std::vector<RecordingMetadata> entries, std::string& error);
// A record tap and the session it taps.
struct SessionTap {
  Session* session = nullptr;
  std::shared_ptr<RecordTap> tap;
};
// Every session's tap of `recording`, by source id.
std::vector<SessionTap> recording_taps(const std::vector<Session*>& sessions, const SourcesRecording& recording);
// Closes `taps`, each session's in one step on its I/O thread (Session::stop_taps), every session
// asked before any is waited on: every file of a run (a .ydrec and an MCAP file alike) ends at the
// same byte of each lidar. Closes asked one by one let a read land between them, and an MCAP file
// then held a lap more than the .ydrec of the same run. A future per session says when it did.
std::vector<std::future<CommandResult>> close_taps_together(const std::vector<SessionTap>& taps);

class SourceSet {
 public:
  // A session per spec, each subscribed with a ring of `lap_queue` laps. `specs` is not empty.
  explicit SourceSet(std::vector<SourceSpec> specs, std::size_t lap_queue = 4);
  SourceSet(const SourceSet&) = delete;
  SourceSet& operator=(const SourceSet&) = delete;

  std::size_t size() const { return sessions_.size(); }
  Session& session(std::size_t id) const { return *sessions_.at(id); }
  const SourceInfo& info(std::size_t id) const { return infos_.at(id); }
  const std::vector<SourceInfo>& infos() const { return infos_; }
  const SessionConfig& config(std::size_t id) const { return configs_.at(id); }

  // One .ydrec of every source (version 1 for a set of one, as a lone lidar's always was; 2 for
  // several), each session tapped before it connects so the start-up exchange is in the file.
  // Call before connect_all(). Null plus one sentence in `error` when the file cannot be made.
  std::unique_ptr<SourcesRecording> record(const std::string& path, std::string& error);
  std::vector<Session*> sessions() const;

  void connect_all();
  // Every session's link stops; waits up to `wait` for each to be idle. Idempotent.
  void disconnect_all(std::chrono::milliseconds wait = std::chrono::seconds(3));

  // Looks at every session once: the "all scanning, or one in trouble" wait a command runs at its
  // start. Remembers which sources ever scanned.
  SetStart start_state();
  bool ever_scanned(std::size_t id) const { return ever_scanned_.at(id); }

 private:
  std::vector<SourceInfo> infos_;
  std::vector<SessionConfig> configs_;
  std::vector<std::unique_ptr<Session>> sessions_;
  std::vector<bool> ever_scanned_;
};

}  // namespace ydscope
