#include "core/link/link_address.h"

#include <charconv>

#include "core/link/serial_link.h"
#include "core/link/tcp_link.h"

namespace ydscope {
namespace {

constexpr std::string_view kTcpScheme = "tcp://";

std::optional<LinkAddress> parse_tcp(std::string_view original, std::string_view rest, std::string& error) {
  const std::string quoted = "'" + std::string(original) + "'";
  std::string_view host;
  std::string_view port_text;
  if (!rest.empty() && rest.front() == '[') {  // [v6 address]:port
    const auto close = rest.find(']');
    if (close == std::string_view::npos) {
      error = "bad address " + quoted + ": missing ']' after the IPv6 host";
      return std::nullopt;
    }
    host = rest.substr(1, close - 1);
    if (host.find('[') != std::string_view::npos) {  // tcp://[[a]:1 once became host "[a"
      error = "bad address " + quoted + ": a bracketed host cannot hold another '[' (write tcp://[::1]:2000)";
      return std::nullopt;
    }
    const std::string_view after = rest.substr(close + 1);
    if (after.empty() || after.front() != ':') {
      error = "bad address " + quoted + ": missing ':port' (write tcp://host:port, e.g. tcp://192.168.1.20:2000)";
      return std::nullopt;
    }
    port_text = after.substr(1);
  } else {
    const auto colon = rest.rfind(':');
    if (colon == std::string_view::npos) {
      error = "bad address " + quoted + ": missing ':port' (write tcp://host:port, e.g. tcp://192.168.1.20:2000)";
      return std::nullopt;
    }
    host = rest.substr(0, colon);
    port_text = rest.substr(colon + 1);
    if (host.find(':') != std::string_view::npos) {
      error = "bad address " + quoted + ": put an IPv6 host in brackets, e.g. tcp://[::1]:2000";
      return std::nullopt;
    }
    if (host.find_first_of("[]") != std::string_view::npos) {
      error = "bad address " + quoted + ": brackets go around a whole IPv6 host, e.g. tcp://[::1]:2000";
      return std::nullopt;
    }
  }
  if (host.empty()) {
    error = "bad address " + quoted + ": missing host (write tcp://host:port)";
    return std::nullopt;
  }
  unsigned port = 0;
  const auto [end, ec] = std::from_chars(port_text.data(), port_text.data() + port_text.size(), port);
  if (port_text.empty() || ec != std::errc() || end != port_text.data() + port_text.size() || port == 0 ||
      port > 65535) {
    error = "bad address " + quoted + ": the port must be a number from 1 to 65535";
    return std::nullopt;
  }
  LinkAddress address;
  address.kind = LinkAddress::Kind::Tcp;
  address.host = std::string(host);
  address.port = static_cast<std::uint16_t>(port);
  return address;
}

}  // namespace

std::string LinkAddress::text() const {
  if (kind == Kind::Serial) return path;
  const bool ipv6 = host.find(':') != std::string::npos;
  return std::string(kTcpScheme) + (ipv6 ? "[" + host + "]" : host) + ":" + std::to_string(port);
}

std::optional<LinkAddress> parse_link_address(std::string_view text, std::string& error) {
  if (text.empty()) {
    error = "no port given; pass --port /dev/ttyUSB0 (see 'ydscope-cli ports') or --port tcp://host:port";
    return std::nullopt;
  }
  if (text.substr(0, kTcpScheme.size()) == kTcpScheme) return parse_tcp(text, text.substr(kTcpScheme.size()), error);
  if (const auto scheme = text.find("://"); scheme != std::string_view::npos) {
    error = "bad address '" + std::string(text) + "': unknown scheme '" + std::string(text.substr(0, scheme)) +
            "'; use a device path such as /dev/ttyUSB0 or tcp://host:port";
    return std::nullopt;
  }
  LinkAddress address;
  address.kind = LinkAddress::Kind::Serial;
  address.path = std::string(text);
  return address;
}

boost::asio::awaitable<std::unique_ptr<ByteLink>> open_byte_link(boost::asio::io_context& io, std::string address,
                                                                 std::uint32_t baud, std::string& error) {
  const auto parsed = parse_link_address(address, error);
  if (!parsed) co_return nullptr;
  if (parsed->kind == LinkAddress::Kind::Tcp)
    co_return co_await TcpLink::connect(io, parsed->host, parsed->port, error);
  co_return SerialLink::open(io, parsed->path, baud, error);
}

}  // namespace ydscope
