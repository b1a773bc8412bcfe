// ydscope-cli decode: raw lidar bytes (a file or stdin) -> laps as JSON lines, or just the counts.
#include <array>
#include <atomic>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "app/cli/session_cli.h"
#include "app/common/arguments.h"
#include "app/cli/cli_command.h"
#include "app/cli/lap_json.h"
#include "app/cli/lap_output.h"
#include "app/cli/mcap_output.h"
#include "app/cli/raw_input.h"
#include "app/cli/recording_input.h"
#include "app/cli/source_playback.h"
#include "core/protocol/function_ref.h"
#include "core/protocol/interference_filter.h"
#include "core/protocol/model_profile.h"
#include "core/protocol/scan_decoder.h"
#include "core/record/recording_reader.h"

namespace ydscope::cli {
namespace {

constexpr std::string_view kDecodeHelp =
    R"(usage: ydscope-cli decode --model MODEL [--format jsonl|csv|summary] [--filter LIST]
                          [--distance-scale X] [--mcap OUT.mcap [MCAP options]] FILE|-

Decodes the raw bytes a lidar sends after the scan command (A5 60) into complete laps.

  FILE                 the bytes exactly as read from the lidar's port, or - for standard input.
                       They may start with the scan reply header (A5 5A 05 00 00 40 81) and may hold
                       junk; junk is skipped and counted, packets with a bad checksum are dropped.
                       FILE may also be a recording (.ydrec, from `ydscope-cli record`, recognised
                       by its header): its device->host bytes are decoded, with its model and
                       the distance scale it was recorded with (as replay does) unless --model
                       is given.
  --model MODEL        G1, G6, TG15, TG30 or TG50, or X4 or X2 (bytes of those units of the same
                       packet family; ydscope does not drive them), any letter case. Picks the
                       distance formula with --conventions (G1: S>>2 mm with the interference
                       flag in S&3; G6: S/2 mm, the manual's S/4; TG: S mm above firmware 1.2,
                       the manual's S/2; X4, X2: S/4 mm) and, on G1, the CT information and
                       LastCRC byte.
  --format FORMAT      jsonl (default): one JSON object per complete lap, then a summary line.
                       csv: the header lap,t,angle_deg,range_mm,flag, then one row per point of
                       every lap (the fields as in jsonl; no summary). summary: only the summary.
  --filter LIST        drop G1 points flagged as interference: specular (flag 2), ambient
                       (flag 3), or both as specular,ambient. Only the lap points change.
  --distance-scale X   millimetres per raw distance unit (after the flag bits), overriding the
                       model's value (G1 1, G6 0.25, TG 0.5). Some vendor-SDK firmware uses other
                       scales (G6 0.5; TG firmware above 1.2 uses 1). From 0.000001 to 1000000;
                       a recording's scale outside that range is ignored with a warning.
  --conventions C      field (default for raw bytes) or manual; a recording is read with the
                       conventions it was made with unless this is given (docs/conventions.md)
  --mcap OUT.mcap      also write the laps as an MCAP file (the topics of `ydscope-cli export
                       --help`; --filter does not apply to it). Raw bytes carry no times: each
                       byte is timed as if it arrived at the model's baud rate from t=0 (Unix
                       epoch). With --mcap, --format defaults to summary. An existing OUT.mcap is
                       refused unless --force is given.
)" YDSCOPE_MCAP_OPTIONS_HELP R"(  --force              overwrite OUT.mcap

A lap runs from a zero packet (CT bit 0 set), inclusive, to the next one, exclusive. Bytes before
the first zero packet and a cut-off packet at the end are not part of any lap.

FILE may be a FIFO or a device: after 1 s without a byte, decode says on stderr what it waits for.
An input whose first 4 MiB hold no valid scan packet (/dev/zero, a wrong file) is not a lidar's
bytes: decode stops there with one sentence and exit status 1.

jsonl schema, one object per line:
  {"type":"lap","index":I,"t":T,"points":[[angle_deg,range_mm,flag],...],"scan_hz":F|null,
   "health":H|null,"crc_ok":true|false|null,"packets":N,"checksum_errors":E[,"cut_points":C]}
    index            0 for the first complete lap
    t                seconds (6 decimals) from the first byte of the first lap to the byte that
                     closed this one: a recording's recorded receive times; for raw bytes, the
                     times the model's baud rate would deliver them at (ten bits a byte)
    points           in received order; angle corrected (both levels of the manuals) in [0,360)
                     with 4 decimals, range in mm with up to 2 decimals (0 = no return), flag S&3 on
                     G1 and 0 otherwise
    scan_hz, health  G1 CT information (scan frequency of the zero packet, health bits of packet 3);
                     a G6/TG read with the field conventions reports scan_hz in its zero packet
                     too (TG: + 3 Hz); null otherwise, when the packet was missing, or when
                     crc_ok is false
    crc_ok           G1: whether the CRC8 of the lap's CT bytes matched the LastCRC byte; null on
                     other models and when no byte lay between the lap's last packet and the zero
                     packet that closes it (nothing to check: scan_hz and health are then kept,
                     unverified). With several bytes there, the one right before the zero packet
                     is the LastCRC.
    packets          valid packets in the lap
    checksum_errors  packets of this lap dropped for a bad checksum
    cut_points       only present when the lap held more than 24000 points (a stream whose zero
                     packets were lost): how many points beyond that were dropped
  {"type":"summary","bytes":B,"packets":P,"checksum_errors":E,"zero_packets":Z,"laps":L[,"cut_points":C]
   [,"start":S]}
    bytes            bytes read; packets: packets with a valid checksum; zero_packets: those with
                     CT bit 0 set; laps: complete laps; cut_points (only when not 0): points
                     dropped from over-long laps, the partial lap included; start (a recording
                     that names it): the wall-clock time it began, ISO 8601 UTC

exit status: 0 the input was read to the end; 1 reading failed, or 4 MiB without a valid packet;
2 usage error (unknown model, missing file, bad option, a recording of a version or header this
ydscope cannot read).

examples:
  ydscope-cli decode --model G6 scan.bin
  ydscope-cli decode --model g1 --filter specular,ambient --format jsonl - < capture.bin
  ydscope-cli decode --model TG15 --distance-scale 1 --format summary tg.bin
)";

// An input this long without one valid scan packet is not a lidar's bytes (/dev/zero, a wrong
// file): decode stops rather than read it for ever. Thousands of packets of any model fit in it.
constexpr std::uint64_t kNoPacketLimit = 4u << 20;

// Raw bytes carry no times: each gets the time the model's baud rate would deliver it at (8N1,
// ten bits a byte, from t=0), in pieces of 64 bytes (1.25 ms at 512000 baud), so laps get
// distinct, plausible times. The laps' t and --mcap's log times both come from here.
class LineRateClock {
 public:
  explicit LineRateClock(std::uint32_t baud) : ns_per_byte_(10e9 / baud) {}
  // Calls piece_at(piece, time of its last byte) for `chunk` in pieces, in order.
  void split(std::span<const std::uint8_t> chunk,
             FunctionRef<void(std::span<const std::uint8_t>, std::int64_t)> piece_at) {
    constexpr std::size_t kPiece = 64;
    for (std::size_t at = 0; at < chunk.size(); at += kPiece) {
      const auto piece = chunk.subspan(at, std::min(kPiece, chunk.size() - at));
      bytes_ += piece.size();
      piece_at(piece, static_cast<std::int64_t>(static_cast<double>(bytes_) * ns_per_byte_));
    }
  }

