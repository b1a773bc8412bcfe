// Measures how fast a live session scans again after its port comes back, and what it costs to
// wait: `ydscope-cli sim --pty LINK` (a separate process, like a real device behind a port) is
// killed with SIGKILL while a Session scans it, left dead for --outage seconds, then started
// again on the same LINK. Per round it reports:
//   - back: from the new virtual lidar printing "ready" to the session in Scanning again, and to
//     the first lap queued after that;
//   - the I/O thread's CPU during the outage (its thread CPU clock).
// Not a Google Benchmark and not run by ctest. Usage:
//   bench_reconnect --cli build/release/app/ydscope-cli [--rounds 5] [--outage 3] [--model G6]
#include <pthread.h>
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
#include <string>
#include <thread>
#include <vector>

#include "bench_options.h"
#include "core/session/session.h"
#include "core/session/session_io.h"
#include "process_probe.h"

using namespace ydscope;
using namespace std::chrono_literals;

namespace {

struct Args {
  std::string cli;
  int rounds = 5;
  double outage_s = 3;
  std::string model = "G6";
};

Args parse(int argc, char** argv) {
  Args args;
  bench::BenchOptions options("bench_reconnect", "how fast a session scans again after its port comes back");
  options.add("--cli", args.cli, "path of ydscope-cli, whose virtual lidar is killed and restarted")
      .add("--rounds", args.rounds, "outages to measure")
      .add("--outage", args.outage_s, "seconds each outage lasts")
      .add("--model", args.model, "G1, G6 or a TG model");
  options.parse(argc, argv);
  if (args.cli.empty()) options.fail("needs --cli PATH/ydscope-cli");
  if (!find_profile(args.model)) options.fail("does not know the model '" + args.model + "'");
  if (args.rounds < 1 || !(args.outage_s > 0)) options.fail("needs --rounds of 1 or more and --outage above 0");
  return args;
}

// Starts the virtual lidar and returns once it printed "ready" (its pid; -1 on failure).
pid_t start_sim(const Args& args, const std::string& link) {
  int out[2];
  if (pipe(out) != 0) return -1;
  const pid_t child = fork();
  if (child == 0) {
    dup2(out[1], STDOUT_FILENO);
    close(out[0]);
    close(out[1]);
    execl(args.cli.c_str(), args.cli.c_str(), "sim", "--model", args.model.c_str(), "--pty", link.c_str(),
          static_cast<char*>(nullptr));
    _exit(127);
  }
  close(out[1]);
  std::string line;
  char c;
  while (read(out[0], &c, 1) == 1 && c != '\n') line += c;
  close(out[0]);  // the sim writes nothing more to stdout
  if (line.rfind("ready", 0) != 0) {
    std::fprintf(stderr, "the virtual lidar did not start: '%s'\n", line.c_str());
    return -1;
  }
  return child;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0 : v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  const Args args = parse(argc, argv);
  const ModelProfile* profile = find_profile(args.model);
  std::string dir = (std::filesystem::temp_directory_path() / "ydscope-reconnect-XXXXXX").string();
  if (!mkdtemp(dir.data())) return 1;
  const std::string link = dir + "/lidar";
  pid_t sim = start_sim(args, link);
  if (sim < 0) return 1;

  std::atomic<std::uint64_t> pushed{0};
  std::atomic<bool> have_thread{false};
  pthread_t io_thread{};
  Session session(64, [&] {
    if (!have_thread.load(std::memory_order_relaxed)) {
      io_thread = pthread_self();
      have_thread.store(true, std::memory_order_release);
    }
    pushed.fetch_add(1, std::memory_order_release);
  });
  // Stops and joins when it goes out of scope, before the session it reads (declared earlier).
  std::jthread consumer([&](std::stop_token stop) {
    Lap lap;
    while (!stop.stop_requested()) {
      while (session.laps().try_pop(lap)) {
      }
      std::this_thread::sleep_for(10ms);
    }
  });
  SessionConfig config;
  config.address = link;
  config.model = profile->model;
  session.connect(config);
  const auto scanning = [](const SessionSnapshot& s) { return s.state == LinkState::Scanning; };
  if (!scanning(session.wait_until(scanning, 20s))) {
    std::fprintf(stderr, "the session did not start: %s\n", describe_snapshot(session.snapshot()).c_str());
    return 1;
  }
  while (!have_thread.load(std::memory_order_acquire)) std::this_thread::sleep_for(1ms);

  std::vector<double> to_scanning_ms, to_lap_ms, outage_cpu_percent;
  int failures = 0;
  for (int round = 1; round <= args.rounds; ++round) {
    std::this_thread::sleep_for(1s);  // a second of scanning between outages
    kill(sim, SIGKILL);
    waitpid(sim, nullptr, 0);
    session.wait_until([](const SessionSnapshot& s) { return s.state != LinkState::Scanning; }, 10s);
    const std::int64_t cpu0 = bench::thread_cpu_ns(io_thread);
    const std::int64_t wall0 = link_clock_ns();
    std::this_thread::sleep_for(std::chrono::duration<double>(args.outage_s));
    const std::int64_t cpu1 = bench::thread_cpu_ns(io_thread);
    const std::int64_t wall1 = link_clock_ns();
    sim = start_sim(args, link);
    if (sim < 0) return 1;
    const std::int64_t ready = link_clock_ns();
    const std::uint64_t laps_before = pushed.load(std::memory_order_acquire);
    const SessionSnapshot back = session.wait_until(scanning, 30s);
    const std::int64_t scanning_at = link_clock_ns();
    while (pushed.load(std::memory_order_acquire) == laps_before && link_clock_ns() - ready < 30'000'000'000)
      std::this_thread::sleep_for(1ms);
    const std::int64_t lap_at = link_clock_ns();
    if (!scanning(back)) {
      ++failures;
      std::printf("round %d: not scanning again within 30 s: %s\n", round, describe_snapshot(back).c_str());
      continue;
    }
    to_scanning_ms.push_back(static_cast<double>(scanning_at - ready) * 1e-6);
    to_lap_ms.push_back(static_cast<double>(lap_at - ready) * 1e-6);
    outage_cpu_percent.push_back(100.0 * static_cast<double>(cpu1 - cpu0) / static_cast<double>(wall1 - wall0));
    std::printf(
        "round %d: scanning %.0f ms and first lap %.0f ms after the port came back; I/O thread %.3f%% of a core while "
        "it was gone\n",
        round, to_scanning_ms.back(), to_lap_ms.back(), outage_cpu_percent.back());
  }
  std::printf(
      "median over %zu rounds (outage %.1f s): scanning again %.0f ms, first lap %.0f ms, I/O thread CPU while waiting "
      "%.3f%%; %d rounds failed; reconnects counted %llu\n",
      to_scanning_ms.size(), args.outage_s, median(to_scanning_ms), median(to_lap_ms), median(outage_cpu_percent),
      failures, static_cast<unsigned long long>(session.snapshot().counters.reconnects));
  session.disconnect();
  consumer.request_stop();
  consumer.join();
  kill(sim, SIGTERM);
  waitpid(sim, nullptr, 0);
  std::filesystem::remove_all(dir);
  return failures == 0 ? 0 : 1;
}
