#include "app/cli/serve_sources.h"

#include <chrono>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "app/cli/link_loss_notes.h"
#include "app/cli/mcap_output.h"
#include "app/cli/source_options.h"
#include "core/link/session_io.h"

namespace ydscope::cli {
namespace {

using Clock = std::chrono::steady_clock;

}  // namespace

void warn_if_not_loopback(const SessionShare& share) {
  if (is_loopback_host(share.host())) return;
  std::fprintf(stderr,
               "ydscope-cli serve: warning: serving on %s: anyone who can reach this address can watch the "
               "lidar and change its settings (there is no authentication)\n",
               share.host().c_str());
}

void serve_until_stopped(SessionShare& share, const std::vector<ServedLidar>& lidars, std::optional<double> seconds,
                         const std::atomic<bool>& stop) {
  const auto start = Clock::now();
  // A lidar's loss and its return ("scanning again after 1.6 s; reconnected; re-applied ..."),
  // as record and scan say them.
  std::vector<LinkLossNotes> notes;
  for (const ServedLidar& lidar : lidars)
    notes.emplace_back("ydscope-cli serve", lidar.name.empty() ? "the lidar" : lidar.name,
                       "serving on; the clients see the outage on /diagnostics");
  Lap lap;
  while (!stop.load() && (!seconds || std::chrono::duration<double>(Clock::now() - start).count() < *seconds)) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    if (const std::string failed = share.topics().error(); !failed.empty()) throw std::runtime_error(failed);
    for (std::size_t id = 0; id < lidars.size(); ++id) {
      lidars[id].session->laps().drain_newest(lap);  // the served laps come from the tap; keep the queue empty
      notes[id].follow(lidars[id].session->snapshot(), /*tty=*/false);
    }
  }

  for (const auto& c : share.clients())
    std::fprintf(stderr, "ydscope-cli serve: client %s: %llu messages sent, %llu dropped\n", c.peer.c_str(),
                 static_cast<unsigned long long>(c.sent), static_cast<unsigned long long>(c.dropped));
  const bool written = share.stop();
  for (const ServedLidar& lidar : lidars) lidar.session->disconnect();
  if (!written) throw std::runtime_error(share.topics().error());
  if (const auto dropped = share.topics().dropped())
    std::fprintf(stderr, "ydscope-cli serve: warning: %llu records were dropped: serving fell behind the lidars\n",
                 static_cast<unsigned long long>(dropped));
  if (!share.topics().mcap_path().empty())
    std::fprintf(stderr, "ydscope-cli serve: wrote %s: %llu laps, %llu messages\n", share.topics().mcap_path().c_str(),
                 static_cast<unsigned long long>(share.topics().laps()),
                 static_cast<unsigned long long>(share.topics().messages()));
}

int serve_sources(const Arguments& args, foxglove::ServerOptions server_options, const std::atomic<bool>& stop) {
  const auto seconds = args.number("seconds", 0.001, 1e9);
  const auto mcap_path = args.value("mcap");
  if (mcap_path) refuse_to_overwrite(*mcap_path, args, "--mcap");
  std::vector<SourceSpec> specs = source_specs_from(args, /*scan=*/true);
  std::vector<std::unique_ptr<Session>> sessions;
  std::vector<SessionShare::Source> shared;
  std::vector<ServedLidar> lidars;
  for (SourceSpec& spec : specs) {
    spec.config.reconnect = true;
    sessions.push_back(std::make_unique<Session>(4));
    shared.push_back({sessions.back().get(), {spec.name, spec.pose, spec.config.model}});
    lidars.push_back({spec.name, sessions.back().get()});
  }
  ShareOptions options;
  options.server = std::move(server_options);
  options.server.name = "ydscope on " + std::to_string(specs.size()) + " lidars";
  options.topics = mcap_options_from(args);
  options.mcap_path = mcap_path.value_or("");
  std::string error;
  auto share = SessionShare::start(shared, std::move(options), error);
  if (!share) throw std::runtime_error(error);
  warn_if_not_loopback(*share);
  for (std::size_t id = 0; id < specs.size(); ++id) sessions[id]->connect(specs[id].config);
  std::printf("serving %s for %zu lidars:", share->address().c_str(), specs.size());
  for (const SourceSpec& spec : specs) std::printf(" %s on %s", spec.name.c_str(), spec.config.address.c_str());
  std::printf("\n");
  std::fflush(stdout);
  serve_until_stopped(*share, lidars, seconds, stop);
  return 0;
}

}  // namespace ydscope::cli