 private:
  double ns_per_byte_;
  std::uint64_t bytes_ = 0;
};

InterferenceFilter parse_filter(const std::string& list) {
  InterferenceFilter filter;
  std::size_t start = 0;
  while (start <= list.size()) {
    const std::size_t comma = std::min(list.find(',', start), list.size());
    const std::string item = list.substr(start, comma - start);
    if (item == "specular")
      filter.specular = true;
    else if (item == "ambient")
      filter.ambient_light = true;
    else
      throw UsageError("--filter takes specular, ambient or specular,ambient, not '" + list + "'");
    start = comma + 1;
  }
  return filter;
}

// --mcap: the same input as an MCAP file. A recording's records go in with their times; raw
// bytes in small pieces timed at the line rate, so laps get distinct, plausible stamps.
void write_mcap(const Arguments& args, const std::string& path, bool recording, const ModelProfile& profile,
                std::optional<double> scale, std::optional<Reading> reading) {
  const std::string out = *args.value("mcap");
  McapExportOptions options = mcap_options_from(args);
  options.ros.model = profile.model;
  options.ros.distance_scale = scale;
  options.ros.reading = reading;
  std::string error;
  auto exporter = McapRecordingExport::create(out, options, error);
  if (!exporter) throw std::runtime_error(error);
  if (recording) {
    auto reader = RecordingReader::open(path, error);
    if (!reader) throw std::runtime_error(error);
    RecordView record;
    while (reader->next(record) && !exporter->failed()) exporter->record(record.type, record.payload, record.t_ns);
  } else {
    LineRateClock clock(profile.default_baud);
    RawInput again(path, "ydscope-cli decode");  // the first pass read it to the end
    again.read([&](std::span<const std::uint8_t> chunk) {
      clock.split(chunk, [&](std::span<const std::uint8_t> piece, std::int64_t t_ns) {
        exporter->record(RecordType::DeviceToHost, piece, t_ns);
      });
    });
  }
  if (!exporter->finish()) throw std::runtime_error("writing " + out + " failed: " + exporter->error());
}

int run_decode(std::span<const std::string> raw) {
  const Arguments args(raw,
                       with_mcap_value_options({"model", "format", "filter", "distance-scale", "mcap", "conventions"}),
                       with_mcap_flags({"force"}), /*max_positionals=*/1);
  const std::string path = args.single_positional("FILE (or - for standard input)");
  RawInput input(path, "ydscope-cli decode");
  // A .ydrec recording (by its magic) names its model; raw bytes need --model.
  const auto scale_option = args.number("distance-scale", kMinDistanceScale, kMaxDistanceScale);
  const auto recording = path != "-" && is_recording_file(path)
                             ? std::optional(recording_plan_or_throw(path, RecordingUse::Decode, args.value("model"),
                                                                     scale_option, reading_option(args)))
                             : std::nullopt;
  const std::string model = recording ? "" : args.required("model");
  const ModelProfile* profile = recording ? recording->profile : find_decodable_profile(model);
  if (!profile)
    throw UsageError("unknown model '" + model + "'; valid models are " + std::string(model_names()) +
                     ", and X4 or X2 to decode their bytes");
  const auto mcap = args.value("mcap");
  if (mcap) refuse_to_overwrite(*mcap, args, "--mcap");
  if (!mcap && (args.value("compression") || args.value("frame-id") || args.value("parent-frame") ||
                args.has("no-link-bytes") || args.has("force")))
    throw UsageError("--compression, --frame-id, --parent-frame, --no-link-bytes and --force go with --mcap OUT.mcap");
  if (mcap && !input.regular())  // it is read twice
    throw UsageError("--mcap needs a FILE, not standard input, a FIFO or a device");
  const LapFormat format = parse_lap_format(args.value("format"), mcap ? LapFormat::Summary : LapFormat::Jsonl);
  const InterferenceFilter filter = args.value("filter") ? parse_filter(*args.value("filter")) : InterferenceFilter{};
  if (recording && recording->several_sources()) {
    if (mcap)
      throw UsageError(path + " holds several lidars; make their MCAP with ydscope-cli export " + path + " --mcap " +
                       *mcap);
    print_recording_warnings("ydscope-cli decode", recording->warnings());
    const std::atomic<bool> never{false};
    print_source_laps(path, *recording, format, Pacing{}, filter, never);
    return kExitOk;
  }
  const auto scale =
      recording ? recording_distance_scale(scale_option, args.value("model").has_value(), recording->summary.metadata)
                : scale_option;

  // Raw bytes are a real unit's: read them as the field does unless told otherwise. A recording is
  // read as it was made unless told otherwise (plan_recording chose its conventions).
  const std::optional<Reading> reading =
      recording ? reading_option(args) : reading_option(args).value_or(Reading::Field);
  const UnitConventions& conventions =
      recording ? *recording->conventions : conventions_for(*profile, std::nullopt, *reading);
  ScanDecoder decoder(*profile, conventions, scale);
  JsonOut out(stdout);
  LapPrinter printer(out, format, profile->ct_carries_info);
  Lap filtered;
  const auto on_lap = [&](const Lap& lap) {
    if (!filter.any()) return printer.print(lap);
    filtered = lap;
    filter_interference(filtered, filter);
    printer.print(filtered);
  };
  const auto feed = [&](std::span<const std::uint8_t> chunk, std::int64_t t_ns) { decoder.feed(chunk, t_ns, on_lap); };
  if (recording) {
    print_recording_warnings("ydscope-cli decode", recording->warnings());
    read_recording_device_bytes(path, feed);
  } else {
    LineRateClock clock(profile->default_baud);
    input.read([&](std::span<const std::uint8_t> chunk) {
      clock.split(chunk, feed);
      if (const DecoderCounters seen = decoder.counters(); seen.packets == 0 && seen.bytes >= kNoPacketLimit)
        throw std::runtime_error((path == "-" ? std::string("standard input") : path) + " gave " +
                                 std::to_string(seen.bytes >> 20) + " MiB without one valid " +
                                 std::string(profile->name) + " scan packet, so decode gave up on it; check that " +
                                 "it holds the bytes of a lidar's port, and the model (--model)");
    });
  }
  decoder.finish(on_lap);
  if (printer.wants_summary())
    write_summary(out, decoder.counters(), recording ? recording->summary.metadata.start_wall_time : std::nullopt);
  out.flush();
  say_why_no_lap("ydscope-cli decode", profile->name, decoder.counters());
  if (mcap) write_mcap(args, path, recording.has_value(), *profile, scale, reading);
  if (std::fflush(stdout) != 0)
    throw std::runtime_error("writing the output failed: " + std::string(std::strerror(errno)));
  return kExitOk;
}

const RegisterCliCommand decode_command{
    {"decode", "decode raw lidar bytes into laps (JSON lines or a summary)", kDecodeHelp, &run_decode}};

}  // namespace
}  // namespace ydscope::cli
