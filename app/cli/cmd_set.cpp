// ydscope-cli set: move a lidar's scan or ranging frequency to a target and print the read-back.
#include <cstdio>
#include <future>
#include <memory>
#include <stdexcept>
#include <string>

#include "app/common/arguments.h"
#include "app/cli/cli_command.h"
#include "app/cli/lap_json.h"
#include "app/cli/session_cli.h"
#include "core/text/json_writer.h"

namespace ydscope::cli {
namespace {

constexpr std::string_view kSetHelp =
    R"(usage: ydscope-cli set --port PATH [--model auto|MODEL] [--baud B|auto] (--scan-hz F | --ranging-khz K)

Steps the set scan frequency (A5 09/0A/0B/0C: +-0.1 and +-1 Hz) until the read-back (A5 0D) is
the target, or cycles the ranging frequency (A5 D0) until A5 D1 reads it. The lidar is stopped
while commands run, as the manuals require. The G1's ranging frequency is read-only.

options:
  --port PATH        serial port or tcp://host:port
  --model MODEL      auto (default), G1, G6, TG15, TG30, TG50
  --baud B           line rate, or auto to probe (see `ydscope-cli info --help`)
  --conventions C    field (default): read the unit as real units of its model and firmware write
                     (G6 S/2 mm, 18 k samples/s; TG S mm, no correction); manual: as its manual says.
                     docs/conventions.md lists every value and its source
  --scan-hz F        target scan frequency in Hz (the models' range is 5 to 12 Hz)
  --ranging-khz K    target ranging frequency in kHz (G6/TG: 4, 8 or 9)

output: one JSON object, the read-back after the attempt:
  {"ok":true,"scan_hz":10|null,"ranging_khz":9|null,"message":"scan frequency reads back 10.00 Hz"}

exit status: 0 the target was reached; 1 it was not (the JSON still shows the read-back, and
stderr says why) or the device failed; 2 usage error (a port that does not exist included).

examples:
  ydscope-cli set --port /dev/ttyUSB0 --scan-hz 10
  ydscope-cli set --port tcp://192.168.1.20:2000 --model TG30 --ranging-khz 8
)";

int run_set(std::span<const std::string> raw) {
  const Arguments args(raw, session_value_options({"scan-hz", "ranging-khz"}), {});
  const auto scan_hz = args.number("scan-hz", 0.1, 100.0);
  const auto ranging_khz = args.integer("ranging-khz", 1, 100);
  if (scan_hz.has_value() == ranging_khz.has_value())
    throw UsageError("give exactly one of --scan-hz F or --ranging-khz K");
  const SessionConfig config = session_config_from(args, /*scan=*/false);
  Session session(1);
  connect_or_throw(session, config);

  auto promise = std::make_shared<std::promise<CommandResult>>();
  auto future = promise->get_future();
  const CommandCallback done = [promise](const CommandResult& r) { promise->set_value(r); };
  if (scan_hz)
    session.set_scan_hz(*scan_hz, done);
  else
    session.set_ranging_khz(static_cast<std::uint16_t>(*ranging_khz), done);
  if (future.wait_for(std::chrono::seconds(120)) != std::future_status::ready)
    throw std::runtime_error("the command did not finish within 120 s on " + config.address);
  const CommandResult result = future.get();

  JsonOut out(stdout);
  JsonObject(out.buffer())
      .field("ok", result.ok)
      .field("scan_hz", result.scan_hz, 2)
      .field("ranging_khz", result.ranging_khz)
      .field("message", result.message);
  out.raw("\n");
  out.flush();
  std::fflush(stdout);
  if (!result.ok) {
    std::fprintf(stderr, "ydscope-cli set: %s\n", result.message.c_str());
    return kExitFailure;
  }
  return kExitOk;
}

const RegisterCliCommand set_command{
    {"set", "set a lidar's scan or ranging frequency and print the read-back", kSetHelp, &run_set}};

}  // namespace
}  // namespace ydscope::cli
