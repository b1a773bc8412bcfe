#include "core/bridge/session_share.h"

#include "core/bridge/ros_topic_channels.h"

namespace ydscope {

std::unique_ptr<SessionShare> SessionShare::start(const std::vector<Source>& sources, ShareOptions options,
                                                  std::string& error) {
  if (sources.empty()) {
    error = "there is no lidar to share; start one first";
    return nullptr;
  }
  std::unique_ptr<SessionShare> share(new SessionShare());
  std::vector<SourceInfo> infos;
  std::vector<LiveSource> topics;
  for (const Source& source : sources) {
    share->parameters_.push_back(std::make_unique<foxglove::SessionParameters>(*source.session));
    share->named_parameters_.add(source.info.name, share->parameters_.back().get());
    infos.push_back(source.info);
    topics.push_back({source.session, source.info, share->parameters_.back().get()});
  }
  // A lone lidar's parameters keep their plain names (scan_hz); several are named apart.
  foxglove::ParameterBackend* backend = named_apart(infos)
                                            ? static_cast<foxglove::ParameterBackend*>(&share->named_parameters_)
                                            : share->parameters_.front().get();
  share->host_ = options.server.host;
  share->server_ = std::make_unique<foxglove::FoxgloveServer>(
      std::move(options.server), foxglove::ros_topic_channels(infos, options.topics.ros.link_bytes), backend);
  if (!share->server_->start(error)) return nullptr;
  LiveTopicsOptions live;
  live.topics = std::move(options.topics);
  live.mcap_path = std::move(options.mcap_path);
  live.server = share->server_.get();
  share->topics_ = LiveTopics::start(std::move(topics), std::move(live), error);
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
