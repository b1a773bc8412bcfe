#include "core/bridge/foxglove_server.h"

#include <algorithm>
#include <chrono>
#include <future>
#include <map>
#include <set>
#include <thread>
#include <utility>  // before asio's coroutine headers, which use std::exchange without including it

#include <boost/asio/co_spawn.hpp>
#include <boost/asio/detached.hpp>
#include <boost/asio/io_context.hpp>
#include <boost/asio/ip/tcp.hpp>
#include <boost/asio/post.hpp>
#include <boost/asio/redirect_error.hpp>
#include <boost/asio/steady_timer.hpp>
#include <boost/asio/use_awaitable.hpp>
#include <boost/beast/core/flat_buffer.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>

#include "core/bridge/client_send_queue.h"

namespace ydscope::foxglove {
namespace {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
using tcp = asio::ip::tcp;
using Clock = std::chrono::steady_clock;

}  // namespace

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
  ClientStats stats() const { return {peer_, sent_, queue_.dropped()}; }

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
  Clock::time_point last_drop_report_{};
  asio::steady_timer handshake_timer_;  // the HTTP upgrade has no timeout of its own
};

void FoxgloveServer::Impl::on_client_gone(const std::shared_ptr<Client>& client) {
  client->close();
  clients_.erase(client);
}

void FoxgloveServer::Impl::Client::enqueue(OutgoingMessage out) {
  if (!open_) return;
  queue_.push(std::move(out));
  const std::uint64_t dropped = queue_.dropped();
  if (dropped > dropped_reported_ && Clock::now() - last_drop_report_ > std::chrono::seconds(5)) {
    dropped_reported_ = dropped;
    last_drop_report_ = Clock::now();
    OutgoingMessage warning;
    warning.text = true;
    warning.json = status_json(StatusLevel::Warning,
                               "this connection is too slow for the lidar: " + std::to_string(dropped) +
                                   " messages dropped so far (the oldest go first)",
                               "ydscope-dropped");
    queue_.push(std::move(warning));
  }
  write_next();
}

void FoxgloveServer::Impl::Client::write_next() {
  if (!open_) return;
  const OutgoingMessage* out = queue_.begin_write();
  if (!out) return;
  auto self = shared_from_this();
  const auto done = [self](const boost::system::error_code& ec, std::size_t) {
    self->queue_.end_write();
    if (ec) {
      self->open_ = false;  // the read side notices too and removes the client
      self->close();
      return;
    }
    ++self->sent_;
    self->write_next();
  };
  ws_.text(out->text);
  if (out->text) {
    ws_.async_write(asio::buffer(out->json), done);
  } else {
    const std::array<asio::const_buffer, 2> buffers{asio::buffer(out->header), asio::buffer(*out->payload)};
    ws_.async_write(buffers, done);
  }
}

asio::awaitable<void> FoxgloveServer::Impl::Client::run() {
  auto self = shared_from_this();
  boost::system::error_code ec;
  auto token = asio::redirect_error(asio::use_awaitable, ec);
  handshake_timer_.expires_after(server_.options_.handshake_timeout);
  handshake_timer_.async_wait([weak = weak_from_this()](const boost::system::error_code& timer_ec) {
    if (auto client = weak.lock(); client && !timer_ec && !client->open_) client->close();
  });
  beast::flat_buffer buffer;
  http::request<http::string_body> request;
  co_await http::async_read(ws_.next_layer(), buffer, request, token);
  if (ec) co_return server_.on_client_gone(self);
  if (!websocket::is_upgrade(request)) {
    http::response<http::string_body> response{http::status::upgrade_required, request.version()};
    response.set(http::field::content_type, "text/plain");
    response.body() = "This is ydscope's Foxglove WebSocket bridge (" + std::string(kSubprotocol) +
                      "): open it in Foxglove with \"Open connection\" -> Foxglove WebSocket.\n";
    response.prepare_payload();
    co_await http::async_write(ws_.next_layer(), response, token);
    close();
    co_return server_.on_client_gone(self);
  }
  const auto offers = request[http::field::sec_websocket_protocol];
  const bool offered = std::string_view(offers.data(), offers.size()).find(kSubprotocol) != std::string_view::npos;
  ws_.set_option(websocket::stream_base::decorator([offered](websocket::response_type& response) {
    if (offered) response.set(http::field::sec_websocket_protocol, std::string(kSubprotocol));
    response.set(http::field::server, "ydscope");
  }));
  ws_.read_message_max(16u << 20);  // beyond this Beast closes the connection; below it we ignore
  websocket::stream_base::timeout timeouts;
  timeouts.handshake_timeout = server_.options_.handshake_timeout;
  timeouts.idle_timeout = server_.options_.idle_timeout;
  timeouts.keep_alive_pings = true;
  ws_.set_option(timeouts);
  co_await ws_.async_accept(request, token);
  if (ec) co_return server_.on_client_gone(self);
  handshake_timer_.cancel();
  open_ = true;
  send_text(server_info_json(server_.options_.name, std::to_string(Clock::now().time_since_epoch().count())));
  std::vector<ChannelAd> ads;
  for (const auto& c : server_.channels_) ads.push_back({c.id, c.topic, c.schema_name, c.schema});
  send_text(advertise_json(ads));

  buffer.clear();
  std::size_t message_size = 0;
  while (open_) {
    const std::size_t got = co_await ws_.async_read_some(buffer, 4096, token);
    if (ec) break;
    message_size += got;
    if (message_size > kMaxClientMessage) buffer.clear();  // keep reading it, but not keeping it
    if (!ws_.is_message_done()) continue;
    if (message_size > kMaxClientMessage) {
      send_text(status_json(StatusLevel::Error, "ignored a client message of " + std::to_string(message_size) +
                                                    " bytes: the limit is " + std::to_string(kMaxClientMessage)));
    } else if (!ws_.got_text()) {
      send_text(
          status_json(StatusLevel::Error, "ignored a binary message: this server does not accept client publishing"));
    } else {
      const auto data = buffer.cdata();
      handle_text({static_cast<const char*>(data.data()), data.size()});
    }
    buffer.clear();
    message_size = 0;
  }
  open_ = false;
  close();
  server_.on_client_gone(self);
}

