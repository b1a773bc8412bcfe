#pragma once
// ByteLink over a serial port (USB-serial bridge or pseudo-terminal): raw 8N1, no flow control,
// any baud through termios2. A pseudo-terminal takes exactly this path, so tests against the
// virtual lidar exercise the same code a real port does.
#include <cstdint>
#include <memory>
#include <string>

#include <boost/asio/io_context.hpp>
#include <boost/asio/serial_port.hpp>

#include "core/link/byte_link.h"

namespace ydscope {

class SerialLink final : public ByteLink {
 public:
  // Opens and configures the port; on failure returns null and sets `error` to one sentence
  // naming the port, the cause and what to try.
  static std::unique_ptr<SerialLink> open(boost::asio::io_context& io, const std::string& path,
                                          std::uint32_t baud, std::string& error);

  void async_read_some(std::span<std::uint8_t> buffer, IoHandler handler) override;
  void async_write(std::span<const std::uint8_t> bytes, IoHandler handler) override;
  void close() override;
  bool set_baud(std::uint32_t baud, std::string& error) override;
  bool accepts_commands() const override { return true; }
  std::string describe() const override;

  const std::string& path() const { return path_; }
  std::uint32_t baud() const { return baud_; }
  // The port's file descriptor (-1 once closed), for checks of the line settings.
  int native_handle();

 private:
  SerialLink(boost::asio::io_context& io, std::string path, std::uint32_t baud);

  boost::asio::serial_port port_;
  std::string path_;
  std::uint32_t baud_;
};

// "cannot open /dev/ttyUSB0: permission denied; add yourself to the dialout group ..." from an
// errno of open() or of configuring the line. Shared with port discovery messages.
std::string serial_open_error(const std::string& path, int errno_value);

}  // namespace ydscope
