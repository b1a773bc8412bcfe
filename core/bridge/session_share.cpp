#include "core/bridge/session_share.h"

#include "core/bridge/ros_topic_channels.h"

namespace ydscope {

std::unique_ptr<SessionShare> SessionShare::start(Session& session, ShareOptions options, std::string& error) {
  std::unique_ptr<SessionShare> share(new SessionShare());
  share->parameters_.push_back(std::make_unique<foxglove::SessionParameters>(session));
  foxglove::SessionParameters* parameters = share->parameters_.back().get();
  const auto channels = foxglove::ros_topic_channels({}, options.topics.ros.link_bytes);
  if (!share->serve(options, channels, parameters, {{&session, {}, parameters}}, error)) return nullptr;
  return share;
}

std::unique_ptr<SessionShare> SessionShare::start(const std::vector<Source>& sources, ShareOptions options,
                                                  std::string& error) {
  std::unique_ptr<SessionShare> share(new SessionShare());
  std::vector<McapSource> about;
  std::vector<LiveSource> topics;
  for (const Source& source : sources) {
    share->parameters_.push_back(std::make_unique<foxglove::SessionParameters>(*source.session));
    share->named_parameters_.add(source.about.name, share->parameters_.back().get());
    about.push_back(source.about);
    topics.push_back({source.session, source.about, share->parameters_.back().get()});
  }
  const auto channels = foxglove::ros_topic_channels(about, options.topics.ros.link_bytes);
  if (!share->serve(options, channels, &share->named_parameters_, std::move(topics), error)) return nullptr;
  return share;
}

bool SessionShare::serve(ShareOptions& options, std::vector<foxglove::ServerChannel> channels,
                         foxglove::ParameterBackend* backend, std::vector<LiveSource> topics, std::string& error) {
  host_ = options.server.host;
  server_ = std::make_unique<foxglove::FoxgloveServer>(std::move(options.server), std::move(channels), backend);
  if (!server_->start(error)) return false;
  LiveTopicsOptions live;
  live.topics = std::move(options.topics);
  live.mcap_path = std::move(options.mcap_path);
  live.server = server_.get();
  topics_ = LiveTopics::start(std::move(topics), std::move(live), error);
  return topics_ != nullptr;
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
