// Soak of `ydscope-cli serve` with a reader and a non-reader, the way issue 26 asks (not a Google
// Benchmark and not run by ctest; one run, a table and a verdict on stdout):
//   - the virtual G6 (`ydscope-cli sim --pty`, 8 Hz, real time) in a process of its own, logging
//     each zero packet it writes (`--zero-log`): one per lap it closed;
//   - `ydscope-cli serve` on it, listening on 127.0.0.1 (a free port);
//   - a reader: a Foxglove client (tests/bridge/ws_test_client.h) subscribed to /scan and /points,
//     as Foxglove's 3D panel is, counting the /scan messages it receives and any status message
//     that says it lost some;
//   - a non-reader: a client with a 4 KiB receive window subscribed to the same topics that never
//     reads a byte, so serve's queue for it overflows and stays full. serve closes a client that
//     answers none of its keep-alive pings for 5 minutes (as it should), so the non-reader is
//     replaced by a fresh one every --replace seconds (default 120).
// Every --every seconds (default 10) a row: serve's resident memory (VmRSS from /proc/PID/status),
// the laps the lidar closed and the reader received in that interval, and the totals. The
// verdict, after --minutes (default 10): memory is flat when the largest sample of the second half
// of the run is within --rss-tolerance percent (default 10) of the largest of the first half
// (after the --warmup, default 30 s). Halves, not the first sample: the non-reader's full queue
// holds up to 64 laps (about 2 MiB of /scan and /points), which go when it is replaced and come
// back as its successor's queue fills, so the resident memory swings by that much; a leak
// grows from half to half, a bounded queue does not. Every
// lap was served when the reader received every lap the lidar closed after the warmup (one lap at
// either edge of the window is timing, not a loss) and was never told of a drop. Exit 0 on PASS,
// 1 on FAIL. serve's own exit lines (per-client counters) are quoted at the end. Usage:
//   bench_serve_soak [--cli PATH] [--minutes 10] [--every 10] [--warmup 30] [--rss-tolerance 10]
//                    [--replace 120]
// --cli defaults to the ydscope-cli of the build this program belongs to.
#include <fcntl.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "bench_options.h"
#include "support/ws_test_client.h"
#include "process_probe.h"

namespace {

using namespace std::chrono_literals;
namespace fs = std::filesystem;
namespace bench = ydscope::bench;
using ydscope::test::WsTestClient;

struct Args {
  std::string cli;
  double minutes = 10;
  double every_s = 10;
  double warmup_s = 30;
  double rss_tolerance_pct = 10;
  double replace_s = 120;
};

// The first line serve prints: "serving ws://127.0.0.1:PORT for LINK".
unsigned read_serving_port(int fd) {
  std::string banner;
  char c = 0;
  while (read(fd, &c, 1) == 1 && c != '\n') banner += c;
  unsigned port = 0;
  return std::sscanf(banner.c_str(), "serving ws://127.0.0.1:%u", &port) == 1 ? port : 0;
}

// The reader, on a thread of its own: counts /scan messages and statuses that report drops.
class Reader {
 public:
  explicit Reader(std::uint16_t port) : thread_([this, port] { run(port); }) {}
  ~Reader() {
    done_.store(true);
    thread_.join();
  }
  long scans() const { return scans_.load(); }
  long drop_warnings() const { return drop_warnings_.load(); }
  bool failed() const { return failed_.load(); }
  bool subscribed() const { return subscribed_.load(); }

 private:
  void run(std::uint16_t port) {
    try {
      WsTestClient client(port);
      if (!client.subscribe(1, "/scan") || !client.subscribe(2, "/points")) throw std::runtime_error("subscribe");
      subscribed_.store(true);
      while (!done_.load()) {
        const auto message = client.read(5s);
        if (!message) throw std::runtime_error("read");
        if (message->text && message->json.find("messages dropped") != std::string::npos) ++drop_warnings_;
        if (!message->text && message->subscription == 1) ++scans_;
      }
      client.close_handshake();
    } catch (const std::exception&) {
      failed_.store(true);
    }
  }

