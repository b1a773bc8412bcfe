#include "core/sim/pty_endpoint.h"

#include <fcntl.h>
#include <stdlib.h>
#include <sys/stat.h>
#include <termios.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <stdexcept>

#include "core/sim/sim_server.h"

namespace ydscope {

namespace {

std::string read_link(const std::string& path) {
  std::array<char, 4096> target{};
  const ssize_t n = ::readlink(path.c_str(), target.data(), target.size() - 1);
  return n < 0 ? std::string() : std::string(target.data(), static_cast<std::size_t>(n));
}

}  // namespace

void PtyEndpoint::check_link_free(const std::string& link) {
  struct stat st {};
  if (::lstat(link.c_str(), &st) != 0) return;  // absent: free
  struct stat target {};
  if (S_ISLNK(st.st_mode) && read_link(link).rfind("/dev/pts/", 0) == 0 && ::stat(link.c_str(), &target) != 0)
    return;  // a dangling link into /dev/pts: left behind by an earlier virtual lidar
  throw std::runtime_error(link +
                           " already exists and is not a stale pseudo-terminal link; remove it or choose another path");
}

PtyEndpoint::PtyEndpoint(std::string link) : link_(std::move(link)) {
  if (!link_.empty()) check_link_free(link_);
  master_ = ::posix_openpt(O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (master_ < 0 || ::grantpt(master_) != 0 || ::unlockpt(master_) != 0) {
    const int error = errno;
    if (master_ >= 0) ::close(master_);
    throw std::runtime_error(std::string("could not create a pseudo-terminal: ") + std::strerror(error));
  }
  std::array<char, 128> name{};
  ::ptsname_r(master_, name.data(), name.size());
  slave_path_ = name.data();
  // Raw 8N1 on the slave side (termios on the master applies to the slave), so a host that does not
  // set raw mode itself still gets bytes unchanged.
  termios tio{};
  if (::tcgetattr(master_, &tio) == 0) {
    ::cfmakeraw(&tio);
    ::tcsetattr(master_, TCSANOW, &tio);
  }
  if (!link_.empty()) {
    const std::string temp = link_ + ".ydscope-tmp";
    ::unlink(temp.c_str());
    if (::symlink(slave_path_.c_str(), temp.c_str()) != 0 || ::rename(temp.c_str(), link_.c_str()) != 0) {
      const int error = errno;
      ::unlink(temp.c_str());
      ::close(master_);
      throw std::runtime_error("could not create the link " + link_ + ": " + std::strerror(error));
    }
  }
}

PtyEndpoint::~PtyEndpoint() {
  if (!link_.empty() && read_link(link_) == slave_path_) ::unlink(link_.c_str());
  if (master_ >= 0) ::close(master_);
}

void PtyEndpoint::update_hangup(SimServerCounters* counters) {
  pollfd probe{master_, POLLIN, 0};
  if (::poll(&probe, 1, 0) < 0) return;
  const bool hung_up = (probe.revents & POLLHUP) != 0;
  if (hung_up_ && !hung_up && counters) ++counters->host_connections;
  hung_up_ = hung_up;
}

void PtyEndpoint::poll_fds(std::vector<pollfd>& fds) {
  update_hangup(nullptr);
  // With no host the master reports a hangup forever; waiting on it would spin, so leave it out
  // and let the server re-check on a short timeout.
  fds.push_back({hung_up_ ? -1 : master_, POLLIN, 0});
}

void PtyEndpoint::service(std::span<const pollfd> fds, std::vector<std::uint8_t>& host_bytes,
                          SimServerCounters& counters) {
  update_hangup(&counters);
  if (fds.empty() || (fds[0].revents & POLLIN) == 0 || hung_up_) return;
  std::array<std::uint8_t, 512> buffer{};
  for (;;) {
    const ssize_t n = ::read(master_, buffer.data(), buffer.size());
    if (n <= 0) break;
    host_bytes.insert(host_bytes.end(), buffer.begin(), buffer.begin() + n);
  }
}

std::size_t PtyEndpoint::send(std::span<const std::uint8_t> bytes) {
  if (hung_up_) return 0;
  std::size_t sent = 0;
  while (sent < bytes.size()) {
    const ssize_t n = ::write(master_, bytes.data() + sent, bytes.size() - sent);
    if (n > 0) {
      sent += static_cast<std::size_t>(n);
    } else if (n < 0 && errno == EINTR) {
      continue;
    } else {
      break;  // the host is not reading and the pty buffer is full: the rest overruns, as on a UART
    }
  }
  return sent;
}

}  // namespace ydscope
