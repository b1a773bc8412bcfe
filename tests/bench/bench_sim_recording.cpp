// Writes a long .ydrec of the virtual lidar scanning as fast as the CPU allows (device time, no
// waiting), as `ydscope-cli record` would have written it from a live session: the host's A5 60,
// then the device bytes in 5 ms reads. The input for timing `ydscope-cli export --mcap` on an
// hour of G6 (docs/performance.md, "MCAP and the Foxglove bridge"); the file is large, keep it out
// of the repo.
// Not a Google Benchmark and not run by ctest. Usage:
//   bench_sim_recording --out OUT.ydrec [--minutes 60] [--model G6] [--scene demo]
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "bench_options.h"
#include "core/protocol/model_profile.h"
#include "core/record/recording_writer.h"
#include "core/sim/virtual_lidar.h"

using namespace ydscope;

int main(int argc, char** argv) {
  std::string out;
  double minutes = 60;
  std::string model = "G6";
  VirtualLidarConfig config;
  bench::BenchOptions options("bench_sim_recording",
                              "a long recording of the virtual lidar, made faster than real time");
  options.add("--out", out, "the .ydrec file to write")
      .add("--minutes", minutes, "device minutes to record")
      .add("--model", model, "G1, G6 or a TG model")
      .add("--scene", config.scene, "the virtual lidar's scene");
  options.parse(argc, argv);
  if (out.empty()) options.fail("needs --out FILE.ydrec");
  if (!(minutes > 0)) options.fail("needs --minutes above 0");
  const ModelProfile* chosen = find_profile(model);
  if (!chosen) options.fail("does not know the model '" + model + "' (" + std::string(model_names()) + ")");
  config.model = chosen->model;

  VirtualLidar lidar(config);
  const ModelProfile& profile = profile_for(config.model);
  RecordingMetadata metadata;
  metadata.model = std::string(profile.name);
  metadata.baud = profile.default_baud;
  metadata.port = "virtual " + std::string(profile.name) + " (bench_sim_recording)";
  std::string error;
  auto writer = RecordingWriter::create(out, metadata, 0, error);
  if (!writer) {
    std::fprintf(stderr, "bench_sim_recording: %s\n", error.c_str());
    return 1;
  }
  constexpr std::int64_t kReadNs = 5'000'000;
  const std::vector<std::uint8_t> start_scan = {0xA5, 0x60};
  writer->append(Direction::HostToDevice, start_scan, 0);
  lidar.receive(start_scan, 0);
  const auto end_ns = static_cast<std::int64_t>(minutes * 60e9);
  std::vector<std::uint8_t> bytes;
  for (std::int64_t now = kReadNs; now <= end_ns; now += kReadNs) {
    bytes.clear();
    lidar.produce(now, bytes);
    if (!writer->append(Direction::DeviceToHost, bytes, now)) break;
  }
  if (!writer->close()) {
    std::fprintf(stderr, "bench_sim_recording: writing %s failed: %s\n", out.c_str(), writer->error().c_str());
    return 1;
  }
  std::printf("%s: %.1f min of %s, %llu device bytes, %llu laps' zero packets, %llu bytes on disk\n", out.c_str(),
              minutes, std::string(profile.name).c_str(),
              static_cast<unsigned long long>(writer->bytes(Direction::DeviceToHost)),
              static_cast<unsigned long long>(lidar.counters().zero_packets),
              static_cast<unsigned long long>(writer->file_size()));
  return 0;
}
