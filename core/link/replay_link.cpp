#include "core/link/replay_link.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <mutex>
#include <utility>
#include <vector>

#include <boost/asio/post.hpp>
#include <boost/asio/steady_timer.hpp>

#include "core/record/recording_reader.h"
#include "core/record/recording_plan.h"

namespace ydscope {
namespace {

// The longest single timer wait; the timer re-checks the playback point when it fires, so a cap
// changes nothing but keeps the arithmetic far from int64's limits.
constexpr double kMaxWaitNs = 3600e9;

// ns as int64, saturated: a playback point far in the future must not wrap to the past.
std::int64_t saturated_ns(double ns) {
  constexpr double kLimit = 4e18;  // below INT64_MAX (9.2e18), exactly representable
  return static_cast<std::int64_t>(std::clamp(ns, -kLimit, kLimit));
}

}  // namespace

double bounded_replay_speed(double speed) {
  if (std::isnan(speed)) return 1.0;
  if (speed <= 0.0) return 0.0;
  return std::clamp(speed, kMinReplaySpeed, kMaxReplaySpeed);
}

// The playback state. Lives on the io_context's thread; controls reach it through posted
// handlers that hold a shared_ptr, so a control racing the link's destruction stays safe.
class ReplayLink::Core : public std::enable_shared_from_this<Core> {
 public:
  using Clock = std::chrono::steady_clock;

  Core(boost::asio::io_context& io, std::unique_ptr<RecordingReader> reader, const ReplayOptions& options,
       std::int64_t duration_ns)
      : io_(io),
        timer_(io),
        reader_(std::move(reader)),
        source_(options.source),
        speed_(bounded_replay_speed(options.speed)),
        paused_(options.paused),
        loop_(options.loop),
        skip_gaps_(options.skip_gaps),
        on_gap_(options.on_gap),
        anchor_wall_(Clock::now()) {
    status_.duration_ns = duration_ns;
    status_.skip_gaps = skip_gaps_;
    publish();
  }

  boost::asio::io_context::executor_type executor() { return io_.get_executor(); }

  void read(std::span<std::uint8_t> buffer, IoHandler handler) {
    if (closed_) {
      complete(std::move(handler), boost::asio::error::operation_aborted, 0);
      return;
    }
    read_buffer_ = buffer;
    read_handler_ = std::move(handler);
    pump();
  }

  void close() {
    closed_ = true;
    ++wait_generation_;
    timer_.cancel();
    if (read_handler_) complete(std::exchange(read_handler_, nullptr), boost::asio::error::operation_aborted, 0);
  }

  void set_speed(double speed) {
    rebase();
    speed_ = bounded_replay_speed(speed);
    reschedule();
  }
  void set_paused(bool paused) {
    if (paused == paused_) return;
    rebase();
    paused_ = paused;
    reschedule();
  }
  void set_loop(bool loop) {
    loop_ = loop;
    publish();
  }
  void restart() {
    reader_->rewind();
    last_device_t_ = 0;
    have_chunk_ = false;
    finished_ = false;
    anchor_position_ = 0;
    anchor_wall_ = Clock::now();
    reschedule();
  }

  // I/O thread: the recorded time of the bytes the last read delivered.
  std::int64_t delivered_t() const { return delivered_t_; }

  // Status, any thread.
  ReplayStatus status() const {
    const std::lock_guard lock(status_mutex_);
    return status_;
  }

 private:
  std::int64_t position_now() const {
    if (paused_ || speed_ == 0.0) return anchor_position_;
    const auto elapsed = std::chrono::duration_cast<std::chrono::nanoseconds>(Clock::now() - anchor_wall_).count();
    return saturated_ns(static_cast<double>(anchor_position_) + static_cast<double>(elapsed) * speed_);
  }
  // Freezes the playback point so the next speed or pause state continues from it.
  void rebase() {
    anchor_position_ = position_now();
    anchor_wall_ = Clock::now();
  }
  void reschedule() {
    ++wait_generation_;
    timer_.cancel();
    publish();
    pump();
  }

