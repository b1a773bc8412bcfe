#pragma once
// FoxgloveServer: a WebSocket server speaking foxglove.websocket.v1 (Boost.Beast) on a thread of
// its own, so slow or broken clients never touch the session's I/O thread or each other.
//
// Each client has a bounded send queue (core/bridge/client_send_queue.h): when it is full, the
// oldest queued lap is dropped and counted for that client (a status warning tells the client,
// at most every 5 s). Client
// messages above kMaxClientMessage, binary messages, malformed JSON, unknown ops, subscriptions to
// channels never advertised and unsubscriptions of unknown ids get a status message of level
// error and are otherwise ignored (the connection goes on); bytes that break the WebSocket
// protocol itself (unmasked or reserved frames, text that is not UTF-8, a message above 16 MiB)
// end that connection, as RFC 6455 says; a client that vanishes mid-frame is just removed.
//
// Thread contract: publish(), broadcast_parameters(), clients() and stop() may be called from
// any thread. The ParameterBackend is called on the server's thread and must not block: it
// reports results through its callback, from any thread.
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "core/bridge/foxglove_protocol.h"

namespace ydscope::foxglove {

class ParameterBackend {
 public:
  virtual ~ParameterBackend() = default;
  // Every parameter with its current value.
  virtual std::vector<Parameter> current() = 0;
  // Applies `parameter`; `done` gets the read-back values (what the device reports afterwards)
  // or a sentence saying why not. May be called back from another thread.
  using SetDone = std::function<void(std::vector<Parameter> read_back, std::string error)>;
  virtual void set(const Parameter& parameter, SetDone done) = 0;
};

struct ServerOptions {
  std::string host = "127.0.0.1";
  std::uint16_t port = 8765;      // 0 picks a free port (see port())
  std::size_t client_queue = 64;  // messages queued per client before the oldest is dropped
  // A connection that has not finished the WebSocket handshake by then is closed (a port scanner,
  // a peer gone half way). After it, a client that sends nothing for idle_timeout, not even the
  // pong to the server's keep-alive ping (sent at half of it), is closed: a peer that vanished
  // without FIN or RST would otherwise hold its socket for ever.
  std::chrono::milliseconds handshake_timeout{30'000};
  std::chrono::milliseconds idle_timeout{300'000};
  std::string name = "ydscope";
  std::string port_option = "--listen";  // named in the sentence when the port is in use
};

struct ServerChannel {
  std::uint32_t id;
  std::string topic;
  std::string schema_name;
  std::string schema;
  // Latched, as a ROS transient-local topic (/tf_static): the newest message published on it
  // goes to every client that subscribes later, the moment it subscribes.
  bool latched = false;
};

struct ClientStats {
  std::string peer;
  std::uint64_t sent = 0;
  std::uint64_t dropped = 0;
  // Its send queue now: messages waiting or being written (at most client_queue) and their bytes,
  // what a client that does not read holds of the server's memory.
  std::size_t queued = 0;
  std::size_t queued_bytes = 0;
};

class FoxgloveServer {
 public:
  FoxgloveServer(ServerOptions options, std::vector<ServerChannel> channels, ParameterBackend* parameters);
  ~FoxgloveServer();  // stop()
  FoxgloveServer(const FoxgloveServer&) = delete;
  FoxgloveServer& operator=(const FoxgloveServer&) = delete;

  // Binds and starts serving. False plus one sentence in `error` (address in use, bad host...).
  bool start(std::string& error);
  std::uint16_t port() const;
  // Sends the message to every client subscribed to `channel_id`, and on a latched channel keeps
  // it for those who subscribe later. The payload is shared.
  void publish(std::uint32_t channel_id, std::uint64_t log_time_ns,
               std::shared_ptr<const std::vector<std::uint8_t>> payload);
  // Tells the clients that subscribed to these parameters their new values.
  void broadcast_parameters(std::vector<Parameter> parameters);
  // A status message to every client (e.g. the lidar's link went down), under `id`.
  void broadcast_status(StatusLevel level, std::string message, std::string id = "ydscope-link");
  // Withdraws the status sent under `id` from every client (the link is back).
  void remove_status(std::string id);
  // Connected clients and their counters (waits for the server's thread).
  std::vector<ClientStats> clients() const;
  void stop();

  class Impl;

 private:
  std::unique_ptr<Impl> impl_;
};

}  // namespace ydscope::foxglove
