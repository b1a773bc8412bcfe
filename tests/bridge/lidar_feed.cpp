#include "bridge/lidar_feed.h"

#include <algorithm>
#include <memory>

#include "core/bridge/ros_topic_channels.h"
#include "core/export/ros_topic_encoder.h"
#include "core/sim/virtual_lidar.h"

namespace ydscope::test {

LidarFeed::LidarFeed(foxglove::FoxgloveServer& server, double speed)
    : thread_([this, &server, speed] { run(server, speed); }) {}

LidarFeed::~LidarFeed() { stop(); }

void LidarFeed::stop() {
  stop_.store(true);
  if (thread_.joinable()) thread_.join();
}

void LidarFeed::run(foxglove::FoxgloveServer& server, double speed) {
  constexpr std::int64_t kStepNs = 5'000'000;  // the bytes of 5 ms of device time per step
  VirtualLidarConfig config;
  config.model = Model::G6;
  VirtualLidar lidar(config);
  RosExportOptions options;
  options.model = Model::G6;
  options.link_bytes = false;
  RosTopicEncoder encoder(options);
  const std::uint8_t start_scan[] = {0xA5, 0x60};
  lidar.receive(start_scan, 0);

  std::vector<std::uint8_t> bytes;
  std::int64_t device_ns = 0;
  const auto started = std::chrono::steady_clock::now();
  while (!stop_.load()) {
    device_ns += kStepNs;
    bytes.clear();
    lidar.produce(device_ns, bytes);
    encoder.device_bytes(bytes, device_ns,
                         [&](RosTopic topic, std::uint64_t log_time, std::span<const std::uint8_t> cdr) {
                           // Noted before it is published, so no client can have a lap the test does not know of.
                           {
                             std::lock_guard lock(mutex_);
                             largest_message_ = std::max(largest_message_, cdr.size());
                             if (topic == RosTopic::Scan) {
                               scan_times_.push_back(log_time);
                               published_.notify_all();
                             }
                           }
                           server.publish(foxglove::channel_id(topic), log_time,
                                          std::make_shared<const std::vector<std::uint8_t>>(cdr.begin(), cdr.end()));
                         });
    std::this_thread::sleep_until(
        started + std::chrono::nanoseconds(static_cast<std::int64_t>(static_cast<double>(device_ns) / speed)));
  }
}

std::vector<std::uint64_t> LidarFeed::scan_times() const {
  std::lock_guard lock(mutex_);
  return scan_times_;
}

std::size_t LidarFeed::largest_message() const {
  std::lock_guard lock(mutex_);
  return largest_message_;
}

bool LidarFeed::wait_for_scans(std::size_t count, std::chrono::milliseconds timeout) const {
  std::unique_lock lock(mutex_);
  return published_.wait_for(lock, timeout, [&] { return scan_times_.size() >= count; });
}

}  // namespace ydscope::test
