#pragma once
// LiveTopics: live sessions' records (a RecordTap of each) turned into ROS 2 topics on a thread
// of its own: into an MCAP file, to the clients of a FoxgloveServer, or both. It is how
// `ydscope-cli record --mcap` and `serve` (one lidar or several), and the app's Share and MCAP
// recording, all go live, so compression and slow clients never hold up a session's I/O thread
// or the UI.
//
// One lidar's topics are named as ever (/scan ...). Several lidars' are /NAME/scan and so on,
// with every pose on /tf_static (channel ids: core/bridge/ros_topic_channels.h).
//
// With a server it also tells the clients when a lidar's link goes down (a status message of
// level warning, withdrawn with removeStatus when it is back; routine states are not told: Foxglove
// lists every status as a problem) and the parameter values in force once it is back or when they change
// (SessionParameters::updates), and applies the filter the clients set through each
// SessionParameters.
//
// Thread contract: every method is for the thread that created it; error(), laps() and the
// counters may be read from any thread. The sessions must outlive it.
#include <atomic>
#include <chrono>
#include <cstdint>
#include <future>
#include <memory>
#include <mutex>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "core/bridge/foxglove_server.h"
#include "core/bridge/session_parameters.h"
#include "core/bridge/sources_parameters.h"
#include "core/export/mcap_recording_export.h"
#include "core/session/record_tap.h"
#include "core/session/session.h"
#include "core/session/source_set.h"

namespace ydscope {

struct LiveTopicsOptions {
  McapExportOptions topics;                    // frame, model, link bytes; the file's compression
  std::string mcap_path;                       // empty: no file
  foxglove::FoxgloveServer* server = nullptr;  // publish to its clients (must outlive this)
  // False: start() taps no session; the caller calls attach_source(id) right after connecting
  // each one, so its start-up exchange (the first A5 65) is in the topics too.
  bool attach = true;
};

// One lidar of the set served: its session and what it is (a set of one keeps the topics a
// lone lidar always had; several are named apart).
struct LiveSource {
  Session* session = nullptr;
  SourceInfo info;                                    // its name (the topics' namespace), pose, model
  foxglove::SessionParameters* parameters = nullptr;  // the clients' filter choice for it
};

class LiveTopics {
 public:
  // Creates the MCAP file (when asked) and taps the sessions (one or more). Null plus one
  // sentence in `error` when the file cannot be created.
  static std::unique_ptr<LiveTopics> start(std::vector<LiveSource> sources, LiveTopicsOptions options,
                                           std::string& error);
  ~LiveTopics();  // stop()
  LiveTopics(const LiveTopics&) = delete;
  LiveTopics& operator=(const LiveTopics&) = delete;

  // Closes the tap, writes what it still held and finishes the file (summary and footer).
  // False when writing the file failed (error() says why). Idempotent.
  bool stop();

  // Server only: the sessions are changing source. detach() closes the taps (nothing is served
  // meanwhile, the clients stay connected); attach() starts afresh on what the sessions have now,
  // with new decoders, so a G1 after a G6 is decoded as a G1.
  void detach();
  void attach();
  // Taps source `id`'s session afresh (each session runs what it is asked in order: asked right
  // after connect(), the tap sees every byte of the connection).
  void attach_source(std::size_t id);
  // Closes source `id`'s tap only (it is changing source); the others go on being served.
  void detach_source(std::size_t id);
  bool attached(std::size_t id) const { return lanes_.at(id).tap != nullptr; }
  bool attached() const { return !lanes_.empty() && lanes_.front().tap != nullptr; }
  // The open taps, for close_run_taps before stop() (which then finds them closed and writes
  // what they held).
  std::vector<SessionTap> taps() const;

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
  // One session's tap, as the creator sees it.
  struct Lane {
    LiveSource source;
    std::shared_ptr<RecordTap> tap;
  };
  // What the thread reads from one session.
  struct Reading {
    std::shared_ptr<RecordTap> tap;
    std::unique_ptr<RosTopicEncoder> encoder;  // without a file; a file's export has its own
    LinkState told_state = LinkState::Idle;
    // The newest record's time and when it was taken: the tap's clock while nothing comes.
    std::optional<std::int64_t> last_t_ns;
    std::chrono::steady_clock::time_point last_taken;
  };
  LiveTopics(std::vector<LiveSource> sources, LiveTopicsOptions options);
  static std::unique_ptr<LiveTopics> begin(std::unique_ptr<LiveTopics> live, std::string& error);
  void run();
  // New taps from attach()/detach(), if any, with fresh encoders.
  void take_new_taps(std::vector<Reading>& readings, std::uint64_t& laps_before);
  RosTopicEncoder& topics_of(std::vector<Reading>& readings, std::size_t id);
  void publish(std::size_t source, RosTopic topic, std::uint64_t log_time, std::span<const std::uint8_t> cdr);
  // Nothing came from `id`'s tap: its time still passes (an outage keeps /diagnostics coming).
  void idle(std::vector<Reading>& readings, std::size_t id);
  // The link's state and the parameters' new values, to the server's clients.
  void tell_clients(std::size_t source, Reading& reading);
  void publish_poses();
  bool several() const { return named_apart(sources_); }

  LiveTopicsOptions options_;
  std::vector<Lane> lanes_;
  std::vector<SourceInfo> sources_;  // by source id
  std::unique_ptr<McapRecordingExport> mcap_;

  // Handed from the creator to the thread: the taps to read, one per lane (null: none).
  mutable std::mutex mutex_;
  std::vector<std::shared_ptr<RecordTap>> next_taps_;
  bool new_taps_ = false;
  std::string error_;

  std::atomic<bool> stopping_{false};
  std::atomic<std::uint64_t> laps_{0};
  std::atomic<std::uint64_t> messages_{0};
  std::atomic<std::uint64_t> bytes_written_{0};
  std::atomic<std::uint64_t> dropped_{0};
  std::uint32_t chunks_ = 0;  // set by stop()
  bool stopped_ = false;
  std::thread thread_;
};

// The files of one run close together (close_taps_together): the .ydrec `ydrec` records of
// `sessions` and the MCAP file `mcap` writes (either null without one), so both end at the same
// byte of each lidar. `record` and the app's Record both end their runs here.
std::vector<std::future<CommandResult>> close_run_taps(const std::vector<Session*>& sessions,
                                                       const SourcesRecording* ydrec, const LiveTopics* mcap);

}  // namespace ydscope
