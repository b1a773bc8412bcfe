#pragma once
// LidarFeed: the virtual G6 scanning, its bytes decoded and encoded to ROS messages by the same
// RosTopicEncoder `ydscope-cli serve` uses, and published to a FoxgloveServer from a thread of
// its own, `speed` times faster than real time. It remembers the log time of every /scan it
// published, so a test can tell whether a client got every lap.
#include <atomic>
#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <mutex>
#include <thread>
#include <vector>

#include "core/bridge/foxglove_server.h"

namespace ydscope::test {

class LidarFeed {
 public:
  explicit LidarFeed(foxglove::FoxgloveServer& server, double speed = 1.0);
  ~LidarFeed();  // stop()
  LidarFeed(const LidarFeed&) = delete;
  LidarFeed& operator=(const LidarFeed&) = delete;

  // Publishes nothing more once it returns.
  void stop();
  // Log times of the /scan messages published so far, in order.
  std::vector<std::uint64_t> scan_times() const;
  // The largest message (CDR bytes) published so far on any topic: what one queued lap can pin.
  std::size_t largest_message() const;
  // True once at least `count` /scan messages were published; false after `timeout`.
  bool wait_for_scans(std::size_t count, std::chrono::milliseconds timeout) const;

 private:
  void run(foxglove::FoxgloveServer& server, double speed);

  mutable std::mutex mutex_;
  mutable std::condition_variable published_;
  std::vector<std::uint64_t> scan_times_;
  std::size_t largest_message_ = 0;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

}  // namespace ydscope::test
