// Measures the live session the way issue 4 asks, on a pseudo-terminal with the virtual lidar
// writing a real-time G6 stream (not a Google Benchmark: one timed run, numbers on stdout):
//   - the I/O thread's CPU time over the run (its thread CPU clock, read from the main thread),
//   - the latency from the write() that carried a closing zero packet's last byte (the virtual
//     lidar stamps CLOCK_MONOTONIC right after it returns) to that lap being in the session's lap ring
//     (CLOCK_MONOTONIC in the session's wake callback, which runs right after the push),
//   - optionally the peak RSS of `ydscope-cli scan` on the same kind of stream (--cli PATH).
// Not run by ctest. Usage: bench_session_latency [--seconds S] [--model G6] [--cli PATH]
#include <fcntl.h>
#include <pthread.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "bench_options.h"
#include "core/session/session.h"
#include "core/session/session_io.h"
#include "process_probe.h"
#include "core/sim/sim_server.h"

using namespace ydscope;
using namespace std::chrono_literals;

namespace {

constexpr std::size_t kMaxLaps = 100000;

struct Args {
  double seconds = 20;
  std::string model = "G6";
  std::string cli;
};

Args parse(int argc, char** argv) {
  Args args;
  bench::BenchOptions options("bench_session_latency", "the I/O thread's CPU and the lap latency on a live stream");
  options.add("--seconds", args.seconds, "how long to measure")
      .add("--model", args.model, "G1, G6 or a TG model")
      .add("--cli", args.cli, "path of ydscope-cli, to measure `scan`'s peak memory too");
  options.parse(argc, argv);
  if (!(args.seconds > 0)) options.fail("needs --seconds above 0");
  if (!find_profile(args.model)) options.fail("does not know the model '" + args.model + "'");
  return args;
}

double percentile(std::vector<double> values, double p) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  const auto rank = static_cast<std::size_t>(p / 100.0 * static_cast<double>(values.size() - 1) + 0.5);
  return values[std::min(rank, values.size() - 1)];
}

// Peak RSS of one `ydscope-cli scan` run (KiB), from wait4's rusage of that child alone.
long cli_scan_max_rss_kib(const std::string& cli, const std::string& port, const std::string& model, int laps) {
  const pid_t child = fork();
  if (child == 0) {
    const std::string laps_text = std::to_string(laps);
    const int devnull = open("/dev/null", O_WRONLY);
    if (devnull >= 0) dup2(devnull, STDOUT_FILENO);
    execl(cli.c_str(), cli.c_str(), "scan", "--port", port.c_str(), "--model", model.c_str(), "--laps",
          laps_text.c_str(), "--format", "jsonl", static_cast<char*>(nullptr));
    _exit(127);
  }
  int status = 0;
  rusage usage{};
  if (child < 0 || wait4(child, &status, 0, &usage) < 0) return -1;
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) return -1;
  return usage.ru_maxrss;
}

}  // namespace

