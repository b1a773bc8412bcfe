#include "core/bridge/session_share.h"

#include "core/bridge/ros_topic_channels.h"

namespace ydscope {

std::unique_ptr<SessionShare> SessionShare::start(Session& session, ShareOptions options, std::string& error) {
  std::unique_ptr<SessionShare> share(new SessionShare());
  share->host_ = options.server.host;
  share->parameters_ = std::make_unique<foxglove::SessionParameters>(session);
  share->server_ = std::make_unique<foxglove::FoxgloveServer>(std::move(options.server), foxglove::ros_topic_channels(),
                                                              share->parameters_.get());
  if (!share->server_->start(error)) return nullptr;
  LiveTopicsOptions live;
  live.topics = std::move(options.topics);
  live.mcap_path = std::move(options.mcap_path);
  live.server = share->server_.get();
  live.parameters = share->parameters_.get();
  share->topics_ = LiveTopics::start(session, std::move(live), error);
  if (!share->topics_) return nullptr;
  return share;
}

SessionShare::~SessionShare() { stop(); }

bool SessionShare::stop() {
  if (stopped_ || !server_) return !topics_ || topics_->error().empty();
  stopped_ = true;
  const bool written = !topics_ || topics_->stop();
  server_->stop();
  return written;
}

std::string SessionShare::address() const {
  const bool v6 = host_.find(':') != std::string::npos;
  return "ws://" + (v6 ? "[" + host_ + "]" : host_) + ":" + std::to_string(port());
}

bool is_loopback_host(const std::string& host) {
  return host.rfind("127.", 0) == 0 || host == "::1" || host == "localhost";
}

}  // namespace ydscope