  // Next device->host record into chunk_; false at the end of the recording.
  bool load_next() {
    RecordView record;
    while (reader_->next(record)) {
      if (record.type != RecordType::DeviceToHost || record.payload.empty() || record.source != source_) continue;
      if (const auto gap = long_gap(last_device_t_, record.t_ns); gap && speed_ > 0.0) meet_gap(*gap);
      last_device_t_ = record.t_ns;
      chunk_.assign(record.payload.begin(), record.payload.end());
      chunk_offset_ = 0;
      chunk_t_ = record.t_ns;
      have_chunk_ = true;
      return true;
    }
    return false;
  }

  // Playback reaches a long gap: past it at once (the playback point jumps its length), or not.
  void meet_gap(const RecordingGap& gap) {
    if (skip_gaps_) {
      rebase();
      anchor_position_ = saturated_ns(static_cast<double>(anchor_position_) + static_cast<double>(gap.length_ns));
    }
    update_status([&gap](ReplayStatus& status) {
      status.last_gap = gap;
      ++status.gaps;
    });
    if (on_gap_) on_gap_(gap, skip_gaps_);
  }

  void pump() {
    if (!read_handler_ || closed_) return;
    if (!have_chunk_ && !finished_ && !load_next()) {
      if (loop_ && pass_bytes_ > 0) {  // a recording without device bytes would spin
        reader_->rewind();
        last_device_t_ = 0;
        pass_bytes_ = 0;
        anchor_position_ = 0;
        anchor_wall_ = Clock::now();
        update_status([](ReplayStatus& status) { ++status.loops; });
        load_next();
      } else {
        finished_ = true;
      }
    }
    if (finished_) {
      publish();
      complete(std::exchange(read_handler_, nullptr), boost::asio::error::eof, 0);
      return;
    }
    if (paused_) return;  // set_paused(false) pumps again
    // In double and saturated: whatever the times and the speed, the wait is a positive number
    // of nanoseconds (an overflow here once made the timer fire again and again, forever).
    const double ahead_ns = static_cast<double>(chunk_t_) - static_cast<double>(position_now());
    if (speed_ == 0.0 || ahead_ns <= 0.0) {
      deliver();
      return;
    }
    const auto wait = std::chrono::nanoseconds(saturated_ns(std::clamp(ahead_ns / speed_, 1.0, kMaxWaitNs)));
    timer_.expires_after(wait);
    const std::uint64_t generation = ++wait_generation_;
    timer_.async_wait([self = shared_from_this(), generation](const boost::system::error_code& ec) {
      if (!ec && generation == self->wait_generation_) self->pump();
    });
  }

  void deliver() {
    const std::size_t n = std::min(read_buffer_.size(), chunk_.size() - chunk_offset_);
    std::memcpy(read_buffer_.data(), chunk_.data() + chunk_offset_, n);
    chunk_offset_ += n;
    if (chunk_offset_ == chunk_.size()) have_chunk_ = false;
    if (speed_ == 0.0) anchor_position_ = chunk_t_;
    delivered_t_ = chunk_t_;
    pass_bytes_ += n;
    publish(n);
    complete(std::exchange(read_handler_, nullptr), {}, n);
  }

  // Handlers never run inside the call that started the operation.
  void complete(IoHandler handler, boost::system::error_code ec, std::size_t n) {
    boost::asio::post(io_, [handler = std::move(handler), ec, n] { handler(ec, n); });
  }

  // One lock around every change, so status() reads one moment, never fields from two.
  template <class Change>
  void update_status(Change change) {
    const std::lock_guard lock(status_mutex_);
    change(status_);
  }

  // `delivered`: device bytes the read now completing hands over (one lock for both changes).
  void publish(std::size_t delivered = 0) {
    const std::int64_t position = position_now();
    update_status([&](ReplayStatus& status) {
      status.bytes += delivered;
      // Within the recording: an I/O thread that runs late must not show a point past its end.
      status.position_ns = std::clamp<std::int64_t>(position, 0, status.duration_ns);
      status.speed = speed_;
      status.paused = paused_;
      status.loop = loop_;
      status.finished = finished_;
    });
  }

