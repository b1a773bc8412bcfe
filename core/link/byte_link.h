#pragma once
// A byte pipe to a lidar, driven by the session's io_context: a serial port (termios2 baud),
// a TCP bridge (tcp://host:port), or the replay of a recording. The session only sees this.
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>

#include <boost/asio/io_context.hpp>
#include <boost/system/error_code.hpp>

#include "core/record/recording_metadata.h"

namespace ydscope {

class ByteLink {
 public:
  using IoHandler = std::function<void(const boost::system::error_code&, std::size_t)>;

  virtual ~ByteLink() = default;
  // One read of whatever has arrived (at most buffer.size() bytes). The buffer must outlive it.
  virtual void async_read_some(std::span<std::uint8_t> buffer, IoHandler handler) = 0;
  // Writes all bytes (commands are two bytes). The bytes must outlive the call's completion.
  virtual void async_write(std::span<const std::uint8_t> bytes, IoHandler handler) = 0;
  // Cancels pending operations (their handlers see operation_aborted) and releases the port.
  virtual void close() = 0;
  // Until the next async_read_some or async_write, arriving input may wait in the kernel without
  // waking the I/O thread at all (the session holds off reading mid-lap). Links for which waiting
  // saves nothing ignore it.
  virtual void stop_watching_input() {}
  // The most bytes per second the link can deliver (a serial line: baud / 10); 0 when unbounded.
  // Holding off reads is kept short enough that the kernel's buffer cannot fill meanwhile.
  virtual double line_bytes_per_s() const { return 0; }
  // Changes the line rate where there is one (serial); baud probing uses it. False if unsupported.
  virtual bool set_baud(std::uint32_t baud, std::string& error) = 0;
  // A replay's recorded metadata (the device the bytes came from); null for a live link.
  virtual const RecordingMetadata* recording_metadata() const { return nullptr; }
  // False for a replay: it has no device behind it to command.
  virtual bool accepts_commands() const = 0;
  // "/dev/ttyUSB0 at 230400 baud", "tcp://127.0.0.1:2000", "replay of scan.ydrec" for messages.
  virtual std::string describe() const = 0;
};

}  // namespace ydscope