  std::atomic<bool> done_{false};
  std::atomic<bool> subscribed_{false};
  std::atomic<long> scans_{0};
  std::atomic<long> drop_warnings_{0};
  std::atomic<bool> failed_{false};
  std::thread thread_;
};

// A client that subscribes and then never reads, its receive window 4 KiB.
std::unique_ptr<WsTestClient> non_reader(std::uint16_t port) {
  auto client = std::make_unique<WsTestClient>(port, 4096);
  if (!client->subscribe(1, "/scan") || !client->subscribe(2, "/points")) return nullptr;
  return client;
}

}  // namespace

int main(int argc, char** argv) {
  Args args;
  bench::BenchOptions options("bench_serve_soak",
                              "serve on the virtual G6 for minutes with a reader and a non-reader: memory and laps");
  options.add("--cli", args.cli, "path of ydscope-cli (default: this build's)")
      .add("--minutes", args.minutes, "how long to run")
      .add("--every", args.every_s, "seconds between rows")
      .add("--warmup", args.warmup_s, "seconds before the first row, the memory baseline")
      .add("--rss-tolerance", args.rss_tolerance_pct, "percent serve's memory may grow over its baseline")
      .add("--replace", args.replace_s, "seconds between non-readers (serve closes one after 5 min of no pongs)");
  options.parse(argc, argv);
  if (args.cli.empty())
    args.cli = (fs::canonical("/proc/self/exe").parent_path().parent_path().parent_path() / "app" / "ydscope-cli");
  if (!fs::exists(args.cli)) options.fail("cannot find ydscope-cli at " + args.cli + "; pass --cli PATH");
  if (!(args.minutes > 0) || !(args.every_s > 0) || args.warmup_s < 0 || !(args.rss_tolerance_pct >= 0) ||
      !(args.replace_s > 0) || args.replace_s >= 300)
    options.fail(
        "needs --minutes and --every above 0, --warmup and --rss-tolerance of 0 or more, --replace in (0, 300)");

  const fs::path dir = fs::temp_directory_path() / ("bench_serve_soak." + std::to_string(getpid()));
  fs::create_directories(dir);
  const fs::path link = dir / "g6";
  const fs::path zero_log = dir / "zero";
  const fs::path serve_log = dir / "serve.stderr";
  const pid_t sim =
      bench::spawn({args.cli, "sim", "--model", "G6", "--pty", link.string(), "--zero-log", zero_log.string()},
                   /*quiet=*/true);
  for (int wait = 0; wait < 100 && !fs::exists(link); ++wait) std::this_thread::sleep_for(50ms);
  int pipe_fds[2];
  if (sim <= 0 || !fs::exists(link) || pipe(pipe_fds) != 0) {
    std::fprintf(stderr, "bench_serve_soak: the virtual lidar did not start\n");
    if (sim > 0) bench::stop(sim);
    fs::remove_all(dir);
    return 1;
  }
  const pid_t serve = bench::spawn({args.cli, "serve", "--port", link.string(), "--listen", "127.0.0.1:0"}, false,
                                   pipe_fds[1], serve_log);
  close(pipe_fds[1]);
  const auto port = static_cast<std::uint16_t>(read_serving_port(pipe_fds[0]));
  close(pipe_fds[0]);
  const auto stop_all = [&] {
    if (serve > 0) bench::stop(serve);
    bench::stop(sim);
  };
  if (serve <= 0 || port == 0) {
    std::fprintf(stderr, "bench_serve_soak: serve did not start\n");
    stop_all();
    fs::remove_all(dir);
    return 1;
  }

  Reader reader(port);
  std::unique_ptr<WsTestClient> silent = non_reader(port);
  int non_readers = silent ? 1 : 0;
  auto replaced_at = std::chrono::steady_clock::now();
  const auto started = std::chrono::steady_clock::now();
  const auto wait_until = [&](std::chrono::steady_clock::time_point until) {
    while (std::chrono::steady_clock::now() < until) {
      std::this_thread::sleep_for(
          std::min<std::chrono::steady_clock::duration>(200ms, until - std::chrono::steady_clock::now()));
      if (std::chrono::steady_clock::now() - replaced_at >= std::chrono::duration<double>(args.replace_s)) {
        silent.reset();  // the old one goes with its messages unread: a reset, as a crashed client
        silent = non_reader(port);
        non_readers += silent ? 1 : 0;
        replaced_at = std::chrono::steady_clock::now();
      }
    }
  };

  const auto every =
      std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(args.every_s));
  wait_until(started + std::chrono::duration_cast<std::chrono::steady_clock::duration>(
                           std::chrono::duration<double>(args.warmup_s)));
  const std::int64_t from_ns = bench::monotonic_now_ns();
  const long scans0 = reader.scans();
  const long baseline_kib = bench::resident_kib(serve);
  std::vector<long> samples_kib{baseline_kib};
  std::printf(
      "serve on the virtual G6 (8 Hz), one reader (/scan + /points), one non-reader; after %.0f s of warm-up:\n",
      args.warmup_s);
  std::printf("%8s %10s %9s %13s %15s %12s %14s\n", "t (s)", "RSS (KiB)", "vs first", "laps closed", "laps received",
              "total closed", "total received");
  std::printf("%8.0f %10ld %8.1f%% %13s %15s %12d %14d\n", 0.0, baseline_kib, 0.0, "-", "-", 0, 0);
  std::fflush(stdout);
  const int rows = static_cast<int>(args.minutes * 60 / args.every_s + 0.5);
  std::int64_t row_from_ns = from_ns;
  long row_scans = scans0;
  long total_closed = 0;
  const auto measuring = std::chrono::steady_clock::now();
  for (int row = 1; row <= rows && !reader.failed() && bench::running(serve); ++row) {
    wait_until(measuring + row * every);
    const std::int64_t now_ns = bench::monotonic_now_ns();
    const long scans = reader.scans();
    const long kib = bench::resident_kib(serve);
    const long closed = bench::laps_closed(zero_log, row_from_ns, now_ns);
    total_closed += closed;
    samples_kib.push_back(kib);
    std::printf("%8.0f %10ld %8.1f%% %13ld %15ld %12ld %14ld\n", row * args.every_s, kib,
                100.0 * static_cast<double>(kib - baseline_kib) / static_cast<double>(baseline_kib), closed,
                scans - row_scans, total_closed, scans - scans0);
    std::fflush(stdout);
    row_from_ns = now_ns;
    row_scans = scans;
  }
  const long received = reader.scans() - scans0;
  const bool reader_failed = reader.failed();
  const bool serve_ran = bench::running(serve);
  const long warnings = reader.drop_warnings();
  bench::stop(serve);  // SIGTERM: serve prints its per-client counters (the non-reader's too) on stderr
  silent.reset();
  bench::stop(sim);

  const auto half = samples_kib.begin() + static_cast<std::ptrdiff_t>((samples_kib.size() + 1) / 2);
  const long first_half_kib = *std::max_element(samples_kib.begin(), half);
  const long second_half_kib = half == samples_kib.end() ? first_half_kib : *std::max_element(half, samples_kib.end());
  const auto [least, most] = std::minmax_element(samples_kib.begin(), samples_kib.end());
  const double growth_pct =
      100.0 * static_cast<double>(second_half_kib - first_half_kib) / static_cast<double>(first_half_kib);
  const bool flat = growth_pct <= args.rss_tolerance_pct;
  const long lost = std::max(0L, total_closed - received - 1);
  const bool every_lap = !reader_failed && serve_ran && lost == 0 && warnings == 0;
  std::printf(
      "\nserve's resident memory: %ld to %ld KiB; largest in the first half %ld KiB, in the second %ld KiB "
      "(%+.1f%%, tolerance %.1f%%): %s\n",
      *least, *most, first_half_kib, second_half_kib, growth_pct, args.rss_tolerance_pct, flat ? "flat" : "GREW");
  std::printf(
      "laps: closed by the lidar %ld, received by the reader %ld, lost %ld; drop warnings to the reader %ld%s%s\n",
      total_closed, received, lost, warnings, reader_failed ? "; the reader FAILED (timeout or closed)" : "",
      serve_ran ? "" : "; serve EXITED early");
  std::printf("non-readers connected one after another: %d\n", non_readers);
  std::ifstream log(serve_log);
  for (std::string line; std::getline(log, line);) std::printf("  serve said: %s\n", line.c_str());
  std::printf("verdict: %s\n", flat && every_lap ? "PASS" : "FAIL");
  fs::remove_all(dir);
  return flat && every_lap ? 0 : 1;
}
