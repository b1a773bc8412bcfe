#include "core/bridge/live_topics.h"

#include <chrono>
#include <future>

#include "core/bridge/ros_topic_channels.h"
#include "core/export/ros_tf.h"

namespace ydscope {
namespace {

using Clock = std::chrono::steady_clock;
// A live MCAP closes its chunk at least this often, so a killed writer loses under a second.
constexpr auto kFlushEvery = std::chrono::milliseconds(900);
constexpr auto kTakeWait = std::chrono::milliseconds(20);

std::uint64_t unix_now_ns() {
  return static_cast<std::uint64_t>(
      std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::system_clock::now().time_since_epoch())
          .count());
}

}  // namespace

LiveTopics::LiveTopics(std::vector<LiveSource> sources, LiveTopicsOptions options) : options_(std::move(options)) {
  for (LiveSource& source : sources) {
    sources_.push_back(source.info);
    lanes_.push_back({std::move(source), nullptr});
  }
}

std::unique_ptr<LiveTopics> LiveTopics::start(std::vector<LiveSource> sources, LiveTopicsOptions options,
                                              std::string& error) {
  return begin(std::unique_ptr<LiveTopics>(new LiveTopics(std::move(sources), std::move(options))), error);
}

std::unique_ptr<LiveTopics> LiveTopics::begin(std::unique_ptr<LiveTopics> live, std::string& error) {
  if (!live->options_.mcap_path.empty()) {
    live->mcap_ = McapRecordingExport::create(live->options_.mcap_path, live->options_.topics, error, live->sources_);
    if (!live->mcap_) return nullptr;
    live->mcap_->set_observer(
        [p = live.get()](std::size_t source, RosTopic topic, std::uint64_t log_time,
                         std::span<const std::uint8_t> cdr) { p->publish(source, topic, log_time, cdr); });
  }
  if (live->options_.attach) live->attach();
  live->thread_ = std::thread([p = live.get()] { p->run(); });
  return live;
}

LiveTopics::~LiveTopics() { stop(); }

void LiveTopics::attach() {
  detach();
  std::vector<std::shared_ptr<RecordTap>> taps;
  for (Lane& lane : lanes_) {
    lane.tap = std::make_shared<RecordTap>();
    taps.push_back(lane.tap);
  }
  {
    std::lock_guard lock(mutex_);
    next_taps_ = taps;
    new_taps_ = true;
  }
  for (Lane& lane : lanes_) lane.source.session->start_tap(lane.tap);
}

void LiveTopics::attach_source(std::size_t id) {
  Lane& lane = lanes_.at(id);
  if (lane.tap) lane.source.session->stop_tap(lane.tap);
  lane.tap = std::make_shared<RecordTap>();
  {
    std::lock_guard lock(mutex_);
    next_taps_.resize(lanes_.size());
    next_taps_[id] = lane.tap;
    new_taps_ = true;
  }
  lane.source.session->start_tap(lane.tap);
}

void LiveTopics::detach_source(std::size_t id) {
  Lane& lane = lanes_.at(id);
  if (!lane.tap) return;
  lane.source.session->stop_tap(lane.tap);
  lane.tap.reset();
  std::lock_guard lock(mutex_);
  next_taps_.resize(lanes_.size());
  next_taps_[id] = nullptr;
  new_taps_ = true;
}

void LiveTopics::detach() {
  if (!attached()) return;
  for (Lane& lane : lanes_) {
    lane.source.session->stop_tap(lane.tap);
    lane.tap.reset();
  }
  std::lock_guard lock(mutex_);
  next_taps_.assign(lanes_.size(), nullptr);
  new_taps_ = true;
}

std::vector<SessionTap> LiveTopics::taps() const {
  std::vector<SessionTap> open;
  for (const Lane& lane : lanes_)
    if (lane.tap) open.push_back({lane.source.session, lane.tap});
  return open;
}

std::vector<std::future<CommandResult>> close_run_taps(const std::vector<Session*>& sessions,
                                                       const SourcesRecording* ydrec, const LiveTopics* mcap) {
  std::vector<SessionTap> taps;
  if (ydrec) taps = recording_taps(sessions, *ydrec);
  if (mcap)
    for (const SessionTap& tap : mcap->taps()) taps.push_back(tap);
  return close_taps_together(taps);
}

