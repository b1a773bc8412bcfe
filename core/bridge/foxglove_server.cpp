#include <algorithm>
#include <future>
#include <utility>  // before asio's coroutine headers, which use std::exchange without including it

#include <boost/asio/co_spawn.hpp>
#include <boost/asio/detached.hpp>
#include <boost/asio/post.hpp>
#include <boost/asio/redirect_error.hpp>
#include <boost/asio/use_awaitable.hpp>

#include "core/bridge/foxglove_server_impl.h"

namespace ydscope::foxglove {

void FoxgloveServer::Impl::on_client_gone(const std::shared_ptr<Client>& client) {
  client->close();
  clients_.erase(client);
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
    const auto channel = std::find_if(impl->channels_.begin(), impl->channels_.end(),
                                      [channel_id](const ServerChannel& c) { return c.id == channel_id; });
    if (channel != impl->channels_.end() && channel->latched) impl->latched_[channel_id] = {log_time_ns, payload};
  });
}

void FoxgloveServer::broadcast_parameters(std::vector<Parameter> parameters) {
  asio::post(impl_->io_, [impl = impl_.get(), parameters = std::move(parameters)] {
    for (const auto& client : impl->clients_) client->send_parameters(parameters, std::nullopt, true);
  });
}

void FoxgloveServer::broadcast_status(StatusLevel level, std::string message, std::string id) {
  asio::post(impl_->io_, [impl = impl_.get(), json = status_json(level, message, id)] {
    for (const auto& client : impl->clients_) client->send_text(json);
  });
}

void FoxgloveServer::remove_status(std::string id) {
  asio::post(impl_->io_, [impl = impl_.get(), json = remove_status_json(id)] {
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
