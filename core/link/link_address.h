#pragma once
// What --port names: a serial device path, or tcp://host:port for a network bridge. Parsing is
// separate from opening so the CLI can reject a malformed address before touching any device.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <utility>  // before asio's awaitable.hpp, which uses std::exchange without including it

#include <boost/asio/awaitable.hpp>
#include <boost/asio/io_context.hpp>

#include "core/link/byte_link.h"

namespace ydscope {

struct LinkAddress {
  enum class Kind { Serial, Tcp };
  Kind kind = Kind::Serial;
  std::string path;  // Serial: the device path as given
  std::string host;  // Tcp: name or address (IPv6 without brackets)
  std::uint16_t port = 0;

  // Back to the --port form ("tcp://[::1]:2000", "/dev/ttyUSB0").
  std::string text() const;
};

// Null and one sentence in `error` when the text is empty, has an unknown scheme, or a tcp://
// address lacks a host or a port in 1..65535.
std::optional<LinkAddress> parse_link_address(std::string_view text, std::string& error);

// Opens a serial port (raw 8N1 at `baud`) or connects to a TCP bridge (baud is the bridge's
// business and is ignored), parsing the --port text first. A connect waits on `io` without
// blocking it. Null plus one sentence in `error` (which must outlive the wait) on failure.
boost::asio::awaitable<std::unique_ptr<ByteLink>> open_byte_link(boost::asio::io_context& io, std::string address,
                                                                 std::uint32_t baud, std::string& error);

}  // namespace ydscope