bool LiveTopics::stop() {
  if (stopped_) return error().empty();
  stopped_ = true;
  // Each tap closes on its session's I/O thread; what it holds until then is still written.
  std::vector<std::future<void>> closing;
  for (Lane& lane : lanes_) {
    if (!lane.tap) continue;
    auto closed = std::make_shared<std::promise<void>>();
    closing.push_back(closed->get_future());
    lane.source.session->stop_tap(lane.tap, [closed](const CommandResult&) { closed->set_value(); });
    lane.tap.reset();
  }
  const auto give_up = Clock::now() + std::chrono::seconds(3);
  for (auto& closed : closing) closed.wait_until(give_up);
  stopping_.store(true);
  if (thread_.joinable()) thread_.join();
  if (mcap_) {
    const bool finished = mcap_->finish();
    messages_.store(mcap_->statistics().message_count);
    chunks_ = mcap_->statistics().chunk_count;
    bytes_written_.store(mcap_->bytes_written());
    std::lock_guard lock(mutex_);
    if (!finished && error_.empty()) error_ = "writing " + options_.mcap_path + " failed: " + mcap_->error();
  }
  return error().empty();
}

std::string LiveTopics::file_summary() const {
  return "wrote " + options_.mcap_path + ": " + std::to_string(laps()) + " laps, " + std::to_string(messages()) +
         " messages in " + std::to_string(chunks_) + " chunks, " + std::to_string(bytes_written()) + " bytes";
}

std::string LiveTopics::error() const {
  std::lock_guard lock(mutex_);
  return error_;
}

void LiveTopics::publish(std::size_t source, RosTopic topic, std::uint64_t log_time,
                         std::span<const std::uint8_t> cdr) {
  messages_.fetch_add(1, std::memory_order_relaxed);
  if (options_.server)
    options_.server->publish(foxglove::channel_id(topic, source), log_time,
                             std::make_shared<const std::vector<std::uint8_t>>(cdr.begin(), cdr.end()));
}

void LiveTopics::idle(std::vector<Reading>& readings, std::size_t id) {
  const Reading& reading = readings[id];
  if (!reading.last_t_ns) return;
  const std::int64_t t_ns =
      *reading.last_t_ns +
      std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now() - reading.last_taken).count();
  if (mcap_) return mcap_->idle(t_ns, static_cast<std::uint16_t>(id));
  readings[id].encoder->idle(t_ns,
                             [this, id](RosTopic topic, std::uint64_t log_time, std::span<const std::uint8_t> cdr) {
                               publish(id, topic, log_time, cdr);
                             });
}

void LiveTopics::tell_clients(std::size_t source, Reading& reading) {
  const LiveSource& lidar = lanes_[source].source;
  const SessionSnapshot s = lidar.session->snapshot();
  if (lidar.parameters) {
    std::vector<foxglove::Parameter> values = lidar.parameters->updates(s);
    if (several())
      for (foxglove::Parameter& p : values) p.name = foxglove::source_parameter_name(lidar.info.name, p.name);
    if (!values.empty()) options_.server->broadcast_parameters(std::move(values));
  }
  if (s.state == reading.told_state) return;
  const auto bad = [](LinkState state) {
    return state == LinkState::Failed || state == LinkState::Reconnecting || state == LinkState::Stalled;
  };
  const bool was_bad = bad(reading.told_state);
  reading.told_state = s.state;
  // Foxglove lists every status message under Problems, info too: only trouble is told, and
  // withdrawn once the link is fine again. Routine states (connecting, scanning, a command in
  // progress) are no problem and /diagnostics says how the lidar is.
  const std::string id = "ydscope-link" + (several() ? "-" + lidar.info.name : std::string());
  if (!bad(s.state)) {
    if (was_bad) options_.server->remove_status(id);
    return;
  }
  const std::string who = several() ? lidar.info.name + ": lidar " : "lidar ";
  options_.server->broadcast_status(
      foxglove::StatusLevel::Warning,
      who + std::string(link_state_name(s.state)) + (s.message.empty() ? "" : ": " + s.message), id);
}

void LiveTopics::publish_poses() {
  std::vector<RosTransform> transforms;
  for (std::size_t id = 0; id < lanes_.size(); ++id) {
    const RosFrameOptions frame = ros_options_of(options_.topics.ros, sources_, id).frame;  // this lidar's frame_id
    append_lidar_transforms(id < sources_.size() ? sources_[id].pose : Pose{}, frame, frame.parent_frame_id,
                            frame.frame_id, transforms);
  }
  std::vector<std::uint8_t> cdr;
  const std::uint64_t now_ns = unix_now_ns();
  encode_tf_message(transforms, now_ns, cdr);
  options_.server->publish(foxglove::tf_static_channel_id(sources_.size()), now_ns,
                           std::make_shared<const std::vector<std::uint8_t>>(std::move(cdr)));
}

