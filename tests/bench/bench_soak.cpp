// Soak: a virtual G6 streaming 50x faster than real time through a Session for 10 minutes (the
// serial code path, on a pseudo-terminal), to show that nothing accumulates: resident memory stays
// flat, the counters that should not move (checksum errors, resync bytes, queue drops,
// reconnects, bytes the host never read) do not, and every lap the device closed reaches the
// queue's consumer, in order. No fault is injected, so no lap may be lost.
// Prints one line every --every seconds and a verdict; exit 1 if a check failed.
// Not a Google Benchmark and not run by ctest. Usage:
//   bench_soak [--minutes 10] [--scale 50] [--model G6] [--every 30]
#include <unistd.h>

#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include "core/link/serial_link.h"
#include "core/link/session.h"
#include "core/sim/sim_server.h"

using namespace ydscope;
using namespace std::chrono_literals;

namespace {

struct Args {
  double minutes = 10;
  double scale = 50;
  std::string model = "G6";
  double every_s = 30;
};

Args parse(int argc, char** argv) {
  Args args;
  for (int i = 1; i + 1 < argc; i += 2) {
    const std::string key = argv[i];
    if (key == "--minutes")
      args.minutes = std::atof(argv[i + 1]);
    else if (key == "--scale")
      args.scale = std::atof(argv[i + 1]);
    else if (key == "--model")
      args.model = argv[i + 1];
    else if (key == "--every")
      args.every_s = std::atof(argv[i + 1]);
  }
  return args;
}

long resident_kib() {
  std::ifstream statm("/proc/self/statm");
  long pages = 0, resident = 0;
  statm >> pages >> resident;
  return resident * (sysconf(_SC_PAGESIZE) / 1024);
}

// The serial port, reporting the line as `scale` times its baud: the session sizes its read holds
// by the line rate, and the virtual line really is that much faster.
class ScaledLine final : public ByteLink {
 public:
  ScaledLine(std::unique_ptr<ByteLink> inner, double scale) : inner_(std::move(inner)), scale_(scale) {}
  void async_read_some(std::span<std::uint8_t> buffer, IoHandler handler) override {
    inner_->async_read_some(buffer, std::move(handler));
  }
  void async_write(std::span<const std::uint8_t> bytes, IoHandler handler) override {
    inner_->async_write(bytes, std::move(handler));
  }
  void close() override { inner_->close(); }
  void stop_watching_input() override { inner_->stop_watching_input(); }
  double line_bytes_per_s() const override { return inner_->line_bytes_per_s() * scale_; }
  bool set_baud(std::uint32_t baud, std::string& error) override { return inner_->set_baud(baud, error); }
  bool accepts_commands() const override { return true; }
  std::string describe() const override { return inner_->describe(); }

 private:
  std::unique_ptr<ByteLink> inner_;
  double scale_;
};

}  // namespace

