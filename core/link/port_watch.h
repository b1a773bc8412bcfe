#pragma once
// PortWatch: tells a waiting reconnect that a serial port's path may have come back, so it can
// try at once instead of sleeping out its backoff. A re-plugged USB lidar reappears as a new
// device node (/dev/ttyUSB0, created and then given its permissions by udev) and often as a
// symlink (/dev/serial/by-id/..., or the virtual lidar's --pty LINK, replaced by a rename).
//
// Linux inotify on the nearest directory of the path that exists: an entry created, moved in or
// changed in attributes under the name the path continues with wakes the waiter. When that is a
// directory that came back (by-id/ is removed with its last device), the next arm() watches it.
// Waiting costs no CPU: the descriptor sits in the io_context's reactor. Where inotify is not
// available arm() returns false and the caller keeps its timer.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>

#include <boost/asio/io_context.hpp>
#include <boost/asio/posix/stream_descriptor.hpp>

namespace ydscope {

class PortWatch {
 public:
  explicit PortWatch(boost::asio::io_context& io) : descriptor_(io) {}
  ~PortWatch() { disarm(); }
  PortWatch(const PortWatch&) = delete;
  PortWatch& operator=(const PortWatch&) = delete;

  // Watches for `path` (an absolute or relative file path) to change; on_change runs once, on the
  // io_context, at the first matching event. Replaces an earlier arm(). False when no watch could
  // be set (inotify unavailable, or no directory of the path exists at all).
  bool arm(const std::string& path, std::function<void()> on_change);
  // Stops watching; on_change will not run.
  void disarm();

  // The directory arm() watches for `path` and the entry name in it that leads to the path.
  struct Target {
    std::string directory;
    std::string name;
  };
  static Target target_for(const std::string& path);

 private:
  void wait();
  bool matches(const char* events, std::size_t size) const;

  boost::asio::posix::stream_descriptor descriptor_;
  Target target_;
  std::function<void()> on_change_;
  std::uint64_t generation_ = 0;  // a wait of an earlier arm() ignores what it reads
};

}  // namespace ydscope