int main(int argc, char** argv) {
  const Args args = parse(argc, argv);
  const ModelProfile* profile = find_profile(args.model);
  std::string dir = (std::filesystem::temp_directory_path() / "ydscope-bench-XXXXXX").string();
  if (!mkdtemp(dir.data())) return 1;
  const std::string port = dir + "/lidar";

  std::mutex zero_mutex;
  std::vector<std::int64_t> zero_written;  // by the virtual lidar's zero index
  zero_written.reserve(kMaxLaps);
  SimServerOptions options;
  options.device.model = profile->model;
  options.device.scene = "room";
  options.pty_link = port;
  options.on_zero_packet_written = [&](std::int64_t ns, std::uint64_t index) {
    std::lock_guard lock(zero_mutex);
    if (zero_written.size() <= index) zero_written.resize(index + 1, 0);
    zero_written[index] = ns;
  };
  SimServer sim(options);
  sim.start();

  // Written only by the I/O thread inside the wake callback; read after the session is gone.
  static std::int64_t queued_ns[kMaxLaps];
  std::atomic<std::size_t> queued{0};
  std::atomic<bool> have_thread{false};
  pthread_t io_thread{};
  static std::int64_t closing_rx_ns[kMaxLaps];
  std::size_t popped = 0;

  double cpu_seconds = 0, wall_seconds = 0;
  std::uint64_t reads_in_window = 0;
  SessionSnapshot end;
  {
    Session session(64, [&] {
      const std::int64_t now = link_clock_ns();
      const std::size_t n = queued.load(std::memory_order_relaxed);
      if (n < kMaxLaps) queued_ns[n] = now;
      queued.store(n + 1, std::memory_order_release);
      if (!have_thread.load(std::memory_order_relaxed)) {
        io_thread = pthread_self();
        have_thread.store(true, std::memory_order_release);
      }
    });
    // The consumer pops in push order (no drops: the ring never fills), so its i-th lap is the one
    // whose push the wake callback stamped as queued_ns[i]; its last_rx_ns finds the zero packet.
    // Stops and joins when it goes out of scope, before the session it reads (declared earlier).
    std::jthread consumer([&](std::stop_token stop) {
      Lap lap;
      while (!stop.stop_requested()) {
        while (session.laps().try_pop(lap)) {
          if (popped < kMaxLaps) closing_rx_ns[popped] = lap.last_rx_ns;
          ++popped;
        }
        std::this_thread::sleep_for(5ms);
      }
    });
    SessionConfig config;
    config.address = port;
    config.model = profile->model;
    session.connect(config);
    const auto s = session.wait_until([](const SessionSnapshot& x) { return x.state == LinkState::Scanning; }, 20s);
    if (s.state != LinkState::Scanning) {
      std::fprintf(stderr, "the session did not start: %s\n", describe_snapshot(s).c_str());
      return 1;
    }
    while (!have_thread.load(std::memory_order_acquire)) std::this_thread::sleep_for(1ms);
    std::this_thread::sleep_for(1s);  // past start-up
    const std::uint64_t reads0 = session.snapshot().counters.reads;
    const std::int64_t cpu0 = bench::thread_cpu_ns(io_thread);
    const std::int64_t wall0 = link_clock_ns();
    std::this_thread::sleep_for(std::chrono::duration<double>(args.seconds));
    const std::int64_t cpu1 = bench::thread_cpu_ns(io_thread);
    const std::int64_t wall1 = link_clock_ns();
    cpu_seconds = static_cast<double>(cpu1 - cpu0) * 1e-9;
    reads_in_window = session.snapshot().counters.reads - reads0;
    wall_seconds = static_cast<double>(wall1 - wall0) * 1e-9;
    end = session.snapshot();
    consumer.request_stop();
    consumer.join();
  }

  // Each lap is closed by the zero packet written nearest to the moment its closing byte was read
  // (laps are ~100 ms apart, the read follows the write by microseconds), whatever the indexes.
  std::vector<double> latency_us;
  std::size_t unmatched = 0;
  {
    std::lock_guard lock(zero_mutex);
    std::vector<std::int64_t> zeros;
    for (const auto ns : zero_written)
      if (ns != 0) zeros.push_back(ns);
    std::sort(zeros.begin(), zeros.end());
    const std::size_t laps = std::min({queued.load(), popped, kMaxLaps});
    for (std::size_t k = 0; k < laps; ++k) {
      const std::int64_t rx = closing_rx_ns[k];
      auto it = std::lower_bound(zeros.begin(), zeros.end(), rx);
      std::int64_t best = -1;
      if (it != zeros.end()) best = *it;
      if (it != zeros.begin() && (best < 0 || rx - *(it - 1) < best - rx)) best = *(it - 1);
      if (best < 0 || std::llabs(rx - best) > 10'000'000) {  // no write within 10 ms: not matched
        ++unmatched;
        continue;
      }
      latency_us.push_back(static_cast<double>(queued_ns[k] - best) * 1e-3);
    }
  }
  std::printf("model %s, %.1f s measured, %llu laps queued, %.1f laps/s, %.0f bytes/s\n", profile->name.data(),
              wall_seconds, static_cast<unsigned long long>(queued.load()), end.counters.laps_per_s,
              end.counters.bytes_per_s);
  std::printf("io thread cpu: %.4f s over %.1f s = %.3f%% of one core; %.0f reads/s, %.1f us of cpu per read\n",
              cpu_seconds, wall_seconds, 100.0 * cpu_seconds / wall_seconds,
              static_cast<double>(reads_in_window) / wall_seconds,
              reads_in_window ? cpu_seconds * 1e6 / static_cast<double>(reads_in_window) : 0.0);
  std::printf(
      "latency zero-packet write -> lap queued (us) over %zu laps: median %.1f  p90 %.1f  p99 %.1f  max %.1f  min "
      "%.1f%s\n",
      latency_us.size(), percentile(latency_us, 50), percentile(latency_us, 90), percentile(latency_us, 99),
      latency_us.empty() ? 0.0 : *std::max_element(latency_us.begin(), latency_us.end()),
      latency_us.empty() ? 0.0 : *std::min_element(latency_us.begin(), latency_us.end()), "");
  std::printf("unmatched laps %zu, checksum errors %llu, queue drops %llu, reconnects %llu, state %s\n", unmatched,
              static_cast<unsigned long long>(end.counters.checksum_errors),
              static_cast<unsigned long long>(end.queue_dropped),
              static_cast<unsigned long long>(end.counters.reconnects), describe_snapshot(end).c_str());
  if (!args.cli.empty()) {
    const long rss = cli_scan_max_rss_kib(args.cli, port, std::string(profile->name), 100);
    std::printf("ydscope-cli scan --laps 100 max RSS: %ld KiB\n", rss);
  }
  sim.stop();
  std::filesystem::remove_all(dir);
  return 0;
}
