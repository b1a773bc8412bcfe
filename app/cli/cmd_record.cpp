// ydscope-cli record: every byte between a live lidar and us, both directions, into a .ydrec file,
// an MCAP file, or both.
#include <csignal>
#include <string>

#include "app/common/arguments.h"
#include "app/cli/cli_command.h"
#include "app/cli/mcap_output.h"
#include "app/cli/record_sources.h"
#include "app/cli/session_cli.h"
#include "app/cli/source_options.h"

namespace ydscope::cli {
namespace {

constexpr std::string_view kRecordHelp =
    R"(usage: ydscope-cli record --port PATH (--out FILE | --mcap OUT.mcap | both) [--model auto|MODEL]
                          [--baud B|auto] [--seconds S] [--force] [MCAP options]
       ydscope-cli record --port PATH [--name NAME] [--pose X,Y,YAW[,flip]] --port PATH ...
                          (--out FILE | --mcap OUT.mcap | both) [--model ...] [--baud ...] [--seconds S]

Connects to the lidar, starts it scanning and records every byte in both directions (the start-up
commands and replies, then the scan stream) with its time, and the device's details, into FILE
(format: core/record/recording_format.h; replay it with `ydscope-cli replay FILE` or decode it
with `ydscope-cli decode FILE`). The file is written as it grows: if the program is killed, the
file is still readable up to the last ~100 ms.

With --mcap, the same session goes live into an MCAP file as well (or instead): /scan, /points,
/diagnostics and the link bytes, as `ydscope-cli export --help` describes. Its chunks are closed
and flushed at least once a second, so a killed recorder leaves an MCAP whose flushed chunks a
streaming reader recovers (it lacks the summary; `ydscope-cli export` of the .ydrec makes a full one).

Several lidars: give --port once for each; all go into one FILE (recording format version 2),
every lap tagged with its lidar's name by replay and decode; --mcap puts each lidar's topics under
its name (/NAME/scan, /NAME/points ...) with every pose on /tf_static, as `export` does. Each
lidar has a session of its own and reconnects by itself: one that stops is said in one line on
stderr and the others keep recording. --seconds counts from when every lidar scans (or was said
to be in trouble). One lidar is recorded the same way, as a set of one: its file is version 1 and
its topics keep their plain names (/scan).

options:
  --port PATH      serial port (see `ydscope-cli ports`) or tcp://host:port; repeat for several lidars
  --name NAME      several lidars: each one's name (letters, digits, _), once per --port in the
                   same order (default lidar0, lidar1, ...)
  --pose X,Y,YAW[,flip]  several lidars: where each sits on the robot, once per --port, as
                   ROS says it (REP-103): metres forward, metres left, degrees counter-clockwise;
                   flip when mounted upside down (default 0,0,0)
  --out FILE       the recording to write (.ydrec by convention): a regular file in a folder
                   that exists (not a device such as /dev/null: a recording is read back); an
                   existing file is refused unless --force is given
  --mcap OUT.mcap  the MCAP file to write live; an existing file is refused unless --force
  --model MODEL    auto (default: detect from the device info), G1, G6, TG15, TG30, TG50; with
                   several --port, once for all or once per --port
  --baud B         line rate, or auto to probe (default: the model's, 230400 when auto); like --model
  --conventions C  field (default): read the unit as real units of its model and firmware write
                   (G6 S/2 mm, 18 k samples/s; TG S mm, no correction); manual: as its manual says.
                   docs/conventions.md lists every value and its source
  --seconds S      stop after S seconds of scanning (default: until Ctrl-C)
  --force          overwrite FILE and OUT.mcap
  --no-reconnect   end the recording at the first link fault; by default a lidar that drops
                   (a pulled cable, a stall) is reconnected, its settings put back, and the
                   gap marked in the files (link_fault metadata, /diagnostics), said on stderr
)" YDSCOPE_MCAP_OPTIONS_HELP R"(
On a terminal, progress (time, bytes, laps) is shown on stderr and updated in place. Ctrl-C ends
the recording cleanly: the file is closed, the lidar stopped and the summary printed.

output: one summary line on stdout per file (several lidars: a line for the file, then one per
lidar: "  NAME: MODEL on PORT, B bytes from the device, H bytes to it, L laps"), read back from the finished .ydrec (L: laps decoded
from it) and counted while writing the MCAP:
  recorded FILE: S s, B bytes from the device, H bytes to it, L laps
  wrote OUT.mcap: L laps, M messages in C chunks, B bytes
When the lidar reported a health warning or error, the first line ends with the worst of them:
  ...; the lidar reported a health error: error (error code 0x00FF) (A5 91)

health: a warning or an error the lidar reports (its A5 91/92 answer, or G1's CT health bits) is
one line on stderr when it first shows and again whenever it changes, back to ok included.
A bad line (more than one packet in twenty, and at least ten, failing the checksum) is one line
on stderr at the end: check the cable, the power supply and that no other program has the port.

exit status: 0 recorded (a health warning does not change this); 3 recorded, but the lidar
reported a health error; 1 the device or the file failed (one sentence on stderr; what was
recorded until then stays in FILE; several lidars: one of them never scanned); 2 usage error
(a bad --pose or --name, a port that does not exist).

examples:
  ydscope-cli record --port /dev/ttyUSB0 --out bench.ydrec --seconds 10
  ydscope-cli record --port tcp://192.168.1.20:2000 --model G6 --out g6.ydrec
  ydscope-cli record --port /dev/ttyUSB0 --mcap bench.mcap --seconds 60
  ydscope-cli record --port /dev/ttyUSB0 --out bench.ydrec --mcap bench.mcap
  ydscope-cli record --port /dev/ttyUSB0 --name front --pose 0.2,0,0 \
                     --port /dev/ttyUSB1 --name back --pose -0.2,0,180,flip --out robot.ydrec --mcap robot.mcap
)";

int run_record(std::span<const std::string> raw) {
  const Arguments args(
      raw, with_mcap_value_options(session_value_options({"out", "seconds", "mcap", "name", "pose", "serial"})),
      with_mcap_flags({"force", "no-reconnect"}), 0, source_repeatable_options());
  end_on_signals();
  return record_sources(args, end_requested());
}

const RegisterCliCommand record_command{
    {"record", "record every byte of a live lidar session to a file", kRecordHelp, &run_record}};

}  // namespace
}  // namespace ydscope::cli
