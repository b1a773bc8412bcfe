#include "support/ws_test_client.h"

#include <sstream>
#include <stdexcept>
#include <utility>

#include <boost/asio/connect.hpp>
#include <boost/asio/write.hpp>
#include <boost/beast/http/field.hpp>
#include <boost/beast/websocket.hpp>
#include <boost/property_tree/json_parser.hpp>
#include <boost/property_tree/ptree.hpp>

namespace ydscope::test {
namespace {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace websocket = beast::websocket;
using tcp = asio::ip::tcp;

std::uint64_t little_endian(const std::uint8_t* p, int bytes) {
  std::uint64_t value = 0;
  for (int i = 0; i < bytes; ++i) value |= static_cast<std::uint64_t>(p[i]) << (8 * i);
  return value;
}

}  // namespace

template <class Start>
bool WsTestClient::run_bounded(Start start, std::chrono::milliseconds timeout) {
  if (closed_) return false;
  bool done = false;
  boost::system::error_code result;
  start([&done, &result](const boost::system::error_code& ec, auto&&...) {
    done = true;
    result = ec;
  });
  io_.restart();
  io_.run_for(timeout);
  if (!done) {
    // Cancelling leaves the Beast stream unusable, so a timeout ends the client.
    boost::system::error_code ignored;
    ws_.next_layer().cancel(ignored);
    ws_.next_layer().close(ignored);
    io_.restart();
    io_.run();
  }
  if (done && !result) return true;
  closed_ = true;
  boost::system::error_code ignored;
  ws_.next_layer().close(ignored);
  return false;
}

WsTestClient::WsTestClient(std::uint16_t port, int receive_buffer_bytes, std::chrono::milliseconds timeout) : ws_(io_) {
  const tcp::endpoint server(asio::ip::make_address("127.0.0.1"), port);
  auto& socket = ws_.next_layer();
  socket.open(tcp::v4());
  if (receive_buffer_bytes > 0) socket.set_option(asio::socket_base::receive_buffer_size(receive_buffer_bytes));
  if (!run_bounded([&](auto handler) { socket.async_connect(server, std::move(handler)); }, timeout))
    throw std::runtime_error("cannot connect to 127.0.0.1:" + std::to_string(port));
  local_port_ = socket.local_endpoint().port();
  ws_.set_option(websocket::stream_base::decorator([](websocket::request_type& request) {
    request.set(beast::http::field::sec_websocket_protocol, "foxglove.websocket.v1");
  }));
  if (!run_bounded([&](auto handler) { ws_.async_handshake("127.0.0.1", "/", std::move(handler)); }, timeout))
    throw std::runtime_error("the WebSocket handshake with 127.0.0.1:" + std::to_string(port) + " failed");
}

std::uint32_t WsTestClient::channel_of(std::string_view topic, std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (!channels_.count(topic)) {
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left <= 0ms || !read(left)) return 0;
  }
  return channels_.find(topic)->second;
}

bool WsTestClient::subscribe(std::uint32_t subscription_id, std::string_view topic, std::chrono::milliseconds timeout) {
  const std::uint32_t channel = channel_of(topic, timeout);
  if (!channel) return false;
  return send_text(R"({"op":"subscribe","subscriptions":[{"id":)" + std::to_string(subscription_id) +
                       R"(,"channelId":)" + std::to_string(channel) + "}]}",
                   timeout);
}

bool WsTestClient::send_text(std::string_view json, std::chrono::milliseconds timeout) {
  ws_.text(true);
  return run_bounded([&](auto handler) { ws_.async_write(asio::buffer(json.data(), json.size()), std::move(handler)); },
                     timeout);
}

bool WsTestClient::send_binary(std::string_view bytes, std::chrono::milliseconds timeout) {
  ws_.binary(true);
  return run_bounded(
      [&](auto handler) { ws_.async_write(asio::buffer(bytes.data(), bytes.size()), std::move(handler)); }, timeout);
}

std::optional<WsMessage> WsTestClient::read(std::chrono::milliseconds timeout) {
  buffer_.clear();
  if (!run_bounded([&](auto handler) { ws_.async_read(buffer_, std::move(handler)); }, timeout)) return std::nullopt;
  WsMessage message;
  message.text = ws_.got_text();
  const auto data = buffer_.cdata();
  const auto* bytes = static_cast<const std::uint8_t*>(data.data());
  if (message.text) {
    message.json.assign(reinterpret_cast<const char*>(bytes), data.size());
    ++text_messages_;
    remember_channels(message.json);
  } else if (data.size() >= 13 && bytes[0] == 0x01) {
    message.subscription = static_cast<std::uint32_t>(little_endian(bytes + 1, 4));
    message.log_time_ns = little_endian(bytes + 5, 8);
    message.payload_bytes = data.size() - 13;
    message.payload.assign(bytes + 13, bytes + data.size());
  }
  return message;
}

std::optional<WsMessage> WsTestClient::read_binary(std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  for (;;) {
    const auto left =
        std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left <= 0ms) return std::nullopt;
    auto message = read(left);
    if (!message || !message->text) return message;
  }
}

void WsTestClient::remember_channels(const std::string& json) {
  if (json.find(R"("op":"advertise")") == std::string::npos) return;
  boost::property_tree::ptree tree;
  std::istringstream in(json);
  boost::property_tree::read_json(in, tree);
  for (const auto& [key, channel] : tree.get_child("channels"))
    channels_[channel.get<std::string>("topic")] = channel.get<std::uint32_t>("id");
}

void WsTestClient::close_handshake(std::chrono::milliseconds timeout) {
  run_bounded([&](auto handler) { ws_.async_close(websocket::close_code::normal, std::move(handler)); }, timeout);
  close_socket();
}

void WsTestClient::close_socket() {
  boost::system::error_code ignored;
  ws_.next_layer().close(ignored);
  closed_ = true;
}

void WsTestClient::reset_socket() {
  boost::system::error_code ignored;
  ws_.next_layer().set_option(asio::socket_base::linger(true, 0), ignored);
  close_socket();
}

bool WsTestClient::write_raw(std::string_view bytes, std::chrono::milliseconds timeout) {
  return run_bounded(
      [&](auto handler) {
        asio::async_write(ws_.next_layer(), asio::buffer(bytes.data(), bytes.size()), std::move(handler));
      },
      timeout);
}

std::size_t WsTestClient::read_raw(std::size_t bytes, std::chrono::milliseconds timeout) {
  std::string raw(bytes, '\0');
  std::size_t got = 0;
  const bool ok = run_bounded(
      [&](auto handler) {
        ws_.next_layer().async_read_some(
            asio::buffer(raw),
            [&got, handler = std::move(handler)](const boost::system::error_code& ec, std::size_t n) mutable {
              got = n;
              handler(ec, n);
            });
      },
      timeout);
  return ok ? got : 0;
}

}  // namespace ydscope::test
