#include "core/link/serial_link.h"

#include <cerrno>
#include <cstring>

#include <boost/asio/write.hpp>

#include "core/link/termios2_baud.h"

namespace ydscope {

std::string serial_open_error(const std::string& path, int errno_value) {
  const std::string head = "cannot open " + path + ": ";
  switch (errno_value) {
    case ENOENT:
    case ENODEV:
    case ENXIO:
      return head + "no such device; is the lidar plugged in? 'ydscope-cli ports' lists serial ports";
    case EACCES:
    case EPERM:
      return head + "permission denied; add yourself to the dialout group (then log in again) or "
                    "copy assets/99-ydlidar.rules to /etc/udev/rules.d";
    case EBUSY:
      return head + "the port is busy; close the other program using it";
    case ENOTTY:
    case EINVAL:
      return head + "not a serial port; give a tty device such as /dev/ttyUSB0 or tcp://host:port";
    case EIO:
      return head + "input/output error; the device may have been unplugged, plug it in again";
    default:
      return head + std::strerror(errno_value);
  }
}

SerialLink::SerialLink(boost::asio::io_context& io, std::string path, std::uint32_t baud)
    : port_(io), path_(std::move(path)), baud_(baud) {}

std::unique_ptr<SerialLink> SerialLink::open(boost::asio::io_context& io, const std::string& path,
                                             std::uint32_t baud, std::string& error) {
  if (baud == 0) {
    error = "cannot open " + path + ": baud must be a positive number";
    return nullptr;
  }
  std::unique_ptr<SerialLink> link(new SerialLink(io, path, baud));
  boost::system::error_code ec;
  link->port_.open(path, ec);  // O_RDWR | O_NOCTTY | O_NONBLOCK
  if (ec) {
    error = serial_open_error(path, ec.value());
    return nullptr;
  }
  if (const int err = termios2::configure_raw(link->port_.native_handle(), baud)) {
    error = err == EINVAL ? "cannot open " + path + ": the port refuses " + std::to_string(baud) +
                                " baud; check the --baud value"
                          : serial_open_error(path, err);
    link->port_.close(ec);
    return nullptr;
  }
  return link;
}

void SerialLink::async_read_some(std::span<std::uint8_t> buffer, IoHandler handler) {
  port_.async_read_some(boost::asio::buffer(buffer.data(), buffer.size()), std::move(handler));
}

void SerialLink::async_write(std::span<const std::uint8_t> bytes, IoHandler handler) {
  boost::asio::async_write(port_, boost::asio::buffer(bytes.data(), bytes.size()), std::move(handler));
}

void SerialLink::close() {
  boost::system::error_code ignored;
  port_.cancel(ignored);
  port_.close(ignored);
}

bool SerialLink::set_baud(std::uint32_t baud, std::string& error) {
  if (!port_.is_open()) {
    error = path_ + " is closed";
    return false;
  }
  if (baud == 0) {
    error = "baud must be a positive number";
    return false;
  }
  if (const int err = termios2::set_baud(port_.native_handle(), baud)) {
    error = "cannot set " + path_ + " to " + std::to_string(baud) + " baud: " + std::strerror(err);
    return false;
  }
  baud_ = baud;
  return true;
}

std::string SerialLink::describe() const { return path_ + " at " + std::to_string(baud_) + " baud"; }

int SerialLink::native_handle() { return port_.is_open() ? port_.native_handle() : -1; }

}  // namespace ydscope
