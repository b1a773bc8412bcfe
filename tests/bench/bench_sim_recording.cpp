// Writes a long .ydrec of the virtual lidar scanning as fast as the CPU allows (device time, no
// waiting), as `ydscope-cli record` would have written it from a live session: the host's A5 60,
// then the device bytes in 5 ms reads. The input for timing `ydscope-cli export --mcap` on an
// hour of G6 (README, "MCAP and the Foxglove bridge"); the file is large, keep it out of the repo.
// Not a Google Benchmark and not run by ctest. Usage:
//   bench_sim_recording OUT.ydrec [--minutes 60] [--model G6] [--scene demo]
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "core/protocol/model_profile.h"
#include "core/record/recording_writer.h"
#include "core/sim/virtual_lidar.h"

using namespace ydscope;

int main(int argc, char** argv) {
  if (argc < 2 || argv[1][0] == '-') {
    std::fprintf(stderr, "usage: bench_sim_recording OUT.ydrec [--minutes 60] [--model G6] [--scene demo]\n");
    return 2;
  }
  const std::string out = argv[1];
  double minutes = 60;
  VirtualLidarConfig config;
  config.model = Model::G6;
  for (int i = 2; i + 1 < argc; i += 2) {
    const std::string key = argv[i];
    if (key == "--minutes")
      minutes = std::atof(argv[i + 1]);
    else if (key == "--scene")
      config.scene = argv[i + 1];
    else if (key == "--model") {
      const ModelProfile* profile = find_profile(argv[i + 1]);
      if (!profile) {
        std::fprintf(stderr, "bench_sim_recording: unknown model '%s' (%s)\n", argv[i + 1],
                     std::string(model_names()).c_str());
        return 2;
      }
      config.model = profile->model;
    }
  }

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
