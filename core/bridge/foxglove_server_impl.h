#pragma once
// The Foxglove server's insides, shared by its two files only: the server (foxglove_server.cpp:
// accept, start, stop, fan-out) and each connected client (foxglove_client.cpp: the upgrade, the
// read loop, the client's requests, its bounded send queue).
#include <chrono>
#include <map>
#include <set>
#include <thread>
#include <utility>  // before asio's coroutine headers, which use std::exchange without including it

#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/beast/websocket.hpp>

#include "core/bridge/client_send_queue.h"
#include "core/bridge/foxglove_server.h"

namespace ydscope::foxglove {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace websocket = beast::websocket;
using tcp = asio::ip::tcp;

class FoxgloveServer::Impl {
 public:
  class Client;

  Impl(ServerOptions options, std::vector<ServerChannel> channels, ParameterBackend* parameters)
      : options_(std::move(options)),
        channels_(std::move(channels)),
        parameters_(parameters),
        work_(asio::make_work_guard(io_)),
        acceptor_(io_) {}

  bool start(std::string& error);
  void stop();
  void on_client_gone(const std::shared_ptr<Client>& client);
  asio::awaitable<void> accept_loop();

  ServerOptions options_;
  std::vector<ServerChannel> channels_;
  ParameterBackend* parameters_;
  asio::io_context io_;
  asio::executor_work_guard<asio::io_context::executor_type> work_;
  tcp::acceptor acceptor_;
  std::set<std::shared_ptr<Client>> clients_;  // server thread only
  // The newest message of each latched channel: (log time, payload). Server thread only.
  std::map<std::uint32_t, std::pair<std::uint64_t, std::shared_ptr<const std::vector<std::uint8_t>>>> latched_;
  std::thread thread_;
  std::uint16_t port_ = 0;
  bool stopped_ = false;
};

class FoxgloveServer::Impl::Client : public std::enable_shared_from_this<Client> {
 public:
  Client(Impl& server, tcp::socket socket)
      : server_(server), ws_(std::move(socket)), queue_(server.options_.client_queue), handshake_timer_(server.io_) {
    boost::system::error_code ec;
    const auto endpoint = ws_.next_layer().remote_endpoint(ec);
    peer_ = ec ? "unknown peer" : endpoint.address().to_string() + ":" + std::to_string(endpoint.port());
  }

  asio::awaitable<void> run();
  void send_text(std::string json) {
    OutgoingMessage out;
    out.text = true;
    out.json = std::move(json);
    enqueue(std::move(out));
  }
  void send_message(std::uint32_t channel_id, std::uint64_t log_time,
                    const std::shared_ptr<const std::vector<std::uint8_t>>& payload) {
    const auto it = by_channel_.find(channel_id);
    if (it == by_channel_.end()) return;
    OutgoingMessage out;
    out.header = message_data_header(it->second, log_time);
    out.payload = payload;
    enqueue(std::move(out));
  }
  void send_parameters(const std::vector<Parameter>& values, const std::optional<std::string>& id,
                       bool only_subscribed) {
    std::vector<Parameter> chosen;
    for (const auto& p : values)
      if (!only_subscribed || all_parameters_ || parameter_subscriptions_.count(p.name)) chosen.push_back(p);
    if (!chosen.empty() || id) send_text(parameter_values_json(chosen, id));
  }
  void close() {
    handshake_timer_.cancel();
    boost::system::error_code ec;
    ws_.next_layer().shutdown(tcp::socket::shutdown_both, ec);
    ws_.next_layer().close(ec);
  }
  ClientStats stats() const { return {peer_, sent_, queue_.dropped(), queue_.queued(), queue_.queued_bytes()}; }

 private:
  void enqueue(OutgoingMessage out);
  void write_next();
  void handle_text(std::string_view text);

  Impl& server_;
  websocket::stream<tcp::socket> ws_;
  std::string peer_;
  ClientSendQueue queue_;
  bool open_ = false;
  std::map<std::uint32_t, std::uint32_t> subscriptions_;  // subscription id -> channel id
  std::map<std::uint32_t, std::uint32_t> by_channel_;     // channel id -> subscription id
  std::set<std::string> parameter_subscriptions_;
  bool all_parameters_ = false;
  std::uint64_t sent_ = 0;
  std::uint64_t dropped_reported_ = 0;
  std::chrono::steady_clock::time_point last_drop_report_{};
  asio::steady_timer handshake_timer_;  // the HTTP upgrade has no timeout of its own
};

}  // namespace ydscope::foxglove
