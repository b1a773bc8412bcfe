#pragma once
// WsTestClient: a real foxglove.websocket.v1 client for the bridge tests, written with
// Boost.Beast and nothing of the server's code, talking to 127.0.0.1 only. Every wait is bounded:
// each operation runs the client's own io_context for at most its timeout, and a timed-out or
// failed operation leaves the client closed() (a Beast stream is unusable after a cancel).
#include <chrono>
#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/beast/core/flat_buffer.hpp>
#include <boost/beast/websocket/stream.hpp>

namespace ydscope::test {

using namespace std::chrono_literals;

struct WsMessage {
  bool text = false;
  std::string json;                // text messages
  std::uint32_t subscription = 0;  // binary Message Data
  std::uint64_t log_time_ns = 0;
  std::size_t payload_bytes = 0;
  std::vector<std::uint8_t> payload;  // the message (CDR), to decode
};

class WsTestClient {
 public:
  // Connects to 127.0.0.1:port and completes the handshake offering foxglove.websocket.v1.
  // receive_buffer_bytes > 0 shrinks SO_RCVBUF first (a client the server can fill quickly).
  // Throws std::runtime_error with one sentence when it cannot.
  explicit WsTestClient(std::uint16_t port, int receive_buffer_bytes = 0, std::chrono::milliseconds timeout = 10s);

  // The channel id the server advertised for `topic` (reads until the advertise arrives); 0 if
  // it did not within the timeout.
  std::uint32_t channel_of(std::string_view topic, std::chrono::milliseconds timeout = 10s);
  // Subscribes `subscription_id` to `topic`; false when the topic was not advertised or the
  // send failed.
  bool subscribe(std::uint32_t subscription_id, std::string_view topic, std::chrono::milliseconds timeout = 10s);
  bool send_text(std::string_view json, std::chrono::milliseconds timeout = 10s);
  // A binary message (which a Foxglove server without client publishing refuses).
  bool send_binary(std::string_view bytes, std::chrono::milliseconds timeout = 10s);

  // The next message; empty when none came within `timeout` or the connection ended.
  std::optional<WsMessage> read(std::chrono::milliseconds timeout = 10s);
  // The next binary message, skipping text ones (status, advertise...).
  std::optional<WsMessage> read_binary(std::chrono::milliseconds timeout = 10s);

  // Leaving, three ways: the WebSocket close handshake; the TCP socket closed at once (FIN);
  // the TCP connection reset (RST, SO_LINGER 0), as a crashed or unplugged peer.
  void close_handshake(std::chrono::milliseconds timeout = 10s);
  void close_socket();
  void reset_socket();
  // Raw bytes on the TCP socket under the WebSocket (half frames); false on failure.
  bool write_raw(std::string_view bytes, std::chrono::milliseconds timeout = 10s);
  // Up to `bytes` raw bytes from the TCP socket (mid-frame, from the client's side); 0 on failure.
  std::size_t read_raw(std::size_t bytes, std::chrono::milliseconds timeout = 10s);

  // This end's port, which the server reports as the client's peer ("127.0.0.1:PORT").
  std::uint16_t local_port() const { return local_port_; }

  bool closed() const { return closed_; }
  std::size_t text_messages() const { return text_messages_; }

 private:
  template <class Start>
  bool run_bounded(Start start, std::chrono::milliseconds timeout);
  void remember_channels(const std::string& json);

  boost::asio::io_context io_;
  boost::beast::websocket::stream<boost::asio::ip::tcp::socket> ws_;
  boost::beast::flat_buffer buffer_;
  std::map<std::string, std::uint32_t, std::less<>> channels_;
  std::uint16_t local_port_ = 0;
  bool closed_ = false;
  std::size_t text_messages_ = 0;
};

}  // namespace ydscope::test
