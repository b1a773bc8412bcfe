#pragma once
// Shared pieces of the session tests: a virtual lidar on a pseudo-terminal (reached through the
// same SerialLink a real port uses), session configs with generous timeouts, and waits that are
// only upper bounds for hangs (never assertions on time).
#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <functional>
#include <future>
#include <memory>
#include <string>
#include <thread>

#include "core/session/session.h"
#include "core/sim/sim_server.h"
#include "support/temp_dir.h"

namespace ydscope::test {

using namespace std::chrono_literals;

// Generous upper bound for anything to happen (hang guard, not a performance claim).
inline constexpr std::chrono::milliseconds kPatience{20000};

class SimOnPty {
 public:
  explicit SimOnPty(Model model, const std::function<void(SimServerOptions&)>& tweak = {}) {
    SimServerOptions options;
    options.device.model = model;
    options.device.scene = "room";
    options.transport = SimTransport::Pty;
    options.pty_link = (dir_ / "lidar").string();
    if (tweak) tweak(options);
    server_ = std::make_unique<SimServer>(options);
    server_->start();
  }
  ~SimOnPty() { server_.reset(); }  // before its folder goes
  SimServer& server() { return *server_; }
  std::string port() const { return (dir_ / "lidar").string(); }
  SimCounters counters() const { return server_->counters(); }

 private:
  TempDir dir_{"session"};
  std::unique_ptr<SimServer> server_;
};

inline SessionConfig config_for(const std::string& port, std::optional<Model> model = std::nullopt, bool scan = true) {
  SessionConfig config;
  config.address = port;
  config.model = model;
  config.scan = scan;
  config.reply_timeout = 1000ms;
  config.stall_timeout = 2000ms;
  return config;
}

inline bool is_state(const SessionSnapshot& s, LinkState state) { return s.state == state; }

// Waits (bounded) for `state`; the snapshot says what happened when it did not come.
inline SessionSnapshot wait_for_state(const Session& session, LinkState state,
                                      std::chrono::milliseconds patience = kPatience) {
  return session.wait_until([state](const SessionSnapshot& s) { return s.state == state; }, patience);
}

// Pops laps until `count` arrived or patience ran out; returns how many arrived.
inline std::size_t take_laps(Session& session, std::size_t count, std::vector<Lap>* keep = nullptr,
                             std::chrono::milliseconds patience = kPatience) {
  const auto deadline = std::chrono::steady_clock::now() + patience;
  std::size_t taken = 0;
  Lap lap;
  while (taken < count && std::chrono::steady_clock::now() < deadline) {
    if (session.laps().try_pop(lap)) {
      ++taken;
      if (keep) keep->push_back(lap);
    } else {
      std::this_thread::sleep_for(2ms);
    }
  }
  return taken;
}

// Runs a command intent and waits for its result.
template <class Start>
CommandResult run_command(Start&& start, std::chrono::milliseconds patience = kPatience) {
  auto promise = std::make_shared<std::promise<CommandResult>>();
  auto future = promise->get_future();
  start([promise](const CommandResult& result) { promise->set_value(result); });
  if (future.wait_for(patience) != std::future_status::ready) {
    CommandResult timeout;
    timeout.message = "the test gave up waiting for the command result";
    return timeout;
  }
  return future.get();
}

}  // namespace ydscope::test
