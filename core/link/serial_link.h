#pragma once
// ByteLink over a serial port (USB-serial bridge or pseudo-terminal): raw 8N1, no flow control,
// any baud through termios2, opened exclusively (TIOCEXCL and an advisory lock, so a second
// ydscope on the same port is told it is busy). A pseudo-terminal takes exactly this path, so
// tests against the virtual lidar exercise the same code a real port does.
//
// Reads wait for readiness and then empty the port in one go, so a wake-up costs one epoll wait
// and usually one read(). stop_watching_input() takes the port out of the reactor, so input that
// arrives while the session holds off reading does not wake the I/O thread chunk by chunk (VMIN
// would not help: the kernel wakes pollers on every chunk whatever VMIN says).
#include <cstdint>
#include <memory>
#include <string>

#include <boost/asio/io_context.hpp>
#include <boost/asio/posix/stream_descriptor.hpp>

#include "core/link/byte_link.h"

namespace ydscope {

class SerialLink final : public ByteLink {
 public:
  // Opens and configures the port; on failure returns null and sets `error` to one sentence
  // naming the port, the cause and what to try.
  static std::unique_ptr<SerialLink> open(boost::asio::io_context& io, const std::string& path, std::uint32_t baud,
                                          std::string& error);

  void async_read_some(std::span<std::uint8_t> buffer, IoHandler handler) override;
  void async_write(std::span<const std::uint8_t> bytes, IoHandler handler) override;
  void close() override;
  bool set_baud(std::uint32_t baud, std::string& error) override;
  void stop_watching_input() override;
  double line_bytes_per_s() const override { return baud_ / 10.0; }
  bool accepts_commands() const override { return true; }
  std::string describe() const override;

  const std::string& path() const { return path_; }
  std::uint32_t baud() const { return baud_; }
  // The port's file descriptor (-1 once closed), for checks of the line settings.
  int native_handle();

 private:
  SerialLink(boost::asio::io_context& io, std::string path, std::uint32_t baud);
  // Reads what has arrived into `buffer` until the port is empty or the buffer full.
  boost::system::error_code read_available(std::span<std::uint8_t> buffer, std::size_t& got);
  // Completes `handler` with what has arrived, or waits for input first if there is none.
  void read_or_wait(std::span<std::uint8_t> buffer, IoHandler handler);
  void wait_then_read(std::span<std::uint8_t> buffer, IoHandler handler);
  // Puts the port back into the reactor after stop_watching_input().
  void watch_input();

  boost::asio::posix::stream_descriptor port_;
  int unwatched_fd_ = -1;  // the port while it is out of the reactor, else -1
  std::string path_;
  std::uint32_t baud_;
  bool maybe_more_ = true;  // the last read stopped with input perhaps still waiting
  bool writing_ = false;    // a write is in flight (the port must stay in the reactor)
};

// "cannot open /dev/ttyUSB0: permission denied; add yourself to the dialout group ..." from an
// errno of open() or of configuring the line. Shared with port discovery messages.
std::string serial_open_error(const std::string& path, int errno_value);

}  // namespace ydscope
