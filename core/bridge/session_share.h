#pragma once
// SessionShare: live sessions served to Foxglove: the WebSocket server, the parameters that
// set each lidar through its session's commands, and the topics (LiveTopics) that feed it,
// optionally also recorded to MCAP. `ydscope-cli serve` is one (one lidar or several), the
// app's Share toggle another.
//
// Thread contract: the creator's thread calls every method; clients() may be called from any.
// The sessions must outlive it.
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "core/bridge/foxglove_server.h"
#include "core/bridge/live_topics.h"
#include "core/bridge/session_parameters.h"
#include "core/bridge/sources_parameters.h"

namespace ydscope {

struct ShareOptions {
  foxglove::ServerOptions server;  // where to listen (127.0.0.1:8765 by default)
  McapExportOptions topics;
  std::string mcap_path;  // empty: serve only
};

class SessionShare {
 public:
  // One lidar of the set: its session and what it is.
  struct Source {
    Session* session = nullptr;
    SourceInfo info;  // name, pose, model
  };
  // Binds, taps the sessions and serves. A set of one is served as a lone lidar always was
  // (/scan, scan_hz); several each under its name (/NAME/scan, NAME/scan_hz) with every pose on
  // /tf_static. Null plus one sentence in `error` when the address cannot be bound (in use, a
  // bad host) or the MCAP file cannot be created.
  static std::unique_ptr<SessionShare> start(const std::vector<Source>& sources, ShareOptions options,
                                             std::string& error);
  ~SessionShare();  // stop()

  // Stops the topics (the MCAP file gets its summary), then the server. False when writing the
  // file failed (topics().error() says why). Idempotent.
  bool stop();

  // The port clients connect to (the one bound when port 0 was asked).
  std::uint16_t port() const { return server_->port(); }
  const std::string& host() const { return host_; }
  // "ws://127.0.0.1:8765"
  std::string address() const;
  std::vector<foxglove::ClientStats> clients() const { return server_->clients(); }
  LiveTopics& topics() { return *topics_; }

 private:
  SessionShare() = default;
  std::string host_;
  std::vector<std::unique_ptr<foxglove::SessionParameters>> parameters_;  // one per lidar
  foxglove::SourcesParameters named_parameters_;                          // several lidars: under their names
  std::unique_ptr<foxglove::FoxgloveServer> server_;
  std::unique_ptr<LiveTopics> topics_;
  bool stopped_ = false;
};

// Whether serving on `host` stays on this machine (anything else deserves a warning: there is
// no authentication).
bool is_loopback_host(const std::string& host);

}  // namespace ydscope
