// Soak: a virtual G6 streaming 50x faster than real time through a Session for 10 minutes (the
// serial code path, on a pseudo-terminal), to show that nothing accumulates: resident memory stays
// flat, the counters that should not move (queue drops, reconnects) do not, and every lap the
// device closed reaches the queue's consumer, in order, unless the line lost bytes of it.
// At 50x the pty's buffer (about 20 kB) holds only about 20 ms of stream, so a machine that stalls
// its threads that long loses bytes at the line, as a real UART overruns; the virtual lidar counts
// the laps that lost bytes so, a sleeping probe thread measures how late the machine woke it, and
// /proc/stat how much time the hypervisor took (steal). Checksum errors, resync bytes and lost laps
// must stay within the laps the line overran.
// Prints one line every --every seconds and a verdict; exit 1 if a check failed.
// Not a Google Benchmark and not run by ctest.
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include "bench_options.h"
#include "core/link/serial_link.h"
#include "core/session/session.h"
#include "core/sim/sim_server.h"
#include "process_probe.h"

using namespace ydscope;
using namespace std::chrono_literals;

namespace {

// What a Linux pty takes before a writer's bytes overrun (measured: 20 480 bytes, Linux 6.18).
constexpr double kPtyBufferBytes = 20480;

struct Args {
  double minutes = 10;
  double scale = 50;
  std::string model = "G6";
  double every_s = 30;
};

Args parse(int argc, char** argv) {
  Args args;
  bench::BenchOptions options("bench_soak", "a virtual lidar through a Session, faster than real time, for minutes");
  options.add("--minutes", args.minutes, "how long to run")
      .add("--scale", args.scale, "how many times faster than real time the device runs")
      .add("--model", args.model, "G1, G6 or a TG model")
      .add("--every", args.every_s, "seconds between lines");
  options.parse(argc, argv);
  if (!(args.minutes > 0) || !(args.scale >= 1) || !(args.every_s > 0))
    options.fail("needs --minutes and --every above 0 and --scale of at least 1");
  if (!find_profile(args.model)) options.fail("does not know the model '" + args.model + "'");
  return args;
}

// Time all CPUs spent stolen by the hypervisor, in ms (/proc/stat's eighth field, in ticks).
double steal_ms() {
  std::ifstream stat("/proc/stat");
  std::string cpu;
  unsigned long long user, nice, system, idle, iowait, irq, softirq, steal = 0;
  stat >> cpu >> user >> nice >> system >> idle >> iowait >> irq >> softirq >> steal;
  return 1000.0 * static_cast<double>(steal) / static_cast<double>(sysconf(_SC_CLK_TCK));
}

// A thread that sleeps 1 ms at a time and keeps the worst lateness of its wake-ups: how long the
// machine kept a ready thread off the CPU, as it may keep the I/O thread or the virtual lidar's.
class StallProbe {
 public:
  StallProbe()
      : thread_([this] {
          while (!done_.load()) {
            const auto due = std::chrono::steady_clock::now() + 1ms;
            std::this_thread::sleep_until(due);
            const auto late_us =
                std::chrono::duration_cast<std::chrono::microseconds>(std::chrono::steady_clock::now() - due).count();
            std::int64_t worst = worst_us_.load();
            while (late_us > worst && !worst_us_.compare_exchange_weak(worst, late_us)) {
            }
          }
        }) {}
  ~StallProbe() {
    done_ = true;
    thread_.join();
  }
  // The worst lateness since the last call, in ms.
  double take_worst_ms() { return static_cast<double>(worst_us_.exchange(0)) / 1000.0; }

