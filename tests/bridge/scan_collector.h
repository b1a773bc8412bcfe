#pragma once
// ScanCollector: a steady client on a thread of its own that subscribes to /scan and keeps
// every lap's log time, until it has the lap a test names (finish_at). The test then checks
// the laps against what the feed published: every one since the first it got, in order.
#include <cstdint>
#include <mutex>
#include <optional>
#include <thread>
#include <vector>

#include "support/ws_test_client.h"

namespace ydscope::test {

class ScanCollector {
 public:
  explicit ScanCollector(std::uint16_t port) : client_(port) {
    subscribed_ = client_.subscribe(1, "/scan");
    thread_ = std::thread([this] { run(); });
  }
  ~ScanCollector() { finish_at(0); }
  ScanCollector(const ScanCollector&) = delete;
  ScanCollector& operator=(const ScanCollector&) = delete;

  bool subscribed() const { return subscribed_; }
  std::uint16_t local_port() const { return client_.local_port(); }
  // Reads on until the lap logged at `last` (or a later one) arrived, or a read timed out.
  void finish_at(std::uint64_t last) {
    {
      std::lock_guard lock(mutex_);
      if (!last_) last_ = last;
    }
    if (thread_.joinable()) thread_.join();
  }
  std::vector<std::uint64_t> times() const {
    std::lock_guard lock(mutex_);
    return times_;
  }
  // Laps received so far (read while it runs, to compare with the laps published meanwhile).
  std::size_t count() const {
    std::lock_guard lock(mutex_);
    return times_.size();
  }
  bool failed() const {
    std::lock_guard lock(mutex_);
    return failed_;
  }

 private:
  void run() {
    for (;;) {
      {
        std::lock_guard lock(mutex_);
        if (last_ && (!times_.empty() && times_.back() >= *last_)) return;
      }
      const auto message = client_.read_binary(30s);
      std::lock_guard lock(mutex_);
      if (!message) {
        failed_ = true;
        return;
      }
      times_.push_back(message->log_time_ns);
    }
  }

  WsTestClient client_;
  bool subscribed_ = false;
  mutable std::mutex mutex_;
  std::optional<std::uint64_t> last_;
  std::vector<std::uint64_t> times_;
  bool failed_ = false;
  std::thread thread_;
};

}  // namespace ydscope::test