int main(int argc, char** argv) {
  const Args args = parse(argc, argv);
  const ModelProfile* profile = find_profile(args.model);
  if (!profile) {
    std::fprintf(stderr, "bench_soak: unknown model %s\n", args.model.c_str());
    return 2;
  }
  const auto dir = std::filesystem::temp_directory_path() / ("ydscope-soak-" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  SimServerOptions sim_options;
  sim_options.device.model = profile->model;
  sim_options.device.scene = "room";
  sim_options.pty_link = (dir / "lidar").string();
  sim_options.time_scale = args.scale;
  SimServer sim(sim_options);
  sim.start();

  Session session(256);
  SessionConfig config;
  config.address = sim_options.pty_link;
  config.model = profile->model;
  config.scan = true;
  config.reconnect = false;  // a soak without faults must never need one
  const std::string port = config.address;
  const double scale = args.scale;
  config.open_link = [port, scale](boost::asio::io_context& io, std::uint32_t baud,
                                   std::string& error) -> std::unique_ptr<ByteLink> {
    auto serial = SerialLink::open(io, port, baud, error);
    if (!serial) return nullptr;
    return std::make_unique<ScaledLine>(std::move(serial), scale);
  };
  session.connect(config);

  // The consumer: pops every lap and checks that the indices run on without a gap.
  std::atomic<bool> done{false};
  std::atomic<std::uint64_t> laps{0}, index_gaps{0}, points{0};
  std::thread consumer([&] {
    Lap lap;
    std::uint64_t expected = 0;
    while (!done.load()) {
      if (!session.laps().try_pop(lap)) {
        std::this_thread::sleep_for(1ms);
        continue;
      }
      if (lap.index != expected) index_gaps.fetch_add(1);
      expected = lap.index + 1;
      points.fetch_add(lap.points.size());
      laps.fetch_add(1);
    }
  });

  const SessionSnapshot started =
      session.wait_until([](const SessionSnapshot& s) { return s.state == LinkState::Scanning; }, 20s);
  if (started.state != LinkState::Scanning) {
    std::fprintf(stderr, "bench_soak: the session never scanned: %s\n", describe_snapshot(started).c_str());
    done = true;
    consumer.join();
    return 1;
  }
  std::printf("soak: %s at %.0fx real time for %.1f min (device time %.1f h)\n", args.model.c_str(), args.scale,
              args.minutes, args.minutes * args.scale / 60);
  std::printf("%7s %9s %9s %10s %8s %8s %8s %8s %8s %9s %9s\n", "t_s", "rss_kib", "laps", "dev_zeros", "cs_err",
              "resync", "q_drops", "reconn", "unheard", "gaps", "MB/s");
  const auto t0 = std::chrono::steady_clock::now();
  const auto end = t0 + std::chrono::duration<double>(args.minutes * 60);
  long rss_first = -1, rss_max = 0, rss_last = 0;
  SessionSnapshot s;
  SimCounters c;
  std::uint64_t last_bytes = 0;
  auto last_t = t0;
  for (auto next = t0 + std::chrono::duration<double>(args.every_s);;
       next += std::chrono::duration<double>(args.every_s)) {
    std::this_thread::sleep_until(std::min(next, end));
    const auto now = std::chrono::steady_clock::now();
    s = session.snapshot();
    c = sim.counters();
    const long rss = resident_kib();
    if (rss_first < 0) rss_first = rss;  // after the first interval: buffers are warm
    rss_max = std::max(rss_max, rss);
    rss_last = rss;
    const double dt = std::chrono::duration<double>(now - last_t).count();
    const double mbps = static_cast<double>(s.counters.bytes_received - last_bytes) / dt / 1e6;
    last_bytes = s.counters.bytes_received;
    last_t = now;
    std::printf(
        "%7.0f %9ld %9llu %10llu %8llu %8llu %8llu %8llu %8llu %9llu %9.2f\n",
        std::chrono::duration<double>(now - t0).count(), rss, static_cast<unsigned long long>(laps.load()),
        static_cast<unsigned long long>(c.server.zero_packets_written),
        static_cast<unsigned long long>(s.counters.checksum_errors),
        static_cast<unsigned long long>(s.counters.resync_bytes), static_cast<unsigned long long>(s.queue_dropped),
        static_cast<unsigned long long>(s.counters.reconnects), static_cast<unsigned long long>(c.server.bytes_unheard),
        static_cast<unsigned long long>(index_gaps.load()), mbps);
    std::fflush(stdout);
    if (now >= end || s.state != LinkState::Scanning) break;
  }
  // Stop the device first, then let the last laps through, and count what the device closed.
  const std::uint64_t resync_before_stop = s.counters.resync_bytes;
  session.disconnect();
  session.wait_until(
      [](const SessionSnapshot& x) { return x.state == LinkState::Idle || x.state == LinkState::Failed; }, 5s);
  std::this_thread::sleep_for(100ms);  // the consumer drains what is left (not a synchronisation of the checks)
  done = true;
  consumer.join();
  s = session.snapshot();
  c = sim.counters();
  sim.stop();
  std::filesystem::remove_all(dir);

  // A lap is closed by the zero packet after it: the device's zero packets minus the first
  // (which opens lap 0) bound the laps a host could get; one more may be cut by the stop.
  const std::uint64_t closable = c.server.zero_packets_written > 0 ? c.server.zero_packets_written - 1 : 0;
  const std::uint64_t lost = closable > s.counters.laps ? closable - s.counters.laps : 0;
  bool ok = true;
  const auto check = [&](bool good, const char* what) {
    std::printf("%s %s\n", good ? "ok  " : "FAIL", what);
    ok = ok && good;
  };
  std::printf("resident memory: %ld KiB after the first interval, %ld KiB at the end, %ld KiB at most\n", rss_first,
              rss_last, rss_max);
  std::printf("laps: device closed %llu, session assembled %llu, consumer took %llu (%llu points); lost %llu\n",
              static_cast<unsigned long long>(closable), static_cast<unsigned long long>(s.counters.laps),
              static_cast<unsigned long long>(laps.load()), static_cast<unsigned long long>(points.load()),
              static_cast<unsigned long long>(lost));
  check(rss_last - rss_first <= 1024, "resident memory flat (within 1 MiB of the first interval's)");
  check(s.counters.checksum_errors == 0, "no checksum errors");
  check(resync_before_stop == s.counters.resync_bytes || s.counters.resync_bytes < 64, "resync bytes do not grow");
  check(s.queue_dropped == 0, "no queue drops");
  check(s.counters.reconnects == 0 && s.counters.refused_commands == 0, "no reconnects, no refused commands");
  check(c.server.bytes_unheard == 0, "the host read every byte the device sent");
  check(index_gaps.load() == 0 && laps.load() == s.counters.laps, "the consumer got every lap, in order");
  check(lost <= 1, "no lap lost (one may be cut by the stop)");
  return ok ? 0 : 1;
}
