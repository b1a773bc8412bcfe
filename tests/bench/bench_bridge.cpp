// Measures `ydscope-cli serve` on a virtual G6 with N WebSocket clients, the way issue 12 asks
// (not a Google Benchmark: one timed run, numbers on stdout):
//   - the serve process's CPU (utime + stime from /proc/PID/stat) over --seconds, after --warmup,
//     as a percentage of one core; serve decodes, encodes /scan /points /diagnostics and the link
//     bytes, and sends them to the clients, so --clients 0 is the baseline without the bridge;
//   - lap-to-client latency: from the virtual lidar's write() of the zero packet that closes a lap
//     (`ydscope-cli sim --zero-log`, CLOCK_MONOTONIC) to a client's read of that lap's /scan
//     message (CLOCK_MONOTONIC), paired with the newest zero packet written before the read, so
//     valid while the latency is below one lap (125 ms at 8 Hz; a longer one is reported).
// Each client is a Boost.Beast client (tests/bridge/ws_test_client.h) subscribed to /scan and
// /points, as Foxglove's 3D panel would be, on 127.0.0.1. The sim runs in its own process, so its
// CPU is not counted. Not run by ctest. Usage:
//   bench_bridge --cli PATH [--clients 1] [--seconds 30] [--warmup 3]
#include <signal.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "bench_options.h"
#include "process_probe.h"
#include "support/ws_test_client.h"

namespace {

using namespace std::chrono_literals;
namespace fs = std::filesystem;
namespace bench = ydscope::bench;

struct Args {
  std::string cli;
  int clients = 1;
  double seconds = 30;
  double warmup = 3;
};

double percentile(std::vector<double> values, double p) {
  if (values.empty()) return 0;
  std::sort(values.begin(), values.end());
  const auto index = static_cast<std::size_t>(p * static_cast<double>(values.size() - 1) + 0.5);
  return values[std::min(index, values.size() - 1)];
}

}  // namespace

int main(int argc, char** argv) {
  Args args;
  bench::BenchOptions options("bench_bridge", "one virtual lidar through `serve` to Foxglove clients");
  options.add("--cli", args.cli, "path of ydscope-cli")
      .add("--clients", args.clients, "Foxglove clients subscribed to every topic")
      .add("--seconds", args.seconds, "how long to measure")
      .add("--warmup", args.warmup, "seconds before measuring");
  options.parse(argc, argv);
  if (args.cli.empty()) options.fail("needs --cli PATH/ydscope-cli");
  if (args.clients < 0 || !(args.seconds > 0) || args.warmup < 0)
    options.fail("needs --clients of 0 or more, --seconds above 0 and --warmup of 0 or more");

  const fs::path dir = fs::temp_directory_path() / ("bench_bridge." + std::to_string(getpid()));
  fs::create_directories(dir);
  const std::string link = (dir / "lidar").string();
  const std::string zero_log = (dir / "zero.log").string();
  const pid_t sim = bench::spawn({args.cli, "sim", "--model", "G6", "--pty", link, "--zero-log", zero_log},
                                 /*quiet=*/true);  // its "ready" line
  for (int i = 0; i < 100 && !fs::exists(link); ++i) std::this_thread::sleep_for(50ms);
  int pipe_fds[2];
  if (sim <= 0 || !fs::exists(link) || pipe(pipe_fds) != 0) {
    std::fprintf(stderr, "bench_bridge: the virtual lidar did not start\n");
    bench::stop(sim);
    return 1;
  }
  const pid_t serve = bench::spawn({args.cli, "serve", "--port", link, "--listen", "127.0.0.1:0"}, false, pipe_fds[1]);
  close(pipe_fds[1]);
  std::string banner;
  char c = 0;
  while (read(pipe_fds[0], &c, 1) == 1 && c != '\n') banner += c;
  unsigned port = 0;
  if (serve <= 0 || std::sscanf(banner.c_str(), "serving ws://127.0.0.1:%u", &port) != 1) {
    std::fprintf(stderr, "bench_bridge: serve did not start (it said '%s')\n", banner.c_str());
    bench::stop(serve);
    bench::stop(sim);
    return 1;
  }

  std::atomic<bool> measuring{false};
  std::atomic<bool> done{false};
  std::mutex mutex;
  std::vector<std::int64_t> scan_reads;  // CLOCK_MONOTONIC of each /scan read while measuring
  std::atomic<int> failed_clients{0};
  std::vector<std::thread> clients;
  for (int i = 0; i < args.clients; ++i) {
    clients.emplace_back([&] {
      try {
        ydscope::test::WsTestClient client(static_cast<std::uint16_t>(port));
        if (!client.subscribe(1, "/scan") || !client.subscribe(2, "/points")) throw std::runtime_error("subscribe");
        while (!done.load()) {
          const auto message = client.read(5s);
          const std::int64_t now = ydscope::bench::monotonic_now_ns();
          if (!message) throw std::runtime_error("read");
          if (!message->text && message->subscription == 1 && measuring.load()) {
            std::lock_guard lock(mutex);
            scan_reads.push_back(now);
          }
        }
        client.close_handshake(2s);
      } catch (const std::exception&) {
        ++failed_clients;
      }
    });
  }

  std::this_thread::sleep_for(std::chrono::duration<double>(args.warmup));
  const double cpu0 = bench::cpu_seconds(serve);
  const auto wall0 = std::chrono::steady_clock::now();
  const std::int64_t mono0 = ydscope::bench::monotonic_now_ns();
  measuring.store(true);
  std::this_thread::sleep_for(std::chrono::duration<double>(args.seconds));
  measuring.store(false);
  const std::int64_t mono1 = ydscope::bench::monotonic_now_ns();
  const double cpu1 = bench::cpu_seconds(serve);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  done.store(true);
  for (auto& t : clients) t.join();
  bench::stop(serve);
  bench::stop(sim);
  close(pipe_fds[0]);

  std::vector<std::int64_t> zeros;
  {
    std::ifstream in(zero_log);
    std::uint64_t index = 0;
    std::int64_t ns = 0;
    while (in >> index >> ns) zeros.push_back(ns);
  }
  fs::remove_all(dir);
  std::vector<double> latency_ms;
  int beyond_a_lap = 0;
  for (const std::int64_t read_ns : scan_reads) {
    const auto newest = std::upper_bound(zeros.begin(), zeros.end(), read_ns);
    if (newest == zeros.begin()) continue;
    const double ms = static_cast<double>(read_ns - *(newest - 1)) / 1e6;
    latency_ms.push_back(ms);
    if (ms > 100) ++beyond_a_lap;
  }
  const auto zeros_in_window =
      std::count_if(zeros.begin(), zeros.end(), [&](std::int64_t z) { return z >= mono0 && z < mono1; });
  std::printf(
      "clients %d: serve CPU %.1f%% of one core over %.1f s; /scan reads %zu (laps closed by the device: %ld x %d "
      "clients); lap-to-client latency median %.2f ms, p99 %.2f ms, max %.2f ms%s\n",
      args.clients, 100.0 * (cpu1 - cpu0) / wall, wall, scan_reads.size(), static_cast<long>(zeros_in_window),
      args.clients, percentile(latency_ms, 0.5), percentile(latency_ms, 0.99), percentile(latency_ms, 1.0),
      failed_clients ? " (some clients failed)" : "");
  if (beyond_a_lap) std::printf("warning: %d reads came over 100 ms after the newest zero packet\n", beyond_a_lap);
  return failed_clients ? 1 : 0;
}
