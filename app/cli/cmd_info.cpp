// ydscope-cli info: what the lidar on a port says about itself, as one JSON object.
#include <cstdio>
#include <string>

#include "app/common/arguments.h"
#include "app/cli/cli_command.h"
#include "app/cli/lap_json.h"
#include "app/cli/session_cli.h"
#include "core/text/json_writer.h"

namespace ydscope::cli {
namespace {

constexpr std::string_view kInfoHelp = R"(usage: ydscope-cli info --port PATH [--model auto|MODEL] [--baud B|auto]

Stops the lidar if it was scanning, asks for its device info, health, scan frequency and ranging
frequency, and prints them as one JSON object on one line.

options:
  --port PATH     serial port (/dev/ttyUSB0, a pseudo-terminal) or tcp://host:port (ser2net)
  --model MODEL   auto (default: detected from the device-info model code), G1, G6, TG15, TG30, TG50
  --baud B        line rate; default the model's (G1 230400, G6/TG 512000; both tried when the
                  model is auto); auto tries 230400, 512000, 128000 and 115200
  --conventions C field (default): read the unit as real units of its model and firmware write
                  (G6 S/2 mm, 18 k samples/s; TG S mm, no correction); manual: as its manual says.
                  docs/conventions.md lists every value and its source

output:
  {"model":"G6","model_code":13,"firmware":"1.2","hardware":1,"serial":"...",
   "health":{"command":"A5 91","status":0,"error_code":0,"summary":"ok"}|null,
   "scan_hz":8|null,"ranging_khz":9|null,"port":"/dev/ttyUSB0 at 512000 baud","baud":512000,
   "distance_scale":0.5,
   "conventions":{"id":"g6-field","reading":"field","label":"field (vendor SDK): S/2 mm, ..."}}
  health, scan_hz and ranging_khz are null when the device did not answer that question.

exit status: 0 the device answered; 1 it could not be opened or did not answer (one sentence on
stderr says which and what to try); 2 usage error (a port that does not exist included).

example:
  ydscope-cli info --port /dev/ttyUSB0
)";

int run_info(std::span<const std::string> raw) {
  const Arguments args(raw, session_value_options({}), {});
  const SessionConfig config = session_config_from(args, /*scan=*/false);
  Session session(1);
  const SessionSnapshot s = connect_or_throw(session, config);
  JsonOut out(stdout);
  {
    JsonObject line(out.buffer());
    write_device_fields(line, s);
  }
  out.raw("\n");
  out.flush();
  return std::fflush(stdout) == 0 ? kExitOk : kExitFailure;
}

const RegisterCliCommand info_command{
    {"info", "print a lidar's model, firmware, serial, health and frequencies as JSON", kInfoHelp, &run_info}};

}  // namespace
}  // namespace ydscope::cli