void FoxgloveServer::Impl::Client::handle_text(std::string_view text) {
  std::string error;
  const auto request = parse_client_message(text, error);
  if (!request) {
    send_text(status_json(StatusLevel::Error, "ignored a client message: " + error));
    return;
  }
  if (const auto* subscribe = std::get_if<Subscribe>(&*request)) {
    for (const auto& [sub, channel] : subscribe->subscriptions) {
      const bool known = std::any_of(server_.channels_.begin(), server_.channels_.end(),
                                     [channel = channel](const ServerChannel& c) { return c.id == channel; });
      if (!known) {
        send_text(status_json(StatusLevel::Error,
                              "cannot subscribe to channel " + std::to_string(channel) + ": it was never advertised"));
      } else if (subscriptions_.count(sub)) {
        send_text(status_json(StatusLevel::Error, "subscription id " + std::to_string(sub) + " is already in use"));
      } else if (by_channel_.count(channel)) {
        send_text(status_json(StatusLevel::Warning, "channel " + std::to_string(channel) + " is already subscribed"));
      } else {
        subscriptions_[sub] = channel;
        by_channel_[channel] = sub;
      }
    }
  } else if (const auto* unsubscribe = std::get_if<Unsubscribe>(&*request)) {
    for (const std::uint32_t sub : unsubscribe->subscription_ids) {
      const auto it = subscriptions_.find(sub);
      if (it == subscriptions_.end()) continue;
      by_channel_.erase(it->second);
      subscriptions_.erase(it);
    }
  } else if (const auto* get = std::get_if<GetParameters>(&*request)) {
    std::vector<Parameter> values;
    for (auto& p : server_.parameters_ ? server_.parameters_->current() : std::vector<Parameter>{})
      if (get->names.empty() || std::find(get->names.begin(), get->names.end(), p.name) != get->names.end())
        values.push_back(std::move(p));
    send_parameters(values, get->id, false);
  } else if (const auto* set = std::get_if<SetParameters>(&*request)) {
    if (!server_.parameters_) return send_text(status_json(StatusLevel::Error, "this server has no parameters"));
    for (const Parameter& p : set->parameters) {
      std::weak_ptr<Client> weak = shared_from_this();
      Impl* server = &server_;
      const auto id = set->id;
      server_.parameters_->set(
          p, [weak, server, id, name = p.name](std::vector<Parameter> read_back, std::string failure) {
            asio::post(
                server->io_, [weak, server, id, name, read_back = std::move(read_back), failure = std::move(failure)] {
                  if (auto client = weak.lock()) {
                    if (!failure.empty())
                      client->send_text(status_json(StatusLevel::Error, "setting " + name + " failed: " + failure));
                    client->send_parameters(read_back, id, false);
                  }
                  for (const auto& other : server->clients_)
                    if (other != weak.lock()) other->send_parameters(read_back, std::nullopt, true);
                });
          });
    }
  } else if (const auto* sub = std::get_if<SubscribeParameterUpdates>(&*request)) {
    if (sub->names.empty()) all_parameters_ = true;
    parameter_subscriptions_.insert(sub->names.begin(), sub->names.end());
  } else if (const auto* unsub = std::get_if<UnsubscribeParameterUpdates>(&*request)) {
    if (unsub->names.empty()) {
      all_parameters_ = false;
      parameter_subscriptions_.clear();
    }
    for (const auto& name : unsub->names) parameter_subscriptions_.erase(name);
  }
}