  boost::asio::io_context& io_;
  boost::asio::steady_timer timer_;
  std::unique_ptr<RecordingReader> reader_;
  std::uint16_t source_;
  std::vector<std::uint8_t> chunk_;
  std::size_t chunk_offset_ = 0;
  std::int64_t chunk_t_ = 0;
  std::int64_t delivered_t_ = 0;  // recorded time of the bytes the last read delivered
  bool have_chunk_ = false;
  std::span<std::uint8_t> read_buffer_;
  IoHandler read_handler_;
  double speed_;
  bool paused_;
  bool loop_;
  const bool skip_gaps_;
  const std::function<void(const RecordingGap&, bool)> on_gap_;
  std::int64_t last_device_t_ = 0;  // recording time of the last device record loaded, for gaps
  bool finished_ = false;
  bool closed_ = false;
  std::int64_t anchor_position_ = 0;
  Clock::time_point anchor_wall_;
  std::uint64_t wait_generation_ = 0;
  std::uint64_t pass_bytes_ = 0;

  mutable std::mutex status_mutex_;
  ReplayStatus status_;  // guarded by status_mutex_
};

ReplayLink::ReplayLink(std::shared_ptr<Core> core, std::string path, RecordingMetadata metadata,
                       std::vector<std::string> warnings)
    : core_(std::move(core)), path_(std::move(path)), metadata_(std::move(metadata)), warnings_(std::move(warnings)) {}

ReplayLink::~ReplayLink() {
  // The last owner may be another thread (a UI holding the link for its controls): the playback
  // state belongs to the io_context's thread, so close it there.
  if (core_->executor().running_in_this_thread()) {
    core_->close();
  } else {
    boost::asio::post(core_->executor(), [core = core_] { core->close(); });
  }
}

std::unique_ptr<ReplayLink> ReplayLink::open(boost::asio::io_context& io, const std::string& path,
                                             ReplayOptions options, std::string& error, RecordingOpenFailure* failure) {
  const auto summary = summarize_recording(path, error, failure);
  if (!summary) return nullptr;
  if (options.source >= summary->sources.size()) {
    error = path + " has no source " + std::to_string(options.source) + " (it holds " +
            std::to_string(summary->sources.size()) + ")";
    return nullptr;
  }
  if (error = nothing_to_replay(*summary, path); !error.empty()) return nullptr;
  if (summary->sources[options.source].device_bytes == 0) {
    error = path + "'s source " + std::to_string(options.source) + " holds no bytes from a device; nothing to replay";
    return nullptr;
  }
  auto reader = RecordingReader::open(path, error);
  if (!reader) return nullptr;
  auto core = std::make_shared<Core>(io, std::move(reader), options, summary->duration_ns);
  return std::unique_ptr<ReplayLink>(
      new ReplayLink(std::move(core), path, summary->sources[options.source].metadata, summary->damage));
}

void ReplayLink::async_read_some(std::span<std::uint8_t> buffer, IoHandler handler) {
  core_->read(buffer, std::move(handler));
}

void ReplayLink::async_write(std::span<const std::uint8_t> bytes, IoHandler handler) {
  const std::size_t n = bytes.size();
  boost::asio::post(core_->executor(), [handler = std::move(handler), n] { handler({}, n); });
}

void ReplayLink::close() { core_->close(); }

bool ReplayLink::set_baud(std::uint32_t /*baud*/, std::string& error) {
  error = describe() + " has no line rate to set";
  return false;
}

std::string ReplayLink::describe() const { return "replay of " + std::filesystem::path(path_).filename().string(); }

void ReplayLink::set_speed(double speed) {
  boost::asio::post(core_->executor(), [core = core_, speed] { core->set_speed(speed); });
}
void ReplayLink::set_paused(bool paused) {
  boost::asio::post(core_->executor(), [core = core_, paused] { core->set_paused(paused); });
}
void ReplayLink::set_loop(bool loop) {
  boost::asio::post(core_->executor(), [core = core_, loop] { core->set_loop(loop); });
}
void ReplayLink::restart() {
  boost::asio::post(core_->executor(), [core = core_] { core->restart(); });
}

ReplayStatus ReplayLink::status() const { return core_->status(); }
std::int64_t ReplayLink::recorded_time_of_last_read() const { return core_->delivered_t(); }

}  // namespace ydscope
