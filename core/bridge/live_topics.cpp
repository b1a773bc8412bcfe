#include "core/bridge/live_topics.h"

#include <chrono>
#include <future>

#include "core/bridge/ros_topic_channels.h"

namespace ydscope {
namespace {

using Clock = std::chrono::steady_clock;
// A live MCAP closes its chunk at least this often, so a killed writer loses under a second.
constexpr auto kFlushEvery = std::chrono::milliseconds(900);
constexpr auto kTakeWait = std::chrono::milliseconds(20);

}  // namespace

std::unique_ptr<LiveTopics> LiveTopics::start(Session& session, LiveTopicsOptions options, std::string& error) {
  std::unique_ptr<LiveTopics> live(new LiveTopics(session, std::move(options)));
  if (!live->options_.mcap_path.empty()) {
    live->mcap_ = McapRecordingExport::create(live->options_.mcap_path, live->options_.topics, error);
    if (!live->mcap_) return nullptr;
    live->mcap_->set_observer([p = live.get()](std::size_t, RosTopic topic, std::uint64_t log_time,
                                               std::span<const std::uint8_t> cdr) {
      p->publish(topic, log_time, cdr);
    });
  }
  live->attach();
  live->thread_ = std::thread([p = live.get()] { p->run(); });
  return live;
}

LiveTopics::~LiveTopics() { stop(); }

void LiveTopics::attach() {
  detach();
  tap_ = std::make_shared<RecordTap>();
  {
    std::lock_guard lock(mutex_);
    next_tap_ = tap_;
    new_tap_ = true;
  }
  session_.start_tap(tap_);
}

void LiveTopics::detach() {
  if (!tap_) return;
  session_.stop_tap(tap_);
  tap_.reset();
  std::lock_guard lock(mutex_);
  next_tap_.reset();
  new_tap_ = true;
}

bool LiveTopics::stop() {
  if (stopped_) return error().empty();
  stopped_ = true;
  if (tap_) {
    // The tap closes on the session's I/O thread; what it holds until then is still written.
    auto closed = std::make_shared<std::promise<void>>();
    auto done = closed->get_future();
    session_.stop_tap(tap_, [closed](const CommandResult&) { closed->set_value(); });
    done.wait_for(std::chrono::seconds(3));
    tap_.reset();
  }
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

void LiveTopics::publish(RosTopic topic, std::uint64_t log_time, std::span<const std::uint8_t> cdr) {
  messages_.fetch_add(1, std::memory_order_relaxed);
  if (options_.server)
    options_.server->publish(foxglove::channel_id(topic), log_time,
                             std::make_shared<const std::vector<std::uint8_t>>(cdr.begin(), cdr.end()));
}

void LiveTopics::tell_link_state() {
  const SessionSnapshot s = session_.snapshot();
  if (s.state == told_state_) return;
  told_state_ = s.state;
  const bool bad = s.state == LinkState::Failed || s.state == LinkState::Reconnecting || s.state == LinkState::Stalled;
  options_.server->broadcast_status(bad ? foxglove::StatusLevel::Warning : foxglove::StatusLevel::Info,
                                    std::string("lidar ") + std::string(link_state_name(s.state)) +
                                        (s.message.empty() ? "" : ": " + s.message));
}

void LiveTopics::run() {
  std::shared_ptr<RecordTap> tap;
  std::unique_ptr<RosTopicEncoder> encoder;  // without a file; a file's export has its own
  std::uint64_t laps_before = 0;             // of the encoders before the current one
  std::vector<TapRecord> records;
  auto last_flush = Clock::now();
  const auto emit = [this](RosTopic topic, std::uint64_t log_time, std::span<const std::uint8_t> cdr) {
    publish(topic, log_time, cdr);
  };
  for (;;) {
    {
      std::lock_guard lock(mutex_);
      if (new_tap_) {
        new_tap_ = false;
        tap = next_tap_;
        if (!mcap_) {
          if (encoder) laps_before += encoder->laps();
          encoder = std::make_unique<RosTopicEncoder>(options_.topics.ros);
        }
      }
    }
    if (options_.server) tell_link_state();
    if (!tap) {
      if (stopping_.load()) break;
      std::this_thread::sleep_for(kTakeWait);
      continue;
    }
    const bool open = tap->wait_and_take(records, kTakeWait);
    RosTopicEncoder& topics = mcap_ ? mcap_->encoder() : *encoder;
    if (options_.parameters) topics.set_filter(options_.parameters->filter());
    for (const TapRecord& r : records) {
      if (mcap_) mcap_->record(r.type, r.payload, r.t_ns);
      else topics.record(r.type, r.payload, r.t_ns, emit);
    }
    // Nothing came although the tap was closed, or stop() gave up waiting for it to close.
    const bool drained = records.empty() && (!open || stopping_.load());
    tap->recycle(records);
    laps_.store(laps_before + topics.laps());
    if (const auto dropped = tap->dropped()) {
      dropped_.store(dropped);
      topics.set_extra_diagnostics({{"tap_dropped_records", std::to_string(dropped)}});
    }
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
    if (drained) {
      if (stopping_.load()) break;
      tap.reset();  // closed: wait for the next one, or for stop()
    }
  }
}

}  // namespace ydscope