void LiveTopics::take_new_taps(std::vector<Reading>& readings, std::uint64_t& laps_before) {
  std::lock_guard lock(mutex_);
  if (!new_taps_) return;
  new_taps_ = false;
  for (std::size_t id = 0; id < readings.size(); ++id) {
    if (readings[id].tap == next_taps_.at(id)) continue;  // attach_source() of another source
    readings[id].tap = next_taps_.at(id);
    readings[id].last_t_ns.reset();  // a new tap counts its own time
    if (mcap_) continue;
    if (readings[id].encoder) laps_before += readings[id].encoder->laps();
    readings[id].encoder = std::make_unique<RosTopicEncoder>(ros_options_of(options_.topics.ros, sources_, id));
  }
}

RosTopicEncoder& LiveTopics::topics_of(std::vector<Reading>& readings, std::size_t id) {
  return mcap_ ? mcap_->encoder(id) : *readings[id].encoder;
}

void LiveTopics::run() {
  std::vector<Reading> readings(lanes_.size());
  std::uint64_t laps_before = 0;  // of the encoders before the current ones
  std::vector<TapRecord> records;
  auto last_flush = Clock::now();
  bool poses_told = false;
  for (;;) {
    take_new_taps(readings, laps_before);
    if (options_.server) {
      for (std::size_t id = 0; id < readings.size(); ++id) tell_clients(id, readings[id]);
      // Once: /tf_static is latched (ros_topic_channels), so the server gives it to every client
      // that subscribes, whenever it does.
      if (!poses_told) {
        publish_poses();
        poses_told = true;
      }
    }
    bool reading_any = false;
    bool all_drained = true;
    std::uint64_t dropped = 0;
    for (std::size_t id = 0; id < readings.size(); ++id) {
      Reading& reading = readings[id];
      if (!reading.tap) continue;
      RosTopicEncoder& topics = topics_of(readings, id);
      // The first open tap waits for records; the others are only looked at.
      const bool open = reading.tap->wait_and_take(records, reading_any ? std::chrono::milliseconds(0) : kTakeWait);
      reading_any = true;
      if (lanes_[id].source.parameters) topics.set_filter(lanes_[id].source.parameters->filter());
      for (const TapRecord& r : records) {
        if (mcap_) {
          mcap_->record(r.type, r.payload, r.t_ns, static_cast<std::uint16_t>(id));
        } else {
          topics.record(r.type, r.payload, r.t_ns,
                        [this, id](RosTopic topic, std::uint64_t log_time, std::span<const std::uint8_t> cdr) {
                          publish(id, topic, log_time, cdr);
                        });
        }
      }
      if (!records.empty()) {
        reading.last_t_ns = records.back().t_ns;
        reading.last_taken = Clock::now();
      } else {
        idle(readings, id);
      }
      // Nothing came although the tap was closed, or stop() gave up waiting for it to close.
      const bool drained = records.empty() && (!open || stopping_.load());
      reading.tap->recycle(records);
      if (const auto lost = reading.tap->dropped()) {
        dropped += lost;
        topics.set_extra_diagnostics({{"tap_dropped_records", std::to_string(lost)}});
      }
      if (drained && !stopping_.load()) reading.tap.reset();  // closed: wait for the next one, or for stop()
      all_drained = all_drained && drained;
    }
    std::uint64_t laps = laps_before;
    for (std::size_t id = 0; id < readings.size(); ++id)
      if (mcap_ || readings[id].encoder) laps += topics_of(readings, id).laps();
    laps_.store(laps);
    if (dropped) dropped_.store(dropped);
    if (mcap_) {
      if (Clock::now() - last_flush >= kFlushEvery) {
        mcap_->flush();
        last_flush = Clock::now();
      }
      bytes_written_.store(mcap_->bytes_written());
      if (mcap_->failed()) {
        std::lock_guard lock(mutex_);
        if (error_.empty()) error_ = "writing " + options_.mcap_path + " failed: " + mcap_->error();
      }
    }
    if (stopping_.load() && all_drained) break;
    if (!reading_any) std::this_thread::sleep_for(kTakeWait);
  }
}

}  // namespace ydscope
