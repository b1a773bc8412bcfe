#include "core/link/port_watch.h"

#include <sys/inotify.h>
#include <unistd.h>

#include <array>
#include <cstring>
#include <filesystem>

namespace ydscope {

namespace {
constexpr std::uint32_t kEvents = IN_CREATE | IN_MOVED_TO | IN_ATTRIB;
}

PortWatch::Target PortWatch::target_for(const std::string& path) {
  namespace fs = std::filesystem;
  fs::path wanted = fs::path(path).lexically_normal();
  if (wanted.is_relative()) wanted = fs::current_path() / wanted;
  // Walk up until a directory exists; the name is the component just below it on the way down.
  fs::path child = wanted;
  fs::path dir = wanted.parent_path();
  std::error_code ec;
  while (!dir.empty() && !fs::is_directory(dir, ec) && dir != dir.root_path()) {
    child = dir;
    dir = dir.parent_path();
  }
  return {dir.string(), child.filename().string()};
}

bool PortWatch::arm(const std::string& path, std::function<void()> on_change) {
  disarm();
  target_ = target_for(path);
  if (target_.directory.empty() || target_.name.empty()) return false;
  const int fd = ::inotify_init1(IN_NONBLOCK | IN_CLOEXEC);
  if (fd < 0) return false;
  if (::inotify_add_watch(fd, target_.directory.c_str(), kEvents) < 0) {
    ::close(fd);
    return false;
  }
  descriptor_.assign(fd);
  on_change_ = std::move(on_change);
  wait();
  return true;
}

void PortWatch::disarm() {
  ++generation_;
  on_change_ = nullptr;
  if (descriptor_.is_open()) {
    boost::system::error_code ec;
    descriptor_.close(ec);  // cancels the wait; its handler sees a stale generation
  }
}

void PortWatch::wait() {
  descriptor_.async_wait(boost::asio::posix::stream_descriptor::wait_read,
                         [this, generation = generation_](const boost::system::error_code& ec) {
                           if (ec || generation != generation_) return;
                           alignas(inotify_event) std::array<char, 4096> events;
                           const ssize_t got = ::read(descriptor_.native_handle(), events.data(), events.size());
                           if (got > 0 && matches(events.data(), static_cast<std::size_t>(got))) {
                             auto done = std::move(on_change_);
                             disarm();
                             if (done) done();
                             return;
                           }
                           wait();  // another entry of the directory changed: keep waiting
                         });
}

bool PortWatch::matches(const char* events, std::size_t size) const {
  std::size_t at = 0;
  while (at + sizeof(inotify_event) <= size) {
    inotify_event event;
    std::memcpy(&event, events + at, sizeof event);
    if (event.mask & IN_Q_OVERFLOW) return true;  // events were lost: one of them may have been ours
    const char* name = events + at + sizeof(inotify_event);
    if (event.len > 0 && at + sizeof(inotify_event) + event.len <= size &&
        std::strncmp(name, target_.name.c_str(), event.len) == 0 && target_.name.size() < event.len)
      return true;
    at += sizeof(inotify_event) + event.len;
  }
  return false;
}

}  // namespace ydscope
