// One connected Foxglove client: the HTTP upgrade with its timeout, the read loop, the client's
// requests (subscribe, unsubscribe, parameters), and its writes from a bounded queue.
#include <utility>  // before asio's coroutine headers, which use std::exchange without including it

#include <boost/asio/redirect_error.hpp>
#include <boost/asio/use_awaitable.hpp>
#include <boost/beast/core/flat_buffer.hpp>
#include <boost/beast/http.hpp>

#include "core/bridge/foxglove_server_impl.h"

namespace ydscope::foxglove {

namespace http = beast::http;
using Clock = std::chrono::steady_clock;

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
        if (const auto latched = server_.latched_.find(channel); latched != server_.latched_.end())
          send_message(channel, latched->second.first, latched->second.second);
      }
    }
  } else if (const auto* unsubscribe = std::get_if<Unsubscribe>(&*request)) {
    for (const std::uint32_t sub : unsubscribe->subscription_ids) {
      const auto it = subscriptions_.find(sub);
      if (it == subscriptions_.end()) {
        send_text(status_json(StatusLevel::Error, "cannot unsubscribe subscription id " + std::to_string(sub) +
                                                      ": this connection has no such subscription"));
        continue;
      }
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

}  // namespace ydscope::foxglove