asio::awaitable<void> FoxgloveServer::Impl::accept_loop() {
  for (;;) {
    boost::system::error_code ec;
    tcp::socket socket = co_await acceptor_.async_accept(asio::redirect_error(asio::use_awaitable, ec));
    if (ec) {
      if (stopped_ || ec == asio::error::operation_aborted) co_return;
      // E.g. out of file descriptors: the waiting connection fails again at once, so retrying
      // straight away would spin the server's thread; keep serving the others and retry soon.
      asio::steady_timer pause(io_, std::chrono::milliseconds(100));
      co_await pause.async_wait(asio::redirect_error(asio::use_awaitable, ec));
      continue;
    }
    socket.set_option(tcp::no_delay(true), ec);
    auto client = std::make_shared<Client>(*this, std::move(socket));
    clients_.insert(client);
    asio::co_spawn(io_, client->run(), asio::detached);
  }
}

bool FoxgloveServer::Impl::start(std::string& error) {
  boost::system::error_code ec;
  const auto address = asio::ip::make_address(options_.host, ec);
  if (ec) {
    error = "'" + options_.host + "' is not an IP address to listen on (try 127.0.0.1 or 0.0.0.0)";
    return false;
  }
  const tcp::endpoint endpoint(address, options_.port);
  acceptor_.open(endpoint.protocol(), ec);
  if (!ec) acceptor_.set_option(tcp::acceptor::reuse_address(true), ec);
  if (!ec) acceptor_.bind(endpoint, ec);
  if (!ec) acceptor_.listen(asio::socket_base::max_listen_connections, ec);
  if (ec) {
    error = "cannot listen on " + options_.host + ":" + std::to_string(options_.port) + ": " + ec.message() +
            (ec == asio::error::address_in_use
                 ? " (another program has it, perhaps another ydscope; choose another port with " +
                       options_.port_option + ")"
                 : "");
    return false;
  }
  port_ = acceptor_.local_endpoint().port();
  asio::co_spawn(io_, accept_loop(), asio::detached);
  thread_ = std::thread([this] { io_.run(); });
  return true;
}

void FoxgloveServer::Impl::stop() {
  if (!thread_.joinable()) return;
  asio::post(io_, [this] {
    stopped_ = true;
    boost::system::error_code ec;
    acceptor_.close(ec);
    for (const auto& client : clients_) client->close();
    work_.reset();
  });
  // Clients finish their coroutines once their sockets are closed; then run() returns.
  thread_.join();
}

FoxgloveServer::FoxgloveServer(ServerOptions options, std::vector<ServerChannel> channels, ParameterBackend* parameters)
    : impl_(std::make_unique<Impl>(std::move(options), std::move(channels), parameters)) {}
FoxgloveServer::~FoxgloveServer() { stop(); }

bool FoxgloveServer::start(std::string& error) { return impl_->start(error); }
std::uint16_t FoxgloveServer::port() const { return impl_->port_; }
void FoxgloveServer::stop() { impl_->stop(); }

void FoxgloveServer::publish(std::uint32_t channel_id, std::uint64_t log_time_ns,
                             std::shared_ptr<const std::vector<std::uint8_t>> payload) {
  asio::post(impl_->io_, [impl = impl_.get(), channel_id, log_time_ns, payload = std::move(payload)] {
    for (const auto& client : impl->clients_) client->send_message(channel_id, log_time_ns, payload);
  });
}

void FoxgloveServer::broadcast_parameters(std::vector<Parameter> parameters) {
  asio::post(impl_->io_, [impl = impl_.get(), parameters = std::move(parameters)] {
    for (const auto& client : impl->clients_) client->send_parameters(parameters, std::nullopt, true);
  });
}

void FoxgloveServer::broadcast_status(StatusLevel level, std::string message) {
  asio::post(impl_->io_, [impl = impl_.get(), json = status_json(level, message, "ydscope-link")] {
    for (const auto& client : impl->clients_) client->send_text(json);
  });
}

std::vector<ClientStats> FoxgloveServer::clients() const {
  auto promise = std::make_shared<std::promise<std::vector<ClientStats>>>();
  auto result = promise->get_future();
  asio::post(impl_->io_, [impl = impl_.get(), promise] {
    std::vector<ClientStats> stats;
    for (const auto& client : impl->clients_) stats.push_back(client->stats());
    promise->set_value(std::move(stats));
  });
  if (result.wait_for(std::chrono::seconds(2)) != std::future_status::ready) return {};
  return result.get();
}

}  // namespace ydscope::foxglove
