#include "core/link/serial_link.h"

#include <fcntl.h>
#include <sys/file.h>
#include <sys/ioctl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

#include <boost/asio/post.hpp>
#include <boost/asio/write.hpp>

#include "core/link/termios2_baud.h"

namespace ydscope {

std::string serial_open_error(const std::string& path, int errno_value) {
  const std::string head = "cannot open " + path + ": ";
  switch (errno_value) {
    case ENOENT:
    case ENODEV:
    case ENXIO: return head + "no such device; is the lidar plugged in? 'ydscope-cli ports' lists serial ports";
    case EACCES:
    case EPERM:
      return head +
             "permission denied; add yourself to the dialout group (then log in again), or install "
             "ydscope's udev rule /usr/lib/udev/rules.d/70-ydlidar.rules (in the .deb; by hand from "
             "assets/70-ydlidar.rules), which gives the logged-in user the port";
    case EBUSY: return head + "the port is busy; close the other program using it";
    case ENOTTY:
    case EINVAL: return head + "not a serial port; give a tty device such as /dev/ttyUSB0 or tcp://host:port";
    case EISDIR:
      return head +
             "it is a folder, not a serial port; give a device such as /dev/ttyUSB0 "
             "('ydscope-cli ports' lists them)";
    case EIO: return head + "input/output error; the device may have been unplugged, plug it in again";
    default: return head + std::strerror(errno_value);
  }
}

namespace {

// Claims the port for this process: TIOCEXCL refuses further opens of the tty (except by root),
// the advisory lock also stops a second ydscope run as root. Returns 0 or an errno value.
int claim_exclusively(int fd) {
  if (::flock(fd, LOCK_EX | LOCK_NB) != 0) return errno == EWOULDBLOCK ? EBUSY : errno;
  if (::ioctl(fd, TIOCEXCL) != 0) return errno;
  return 0;
}

}  // namespace

SerialLink::SerialLink(boost::asio::io_context& io, std::string path, std::uint32_t baud)
    : port_(io), path_(std::move(path)), baud_(baud) {}

std::unique_ptr<SerialLink> SerialLink::open(boost::asio::io_context& io, const std::string& path, std::uint32_t baud,
                                             std::string& error) {
  if (baud == 0) {
    error = "cannot open " + path + ": baud must be a positive number";
    return nullptr;
  }
  const int fd = ::open(path.c_str(), O_RDWR | O_NOCTTY | O_NONBLOCK | O_CLOEXEC);
  if (fd < 0) {
    error = serial_open_error(path, errno);
    return nullptr;
  }
  int err = claim_exclusively(fd);
  if (err == 0) err = termios2::configure_raw(fd, baud);
  if (err != 0) {
    error = err == EINVAL
                ? "cannot open " + path + ": the port refuses " + std::to_string(baud) + " baud; check the --baud value"
                : serial_open_error(path, err);
    ::close(fd);
    return nullptr;
  }
  std::unique_ptr<SerialLink> link(new SerialLink(io, path, baud));
  link->port_.assign(fd);
  return link;
}

boost::system::error_code SerialLink::read_available(std::span<std::uint8_t> buffer, std::size_t& got) {
  got = 0;
  const int port = port_.native_handle();
  while (got < buffer.size()) {
    const std::size_t asked = buffer.size() - got;
    const ssize_t n = ::read(port, buffer.data() + got, asked);
    if (n > 0) {
      got += static_cast<std::size_t>(n);
      // With VMIN 1 a tty read returns all that is waiting, so a short one leaves the port empty.
      if (static_cast<std::size_t>(n) < asked) {
        maybe_more_ = false;
        return {};
      }
      continue;
    }
    if (n < 0 && errno == EINTR) continue;
    if (n < 0 && (errno == EAGAIN || errno == EWOULDBLOCK)) {
      maybe_more_ = false;
      return {};
    }
    // EOF or an error: hand over what was read first; the next read meets the error again.
    maybe_more_ = true;
    if (got > 0) return {};
    return n == 0 ? boost::system::error_code(boost::asio::error::eof)
                  : boost::system::error_code(errno, boost::system::system_category());
  }
  maybe_more_ = true;  // the buffer filled up
  return {};
}

void SerialLink::async_read_some(std::span<std::uint8_t> buffer, IoHandler handler) {
  watch_input();
  if (!maybe_more_) {
    wait_then_read(buffer, std::move(handler));
    return;
  }
  // Input may be waiting already (the buffer filled last time, or the port is new): try at once,
  // from the io_context like any completion.
  boost::asio::post(port_.get_executor(), [this, buffer, handler = std::move(handler)]() mutable {
    if (!port_.is_open()) {
      handler(boost::asio::error::operation_aborted, 0);
      return;
    }
    read_or_wait(buffer, std::move(handler));
  });
}

void SerialLink::read_or_wait(std::span<std::uint8_t> buffer, IoHandler handler) {
  std::size_t got = 0;
  const boost::system::error_code ec = read_available(buffer, got);
  if (got > 0 || ec) {
    handler(ec, got);
    return;
  }
  wait_then_read(buffer, std::move(handler));  // nothing there (yet)
}

void SerialLink::wait_then_read(std::span<std::uint8_t> buffer, IoHandler handler) {
  port_.async_wait(boost::asio::posix::descriptor_base::wait_read,
                   [this, buffer, handler = std::move(handler)](const boost::system::error_code& ec) mutable {
                     if (ec) {
                       handler(ec, 0);
                       return;
                     }
                     read_or_wait(buffer, std::move(handler));
                   });
}

void SerialLink::stop_watching_input() {
  // Releasing the descriptor would abort a write in flight; commands are rare, so just stay.
  if (writing_ || unwatched_fd_ >= 0 || !port_.is_open()) return;
  unwatched_fd_ = port_.release();
}

void SerialLink::watch_input() {
  if (unwatched_fd_ < 0) return;
  boost::system::error_code ec;
  port_.assign(unwatched_fd_, ec);
  if (ec) return;  // stays out; the next read reports the closed port
  unwatched_fd_ = -1;
  maybe_more_ = true;  // input has been piling up
}

void SerialLink::async_write(std::span<const std::uint8_t> bytes, IoHandler handler) {
  watch_input();
  writing_ = true;
  boost::asio::async_write(port_, boost::asio::buffer(bytes.data(), bytes.size()),
                           [this, handler = std::move(handler)](const boost::system::error_code& ec, std::size_t n) {
                             writing_ = false;
                             handler(ec, n);
                           });
}

void SerialLink::close() {
  boost::system::error_code ignored;
  if (unwatched_fd_ >= 0) ::close(unwatched_fd_);
  unwatched_fd_ = -1;
  port_.cancel(ignored);
  port_.close(ignored);
}

bool SerialLink::set_baud(std::uint32_t baud, std::string& error) {
  if (native_handle() < 0) {
    error = path_ + " is closed";
    return false;
  }
  if (baud == 0) {
    error = "baud must be a positive number";
    return false;
  }
  if (const int err = termios2::set_baud(native_handle(), baud)) {
    error = "cannot set " + path_ + " to " + std::to_string(baud) + " baud: " + std::strerror(err);
    return false;
  }
  baud_ = baud;
  return true;
}

std::string SerialLink::describe() const { return path_ + " at " + std::to_string(baud_) + " baud"; }

int SerialLink::native_handle() {
  if (unwatched_fd_ >= 0) return unwatched_fd_;
  return port_.is_open() ? port_.native_handle() : -1;
}

}  // namespace ydscope
