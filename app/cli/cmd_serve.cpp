// ydscope-cli serve: the headless robot-side server. Scans a lidar (reconnecting by itself),
// serves it live over the Foxglove WebSocket protocol and optionally records it to MCAP. One lidar
// or several alike: a SourceSet shared by one SessionShare (a set of one keeps the plain names).
#include <chrono>
#include <csignal>
#include <cstdio>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

#include "app/common/arguments.h"
#include "app/cli/cli_command.h"
#include "app/cli/mcap_output.h"
#include "app/cli/link_loss_notes.h"
#include "app/cli/session_cli.h"
#include "app/cli/source_options.h"
#include "core/analysis/zone.h"
#include "core/bridge/session_share.h"
#include "core/session/source_set.h"

namespace ydscope::cli {
namespace {

constexpr std::string_view kServeHelp =
    R"(usage: ydscope-cli serve --port PATH|tcp://HOST:PORT [--listen HOST:PORT] [--mcap FILE]
                         [--model auto|MODEL] [--baud B|auto] [--queue N] [--seconds S]
                         [--force] [MCAP options]
       ydscope-cli serve --port PATH [--name NAME] [--pose X,Y,YAW[,flip]] --port PATH ... [options]

Connects to the lidar and keeps it scanning (reconnecting after faults, like the app), and serves
it live to Foxglove over the Foxglove WebSocket protocol (subprotocol foxglove.websocket.v1):
/scan, /points, /diagnostics, /ydscope/device_bytes and /ydscope/host_bytes, the same topics and
ROS 2 schemas as `ydscope-cli export --help` describes. Several clients may connect at once; each
has its own send queue, and a slow client loses its oldest messages (counted, and told by a
status message), never slowing the lidar or the other clients.

Parameters (Foxglove's Parameters panel, or any client's setParameters):
  scan_hz                float, set through the session's command sequencing; the value the
                         clients see is what the device reads back
  ranging_khz            float, G6/TG: cycled until the device reads it back
  power_down_protection  bool, off until set (a unit powers on without it)
  filter_specular        bool, drop G1 points flagged as specular reflection (flag 2)
  filter_ambient         bool, drop G1 points flagged as ambient light (flag 3)
After a reconnect (a pulled cable, a stall) the lidar is set back to the scan_hz, ranging_khz and
power_down_protection last set, before its scan resumes; a status message says what was
re-applied (or could not be), and clients subscribed to parameter updates get the values in
force. The filters are the server's own and never change with the lidar. /diagnostics keeps its
rate through an outage (level ERROR: "no data for 5.0 s; reconnecting to PORT: why"); its level
is the lidar's state now, checksum errors counting for 5 s.

Several lidars (--port once for each): each scans in a session of its own and is served under
its name, /NAME/scan, /NAME/points, /NAME/diagnostics, /NAME/ydscope/device_bytes and
host_bytes (frame_id NAME), plus /tf_static (tf2_msgs/msg/TFMessage, sent every second): every
pose as the transform from the common frame "ydscope" to NAME. Parameters are NAME/scan_hz and
so on; --mcap records the same topics. One lidar's fault is a status message naming it.

options:
  --port PATH        serial port (see `ydscope-cli ports`) or tcp://host:port; repeat for several
  --name NAME        several lidars: each one's name, once per --port in order (default lidar0, ...)
  --pose X,Y,YAW[,flip]  several lidars: each one's place, once per --port (REP-103: metres
                     forward, metres left, degrees counter-clockwise; flip when mounted upside
                     down; default 0,0,0)
  --listen HOST:PORT where to accept WebSocket clients (default 127.0.0.1:8765, this machine
                     only). Any other address serves the lidar to the network, without any
                     authentication: a warning says so. Port 0 picks a free port.
  --mcap FILE        also record everything to this MCAP file (chunks flushed every second)
  --model MODEL      auto (default: detect from the device info), G1, G6, TG15, TG30, TG50
  --baud B           line rate, or auto to probe (default: the model's, 230400 when auto)
  --conventions C    field (default): read the unit as real units of its model and firmware write
                     (G6 S/2 mm, 18 k samples/s; TG S mm, no correction); manual: as its manual says.
                     docs/conventions.md lists every value and its source
  --queue N          messages queued per client before its oldest are dropped (default 64)
  --seconds S        stop after S seconds (default: until Ctrl-C or SIGTERM)
  --zone SPEC        watch a zone, repeatable: NAME:sector:FROM:TO[:MIN_MM:MAX_MM][:RULE] (the
                     lidar's angles, a band in mm) or NAME:polygon:X,Y/X,Y/X,Y[/...][:RULE]
                     (corners in metres in the robot's frame, REP-103). RULE: enter (default;
                     raised while something is in it) or empty (raised while nothing is). Each
                     zone's status is published on /zones (diagnostic_msgs/msg/DiagnosticArray,
                     at once on every entry or exit and once a second) and beside the lidar's
                     on /diagnostics; with several lidars each watches every zone
)" YDSCOPE_MCAP_OPTIONS_HELP R"(  --force            overwrite FILE

On start, one line on stdout says where it serves:  serving ws://HOST:PORT for PORT
Open it in Foxglove: "Open connection" -> "Foxglove WebSocket" -> ws://HOST:PORT.
Ctrl-C or SIGTERM stops cleanly (the MCAP gets its summary); per-client counters go to stderr.

exit status: 0 stopped by a signal or --seconds; 1 the listen address or the MCAP file failed;
2 usage error (a port that does not exist when serve starts included). A lidar that is unplugged
or silent later is not an exit: the server keeps retrying and tells its clients with a status
message.

examples:
  ydscope-cli serve --port /dev/ttyUSB0
  ydscope-cli serve --port /dev/ttyUSB0 --listen 0.0.0.0:8765 --mcap /var/lib/ydscope/run.mcap
)";

using Clock = std::chrono::steady_clock;

foxglove::ServerOptions listen_options(const Arguments& args) {
  foxglove::ServerOptions options;
  if (const auto listen = args.value("listen")) {
    const std::size_t colon = listen->rfind(':');
    if (colon == std::string::npos || colon == 0)
      throw UsageError("--listen takes HOST:PORT, e.g. 127.0.0.1:8765 or 0.0.0.0:8765, not '" + *listen + "'");
    options.host = listen->substr(0, colon);
    if (options.host.size() > 2 && options.host.front() == '[' && options.host.back() == ']')
      options.host = options.host.substr(1, options.host.size() - 2);
    const std::string port = listen->substr(colon + 1);
    char* end = nullptr;
    const long value = std::strtol(port.c_str(), &end, 10);
    if (port.empty() || *end || value < 0 || value > 65535)
      throw UsageError("--listen port must be 0..65535, not '" + port + "'");
    options.port = static_cast<std::uint16_t>(value);
  }
  if (const auto queue = args.integer("queue", 1, 100000)) options.client_queue = static_cast<std::size_t>(*queue);
  return options;
}

// The warning for a share reachable from other machines: there is no authentication.
void warn_if_not_loopback(const SessionShare& share) {
  if (is_loopback_host(share.host())) return;
  std::fprintf(stderr,
               "ydscope-cli serve: warning: serving on %s: anyone who can reach this address can watch the "
               "lidar and change its settings (there is no authentication)\n",
               share.host().c_str());
}

// Until `stop` or `seconds`: then the clients' counters, the share stopped (the MCAP file gets
// its summary), the sessions disconnected and what was written said. Throws with one sentence
// when writing the file failed.
void serve_until_stopped(SessionShare& share, SourceSet& set, std::optional<double> seconds) {
  const auto start = Clock::now();
  // A lidar's loss and its return ("scanning again after 1.6 s; reconnected; re-applied ..."),
  // as record and scan say them.
  std::vector<LinkLossNotes> notes;
  for (std::size_t id = 0; id < set.size(); ++id)
    notes.emplace_back("ydscope-cli serve", named_apart(set.infos()) ? set.info(id).name : "the lidar",
                       "serving on; the clients see the outage on /diagnostics");
  Lap lap;
  while (!end_requested().load() &&
         (!seconds || std::chrono::duration<double>(Clock::now() - start).count() < *seconds)) {
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
    if (const std::string failed = share.topics().error(); !failed.empty()) throw std::runtime_error(failed);
    for (std::size_t id = 0; id < set.size(); ++id) {
      set.session(id).laps().drain_newest(lap);  // the served laps come from the tap; keep the queue empty
      notes[id].follow(set.session(id).snapshot(), /*tty=*/false);
    }
  }

  for (const auto& c : share.clients())
    std::fprintf(stderr, "ydscope-cli serve: client %s: %llu messages sent, %llu dropped\n", c.peer.c_str(),
                 static_cast<unsigned long long>(c.sent), static_cast<unsigned long long>(c.dropped));
  const bool written = share.stop();
  for (std::size_t id = 0; id < set.size(); ++id) set.session(id).disconnect();
  if (!written) throw std::runtime_error(share.topics().error());
  if (const auto dropped = share.topics().dropped())
    std::fprintf(stderr, "ydscope-cli serve: warning: %llu records were dropped: serving fell behind the lidars\n",
                 static_cast<unsigned long long>(dropped));
  if (!share.topics().mcap_path().empty())
    std::fprintf(stderr, "ydscope-cli serve: wrote %s: %llu laps, %llu messages\n", share.topics().mcap_path().c_str(),
                 static_cast<unsigned long long>(share.topics().laps()),
                 static_cast<unsigned long long>(share.topics().messages()));
}

int run_serve(std::span<const std::string> raw) {
  const Arguments args(raw,
                       with_mcap_value_options(session_value_options(
                           {"listen", "mcap", "queue", "seconds", "name", "pose", "serial", "zone"})),
                       with_mcap_flags({"force"}), 0, [] {
                         auto repeatable = source_repeatable_options();
                         repeatable.insert("zone");
                         return repeatable;
                       }());
  ShareOptions options;
  options.server = listen_options(args);
  const auto seconds = args.number("seconds", 0.001, 1e9);
  const auto mcap_path = args.value("mcap");
  if (mcap_path) refuse_to_overwrite(*mcap_path, args, "--mcap");
  // Zones first: a mistaken one is a usage error before any port is looked for.
  std::vector<Zone> zones;
  for (const std::string& spec : args.values("zone")) {
    std::string error;
    auto zone = parse_zone(spec, error);
    if (!zone) throw UsageError("--zone: " + error);
    zones.push_back(std::move(*zone));
  }
  std::vector<SourceSpec> specs = source_specs_from(args, /*scan=*/true);
  for (SourceSpec& spec : specs) spec.config.reconnect = true;  // a robot's server rides out faults
  SourceSet set(std::move(specs));
  const bool several = named_apart(set.infos());
  options.topics = mcap_options_from(args);
  options.topics.ros.zones = std::move(zones);
  options.mcap_path = mcap_path.value_or("");
  options.server.name = "ydscope on " + (several ? std::to_string(set.size()) + " lidars" : set.config(0).address);

  end_on_signals();
  // Clients and the MCAP file get the sessions' records from their taps, on a thread of their own.
  std::vector<SessionShare::Source> shared;
  for (std::size_t id = 0; id < set.size(); ++id) shared.push_back({&set.session(id), set.info(id)});
  std::string error;
  auto share = SessionShare::start(shared, std::move(options), error);
  if (!share) throw std::runtime_error(error);
  warn_if_not_loopback(*share);
  set.connect_all();
  if (several) {
    std::printf("serving %s for %zu lidars:", share->address().c_str(), set.size());
    for (std::size_t id = 0; id < set.size(); ++id)
      std::printf(" %s on %s", set.info(id).name.c_str(), set.config(id).address.c_str());
    std::printf("\n");
  } else {
    std::printf("serving %s for %s\n", share->address().c_str(), set.config(0).address.c_str());
  }
  std::fflush(stdout);
  serve_until_stopped(*share, set, seconds);
  return kExitOk;
}

const RegisterCliCommand serve_command{
    {"serve", "serve a lidar live to Foxglove over WebSocket (and record MCAP)", kServeHelp, &run_serve}};

}  // namespace
}  // namespace ydscope::cli
