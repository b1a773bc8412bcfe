#pragma once
// LiveTopics: a live session's records (a RecordTap of its own) turned into ROS 2 topics on a
// thread of its own: into an MCAP file, to the clients of a FoxgloveServer, or both. It is how
// `ydscope-cli record --mcap` and `serve`, and the app's Share and MCAP recording, all go live,
// so compression and slow clients never hold up the session's I/O thread or the UI.
//
// With a server it also tells the clients when the lidar's link goes down or comes back (a
// status message) and applies the filter the clients set through SessionParameters.
//
// Thread contract: every method is for the thread that created it; error(), laps() and the
// counters may be read from any thread. The session must outlive it.
#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "core/bridge/foxglove_server.h"
#include "core/bridge/session_parameters.h"
#include "core/export/mcap_recording_export.h"
#include "core/link/record_tap.h"
#include "core/link/session.h"

namespace ydscope {

struct LiveTopicsOptions {
  McapExportOptions topics;                     // frame, model, link bytes; the file's compression
  std::string mcap_path;                        // empty: no file
  foxglove::FoxgloveServer* server = nullptr;   // publish to its clients (must outlive this)
  foxglove::SessionParameters* parameters = nullptr;  // the clients' filter choice
};

class LiveTopics {
 public:
  // Creates the MCAP file (when asked) and taps the session. Null plus one sentence in `error`
  // when the file cannot be created.
  static std::unique_ptr<LiveTopics> start(Session& session, LiveTopicsOptions options, std::string& error);
  ~LiveTopics();  // stop()
  LiveTopics(const LiveTopics&) = delete;
  LiveTopics& operator=(const LiveTopics&) = delete;

  // Closes the tap, writes what it still held and finishes the file (summary and footer).
  // False when writing the file failed (error() says why). Idempotent.
  bool stop();

  // Server only: the session is changing source. detach() closes the tap (nothing is served
  // meanwhile, the clients stay connected); attach() starts afresh on what the session has now,
  // with a new decoder, so a G1 after a G6 is decoded as a G1.
  void detach();
  void attach();
  bool attached() const { return tap_ != nullptr; }

  // Empty, or the sentence saying why writing the file failed (any thread).
  std::string error() const;
  const std::string& mcap_path() const { return options_.mcap_path; }
  std::uint64_t laps() const { return laps_.load(); }
  std::uint64_t messages() const { return messages_.load(); }
  std::uint64_t bytes_written() const { return bytes_written_.load(); }
  // Records the tap dropped because this side fell behind the lidar.
  std::uint64_t dropped() const { return dropped_.load(); }
  // After stop(): "wrote PATH: L laps, M messages in C chunks, B bytes".
  std::string file_summary() const;

 private:
  LiveTopics(Session& session, LiveTopicsOptions options) : session_(session), options_(std::move(options)) {}
  void run();
  void publish(RosTopic topic, std::uint64_t log_time, std::span<const std::uint8_t> cdr);
  void tell_link_state();

  Session& session_;
  LiveTopicsOptions options_;
  std::unique_ptr<McapRecordingExport> mcap_;
  std::shared_ptr<RecordTap> tap_;  // the creator's view of the current tap

  // Handed from the creator to the thread: the tap to read, and a fresh encoder for it.
  mutable std::mutex mutex_;
  std::shared_ptr<RecordTap> next_tap_;
  bool new_tap_ = false;
  std::string error_;

  std::atomic<bool> stopping_{false};
  std::atomic<std::uint64_t> laps_{0};
  std::atomic<std::uint64_t> messages_{0};
  std::atomic<std::uint64_t> bytes_written_{0};
  std::atomic<std::uint64_t> dropped_{0};
  std::uint32_t chunks_ = 0;  // set by stop()
  LinkState told_state_ = LinkState::Idle;
  bool stopped_ = false;
  std::thread thread_;
};

}  // namespace ydscope
