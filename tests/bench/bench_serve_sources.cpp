// Measures `ydscope-cli serve` with several virtual G6 at once, the way issue 13 asks (not a Google
// Benchmark: one timed run, numbers on stdout):
//   - the serve process's CPU over --seconds after --warmup, in % of one core, and the part of it
//     spent in the sessions' I/O threads (named ydscope-io);
//   - laps lost on the way to a client: each virtual lidar logs its zero packets (`sim
//     --zero-log`), one per lap it closed; a Foxglove client (tests/bridge/ws_test_client.h)
//     subscribed to every lidar's /NAME/scan counts what arrives in the same window. A lap at
//     either edge of the window may fall on the other side, so up to one per lidar is not a loss.
// Each virtual lidar runs in its own process on its own pseudo-terminal, so their CPU is not
// counted. Not run by ctest. Usage:
//   bench_serve_sources --cli PATH [--lidars 8] [--seconds 30] [--warmup 3]
#include <time.h>
#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
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
  int lidars = 8;
  double seconds = 30;
  double warmup = 3;
};

// The first line serve prints: "serving ws://127.0.0.1:PORT for N lidars: ...".
unsigned read_serving_port(int fd) {
  std::string banner;
  char c = 0;
  while (read(fd, &c, 1) == 1 && c != '\n') banner += c;
  unsigned port = 0;
  return std::sscanf(banner.c_str(), "serving ws://127.0.0.1:%u", &port) == 1 ? port : 0;
}

}  // namespace

int main(int argc, char** argv) {
  Args args;
  bench::BenchOptions options("bench_serve_sources", "several virtual lidars into one `serve`, and a Foxglove client");
  options.add("--cli", args.cli, "path of ydscope-cli")
      .add("--lidars", args.lidars, "virtual G6 lidars, 1 to 32")
      .add("--seconds", args.seconds, "how long to measure")
      .add("--warmup", args.warmup, "seconds before measuring");
  options.parse(argc, argv);
  if (args.cli.empty()) options.fail("needs --cli PATH/ydscope-cli");
  if (args.lidars < 1 || args.lidars > 32) options.fail("takes --lidars from 1 to 32");
  if (!(args.seconds > 0) || args.warmup < 0) options.fail("needs --seconds above 0 and --warmup of 0 or more");

  const fs::path dir = fs::temp_directory_path() / ("bench_serve_sources." + std::to_string(getpid()));
  fs::create_directories(dir);
  std::vector<pid_t> sims;
  std::vector<std::string> serve_argv{args.cli, "serve", "--listen", "127.0.0.1:0"};
  for (int i = 0; i < args.lidars; ++i) {
    const std::string link = (dir / ("g6_" + std::to_string(i))).string();
    sims.push_back(bench::spawn({args.cli, "sim", "--model", "G6", "--pty", link, "--seed", std::to_string(i + 1),
                                 "--zero-log", (dir / ("zero_" + std::to_string(i))).string()},
                                /*quiet=*/true));
    serve_argv.insert(serve_argv.end(), {"--port", link, "--name", "lidar" + std::to_string(i)});
  }
  const auto stop_all = [&] {
    for (const pid_t sim : sims) bench::stop(sim);
    fs::remove_all(dir);
  };
  for (int i = 0; i < args.lidars; ++i)
    for (int wait = 0; wait < 100 && !fs::exists(dir / ("g6_" + std::to_string(i))); ++wait)
      std::this_thread::sleep_for(50ms);

  int pipe_fds[2];
  if (pipe(pipe_fds) != 0) return 1;
  const pid_t serve = bench::spawn(serve_argv, /*quiet=*/false, pipe_fds[1]);
  close(pipe_fds[1]);
  const unsigned port = read_serving_port(pipe_fds[0]);
  close(pipe_fds[0]);
  if (serve <= 0 || port == 0) {
    std::fprintf(stderr, "bench_serve_sources: serve did not start\n");
    if (serve > 0) bench::stop(serve);
    stop_all();
    return 1;
  }

  std::atomic<bool> measuring{false};
  std::atomic<bool> done{false};
  std::atomic<bool> client_failed{false};
  std::vector<std::atomic<long>> received(static_cast<std::size_t>(args.lidars));
  std::thread client_thread([&] {
    try {
      ydscope::test::WsTestClient client(static_cast<std::uint16_t>(port));
      for (int i = 0; i < args.lidars; ++i)
        if (!client.subscribe(static_cast<std::uint32_t>(i + 1), "/lidar" + std::to_string(i) + "/scan"))
          throw std::runtime_error("subscribe");
      while (!done.load()) {
        const auto message = client.read_binary(5s);
        if (!message) throw std::runtime_error("read");
        if (measuring.load() && message->subscription >= 1 &&
            message->subscription <= static_cast<std::uint32_t>(args.lidars))
          ++received[message->subscription - 1];
      }
    } catch (const std::exception&) {
      client_failed.store(true);
    }
  });

  std::this_thread::sleep_for(std::chrono::duration<double>(args.warmup));
  const long ticks0 = bench::cpu_ticks(serve);
  const long io0 = bench::thread_ticks(serve, "ydscope-io");
  const std::int64_t from_ns = bench::monotonic_now_ns();
  measuring.store(true);
  std::this_thread::sleep_for(std::chrono::duration<double>(args.seconds));
  measuring.store(false);
  const std::int64_t to_ns = bench::monotonic_now_ns();
  const long ticks1 = bench::cpu_ticks(serve);
  const long io1 = bench::thread_ticks(serve, "ydscope-io");
  done.store(true);
  client_thread.join();
  bench::stop(serve);

  const double wall = static_cast<double>(to_ns - from_ns) / 1e9;
  const double tick = static_cast<double>(sysconf(_SC_CLK_TCK));
  long sent = 0, got = 0, lost = 0;
  for (int i = 0; i < args.lidars; ++i) {
    const long closed = bench::laps_closed(dir / ("zero_" + std::to_string(i)), from_ns, to_ns);
    sent += closed;
    got += received[static_cast<std::size_t>(i)].load();
    // One lap either side of the window is timing, not a loss.
    lost += std::max(0L, closed - received[static_cast<std::size_t>(i)].load() - 1);
  }
  stop_all();
  std::printf(
      "lidars %d (virtual G6, 8 Hz each): serve CPU %.1f%% of one core over %.1f s, of which the %d I/O "
      "threads %.1f%%; laps closed by the lidars %ld, /scan messages received %ld, laps lost %ld%s\n",
      args.lidars, 100.0 * static_cast<double>(ticks1 - ticks0) / tick / wall, wall, args.lidars,
      100.0 * static_cast<double>(io1 - io0) / tick / wall, sent, got, lost,
      client_failed.load() ? " (the client failed before the end)" : "");
  return client_failed.load() ? 1 : 0;
}