 private:
  std::atomic<bool> done_{false};
  std::atomic<std::int64_t> worst_us_{0};
  std::thread thread_;
};

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
  std::printf("%7s %8s %9s %9s %7s %7s %7s %6s %9s %8s %5s %6s %8s %8s\n", "t_s", "rss_kib", "laps", "dev_zeros",
              "cs_err", "resync", "q_drops", "reconn", "unheard", "overrun", "gaps", "MB/s", "stall_ms", "steal_ms");
  const auto t0 = std::chrono::steady_clock::now();
  const auto end = t0 + std::chrono::duration<double>(args.minutes * 60);
  long rss_first = -1, rss_max = 0, rss_last = 0;
  SessionSnapshot s;
  SimCounters c;
  std::uint64_t last_bytes = 0;
  auto last_t = t0;
  StallProbe stalls;
  double last_steal = steal_ms(), worst_stall = 0;
  for (auto next = t0 + std::chrono::duration<double>(args.every_s);;
       next += std::chrono::duration<double>(args.every_s)) {
    std::this_thread::sleep_until(std::min(next, end));
    const auto now = std::chrono::steady_clock::now();
    s = session.snapshot();
    c = sim.counters();
    const long rss = bench::resident_kib(::getpid());
    if (rss_first < 0) rss_first = rss;  // after the first interval: buffers are warm
    rss_max = std::max(rss_max, rss);
    rss_last = rss;
    const double dt = std::chrono::duration<double>(now - last_t).count();
    const double mbps = static_cast<double>(s.counters.bytes_received - last_bytes) / dt / 1e6;
    last_bytes = s.counters.bytes_received;
    last_t = now;
    const double stall = stalls.take_worst_ms(), steal = steal_ms();
    worst_stall = std::max(worst_stall, stall);
    std::printf(
        "%7.0f %8ld %9llu %9llu %7llu %7llu %7llu %6llu %9llu %8llu %5llu %6.2f %8.1f %8.0f\n",
        std::chrono::duration<double>(now - t0).count(), rss, static_cast<unsigned long long>(laps.load()),
        static_cast<unsigned long long>(c.server.zero_packets_written),
        static_cast<unsigned long long>(s.counters.checksum_errors),
        static_cast<unsigned long long>(s.counters.resync_bytes), static_cast<unsigned long long>(s.queue_dropped),
        static_cast<unsigned long long>(s.counters.reconnects), static_cast<unsigned long long>(c.server.bytes_unheard),
        static_cast<unsigned long long>(c.server.laps_overrun), static_cast<unsigned long long>(index_gaps.load()),
        mbps, stall, steal - last_steal);
    last_steal = steal;
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
  const std::uint64_t overrun = c.server.laps_overrun;
  const double stream_bytes_per_s = static_cast<double>(s.counters.bytes_received) /
                                    std::max(1.0, std::chrono::duration<double>(last_t - t0).count());
  std::printf("the line: %llu bytes overran in %llu laps; the longest stall of a sleeping thread %.1f ms\n",
              static_cast<unsigned long long>(c.server.bytes_unheard), static_cast<unsigned long long>(overrun),
              worst_stall);
  check(rss_last - rss_first <= 1024, "resident memory flat (within 1 MiB of the first interval's)");
  check(s.queue_dropped == 0, "no queue drops");
  check(s.counters.reconnects == 0 && s.counters.refused_commands == 0, "no reconnects, no refused commands");
  check(index_gaps.load() == 0 && laps.load() == s.counters.laps, "the consumer got every lap, in order");
  // A lap that lost bytes at the line may come as a broken packet or two and a resync, or merge
  // with its neighbour; none of that may happen anywhere else.
  check(lost <= overrun + 1, "no lap lost but those the line overran (one may be cut by the stop)");
  check(s.counters.checksum_errors <= 2 * overrun, "checksum errors only where the line overran (two at most each)");
  check(resync_before_stop == s.counters.resync_bytes || s.counters.resync_bytes < 64 || overrun > 0,
        "resync bytes do not grow unless the line overran");
  if (overrun > 0)
    std::printf(
        "note: the machine kept threads off the CPU for up to %.1f ms; at %.0fx the pty holds about %.0f ms of "
        "stream, so bytes overran at the line, not in the session; run again on a quieter machine or with a "
        "smaller --scale to see none\n",
        worst_stall, args.scale, kPtyBufferBytes / stream_bytes_per_s * 1e3);
  return ok ? 0 : 1;
}
