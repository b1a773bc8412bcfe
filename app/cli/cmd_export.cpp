// ydscope-cli export: a recording (.ydrec) -> an MCAP file that Foxglove and ROS 2 tools open.
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/cli/session_cli.h"
#include "app/common/arguments.h"
#include "app/cli/cli_command.h"
#include "app/cli/mcap_output.h"
#include "app/cli/recording_input.h"
#include "core/export/mcap_recording_export.h"
#include "core/record/recording_reader.h"

namespace ydscope::cli {
namespace {

constexpr std::string_view kExportHelp =
    R"(usage: ydscope-cli export REC.ydrec --mcap OUT.mcap [--model MODEL] [--distance-scale X]
                          [--compression zstd|lz4|none] [--frame-id ID] [--no-link-bytes] [--force]

Converts a recording (from `ydscope-cli record` or the app) into an MCAP file (profile ros2, every
channel CDR with a ros2msg schema) that Foxglove, `ros2 bag play` and the MCAP tools open:

  /scan                   sensor_msgs/msg/LaserScan, one per lap, binned like the official ROS 2
                          driver (angle_min -pi, angle_max pi, one bin per point, ROS angles
                          counter-clockwise with the driver's 180-degree turn), with REP-117's
                          values: +Inf no return or beyond range_max, -Inf below range_min, NaN a
                          bin no point fell in; no intensities (no unit here measures return
                          strength); stamp = receive time of the lap's first byte (its first ray),
                          scan_time = first byte to closing byte, time_increment = that / points;
                          logged when the closing byte came
  /points                 sensor_msgs/msg/PointCloud2, every return of the lap (a point without a
                          return is left out, so is_dense holds): x y z (m), range (m), angle (the
                          corrected device angle in degrees), and on a G1 interference_flag (uint8,
                          2 specular reflection, 3 ambient light); stamped and logged as /scan
  /diagnostics            diagnostic_msgs/msg/DiagnosticArray once per recorded second: device,
                          health, set and measured scan rate, ranging frequency, error counters
  /ydscope/device_bytes   std_msgs/msg/UInt8MultiArray, the bytes exactly as recorded, both ways,
  /ydscope/host_bytes     so the MCAP can be decoded again like the recording

The laps are the ones `ydscope-cli decode REC.ydrec` prints. Times are the recording's start
wall-clock time plus each record's time.

A recording of several lidars (`record` with several --port) puts each lidar's topics under its
name, /NAME/scan, /NAME/points, /NAME/diagnostics, /NAME/ydscope/device_bytes and host_bytes,
with NAME as their frame_id. /tf_static (tf2_msgs/msg/TFMessage) places every lidar, one too:
its pose as the transform from the robot's frame (--parent-frame, default base_link; x forward,
y left) to its frame (an upside-down lidar rolled 180 degrees), and under that NAME_unit, whose x
is the unit's 0 degrees and y its 90 (z down: the unit sweeps clockwise seen from above).

options:
  --mcap OUT.mcap    the file to write; an existing file is refused unless --force is given
  --model MODEL      decode as this model instead of the recording's
  --distance-scale X mm per raw distance unit, instead of the recording's
  --conventions C    field or manual, instead of the conventions the recording was made with
                     (recordings without them were read as the manuals say)
)" YDSCOPE_MCAP_OPTIONS_HELP R"(  --force            overwrite OUT.mcap

On a terminal, progress is shown on stderr. Output: one line on stdout,
  exported REC.ydrec -> OUT.mcap: L laps, M messages in C chunks, B bytes

exit status: 0 exported (a recording cut off at its end is exported up to the cut, with a warning);
1 reading or writing failed; 2 usage error.

examples:
  ydscope-cli export bench.ydrec --mcap bench.mcap
  ydscope-cli export g6.ydrec --mcap g6.mcap --compression lz4 --frame-id base_laser
)";

using Clock = std::chrono::steady_clock;

int run_export(std::span<const std::string> raw) {
  const Arguments args(raw, with_mcap_value_options({"mcap", "model", "distance-scale", "conventions"}),
                       with_mcap_flags({"force"}),
                       /*max_positionals=*/1);
  const std::string path = args.single_positional("REC.ydrec");
  const std::string out = args.required("mcap");
  require_existing_file(path, "recording");
  if (const std::string problem = not_a_regular_file(path); !problem.empty()) throw std::runtime_error(problem);
  if (!is_recording_file(path))
    throw UsageError(
        path +
        " is not a ydscope recording (.ydrec); for raw lidar bytes use `ydscope-cli decode --model MODEL --mcap " +
        out + " " + path + "`");
  refuse_to_overwrite(out, args, "--mcap");
  McapExportOptions options = mcap_options_from(args);
  // One pass for the merged metadata: the model may be named only after the recording started.
  const RecordingPlan plan = recording_plan_or_throw(path, RecordingUse::Decode, args.value("model"));
  options.ros.model = plan.profile->model;
  options.ros.distance_scale = args.number("distance-scale", 1e-6, 1e6);
  options.ros.reading = reading_option(args);

  std::string error;
  auto reader = RecordingReader::open(path, error);
  if (!reader) throw std::runtime_error(error);
  // Several lidars: each under its name, decoded as its own model, and /tf_static.
  if (plan.several_sources() && args.value("frame-id"))
    throw UsageError("--frame-id names one lidar's frame, but " + path + " holds " +
                     std::to_string(plan.sources.size()) +
                     " lidars, each written in a frame named after it; leave --frame-id out");
  // The recording's lidars as a set, as record and serve take theirs: one is a set of one, whose
  // topics keep their plain names (named_apart).
  std::vector<SourceInfo> sources;
  for (std::size_t id = 0; id < plan.sources.size(); ++id)
    sources.push_back({plan.sources[id].name, plan.summary.sources[id].metadata.pose.value_or(Pose{}),
                       plan.sources[id].profile->model});
  auto exporter = McapRecordingExport::create(out, options, error, std::move(sources));
  if (!exporter) throw std::runtime_error(error);
  const auto laps = [&] {
    std::uint64_t total = 0;
    for (std::size_t id = 0; id < exporter->source_count(); ++id) total += exporter->encoder(id).laps();
    return total;
  };

  const bool tty = ::isatty(STDERR_FILENO) == 1;
  const double total = static_cast<double>(std::filesystem::file_size(path));
  auto last_progress = Clock::now();
  RecordView record;
  while (reader->next(record)) {
    exporter->record(record.type, record.payload, record.t_ns, record.source);
    if (exporter->failed()) break;
    if (tty && Clock::now() - last_progress > std::chrono::milliseconds(200)) {
      last_progress = Clock::now();
      std::fprintf(stderr, "\r\033[Kexporting %s: %.0f%% (%.0f s of recording, %llu laps)", path.c_str(),
                   100.0 * static_cast<double>(record.file_offset) / total, static_cast<double>(record.t_ns) / 1e9,
                   static_cast<unsigned long long>(laps()));
      std::fflush(stderr);
    }
  }
  if (tty) std::fputs("\r\033[K", stderr);
  const bool ok = exporter->finish();
  if (!ok) throw std::runtime_error("writing " + out + " failed: " + exporter->error());
  const auto& stats = exporter->statistics();
  std::printf("exported %s -> %s: %llu laps, %llu messages in %u chunks, %llu bytes\n", path.c_str(), out.c_str(),
              static_cast<unsigned long long>(laps()), static_cast<unsigned long long>(stats.message_count),
              stats.chunk_count, static_cast<unsigned long long>(exporter->bytes_written()));
  std::fflush(stdout);
  print_recording_warnings("ydscope-cli export", plan.warnings());
  return kExitOk;
}

const RegisterCliCommand export_command{
    {"export", "convert a recording to MCAP for Foxglove and ROS 2 (/scan, /points, ...)", kExportHelp, &run_export}};

}  // namespace
}  // namespace ydscope::cli
