#include "app/cli/port_wait.h"

#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <functional>

#include <boost/asio/io_context.hpp>
#include <boost/asio/steady_timer.hpp>

#include "core/link/port_discovery.h"
#include "core/link/port_watch.h"

namespace ydscope::cli {

namespace {

// How often the condition is looked at when nothing wakes the wait sooner: also how long Ctrl-C
// may take to be noticed.
constexpr std::chrono::milliseconds kLook{200};

bool openable(const std::string& path) { return ::access(path.c_str(), R_OK | W_OK) == 0; }

// Looks at `ready` until it holds or `stop` is set; a watch on `watched` (when given) wakes the
// look early instead of waiting out the period.
bool wait_for(const std::function<bool()>& ready, const std::string& watched, const std::atomic<bool>& stop) {
  boost::asio::io_context io;
  PortWatch watch(io);
  boost::asio::steady_timer tick(io);
  bool armed = false;
  while (!stop.load()) {
    if (ready()) return true;
    if (!watched.empty() && !armed) {
      armed = watch.arm(watched, [&io, &armed] {
        armed = false;
        io.stop();
      });
      if (ready()) return true;  // it came between the look and the watch
    }
    // The timer gives the io_context work, so run_for waits out the period when no watch is set.
    tick.expires_after(kLook);
    tick.async_wait([](const boost::system::error_code&) {});
    io.run_for(kLook);
    io.restart();
  }
  return false;
}

}  // namespace

std::optional<std::string> wait_for_unit(const std::string& port, const std::atomic<bool>& stop) {
  std::string found;
  const auto present = [&] {
    if (!port.empty()) {
      found = port;
      return openable(port);
    }
    const std::optional<SerialPortInfo> candidate = first_lidar_candidate(PortDiscovery().list());
    found = candidate ? candidate->preferred_path() : std::string();
    return candidate && openable(found);
  };
  if (!wait_for(present, port, stop)) return std::nullopt;
  return found;
}

std::optional<PortNode> port_node(const std::string& path) {
  // The name's own inode (lstat): a link made again for a new unit is a new file even when it
  // points at a reused /dev/pts number, and udev makes /dev/serial/by-id links and nodes afresh.
  struct stat info {};
  if (::lstat(path.c_str(), &info) != 0 || ::access(path.c_str(), F_OK) != 0) return std::nullopt;
  return PortNode{static_cast<std::uint64_t>(info.st_dev), static_cast<std::uint64_t>(info.st_ino),
                  static_cast<std::int64_t>(info.st_ctim.tv_sec) * 1'000'000'000 + info.st_ctim.tv_nsec};
}

bool wait_until_unplugged(const std::string& path, const std::optional<PortNode>& unit, const std::atomic<bool>& stop) {
  return wait_for([&] { return !unit || port_node(path) != unit; }, {}, stop);
}

}  // namespace ydscope::cli
