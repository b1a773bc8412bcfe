// Soak of the desktop app: the real ydscope window on a real-time G6 stream (demo scene, from
// `ydscope-cli sim` in another process on a pseudo-terminal) for 10 minutes, to show that nothing
// accumulates while the picture runs: resident memory flat after the warm-up, CPU steady, and
// the app still answering at the end (a SIGUSR1 screenshot is written, to look at).
// Prints one line every --every seconds and a verdict; exit 1 if a check failed.
// Not a Google Benchmark and not run by ctest. Usage (from any directory):
//   xvfb-run -a -s "-screen 0 1280x800x24" build/release/tests/bench/bench_app_soak [--minutes 10] [--every 30]
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <string>
#include <thread>

#include "bench_options.h"
#include "process_probe.h"

namespace fs = std::filesystem;
using namespace ydscope::bench;

namespace {

// Growth of resident memory after the first minute that still counts as flat: the allocator and
// the GL driver settle in steps of a few pages; a leak of a lap a second would pass this in
// about a minute (a G6 lap is ~14 KB of points).
constexpr long kFlatKib = 2048;

}  // namespace

int main(int argc, char** argv) {
  double minutes = 10;
  int every_s = 30;
  BenchOptions options("bench_app_soak", "the app on a real-time virtual G6, its memory and CPU over minutes");
  options.add("--minutes", minutes, "how long to run").add("--every", every_s, "seconds between lines");
  options.parse(argc, argv);
  if (!(minutes > 0) || every_s < 1) options.fail("needs --minutes above 0 and --every of 1 or more");
  const auto binaries = find_app_binaries("bench_app_soak");
  if (!binaries) return 1;
  const fs::path home = fs::temp_directory_path() / ("ydscope-soak-" + std::to_string(getpid()));
  fs::create_directories(home);
  setenv("XDG_CONFIG_HOME", home.c_str(), 1);
  fs::current_path(home);  // the app writes its screenshot here

  const std::string link = (home / "g6").string();
  const pid_t sim = spawn({binaries->cli, "sim", "--model", "G6", "--scene", "demo", "--pty", link}, true);
  for (int i = 0; i < 50 && !fs::exists(link); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  const pid_t app = spawn({binaries->app, "--port", link, "--model", "G6"}, true);

  std::printf("app soak: G6 demo in real time for %.1f min, a line every %d s\n", minutes, every_s);
  std::printf("%8s %12s %10s\n", "time s", "resident KiB", "CPU %");
  const auto start = std::chrono::steady_clock::now();
  const auto end = start + std::chrono::duration<double>(minutes * 60.0);
  long settled_kib = -1, min_kib = -1, max_kib = -1;
  long last_ticks = cpu_ticks(app);
  auto last = start;
  bool alive = true;
  while (std::chrono::steady_clock::now() < end) {
    std::this_thread::sleep_for(std::chrono::seconds(every_s));
    const auto now = std::chrono::steady_clock::now();
    const long kib = resident_kib(app);
    const long ticks = cpu_ticks(app);
    if (kib < 0 || ticks < 0 || !running(app)) {
      alive = false;
      break;
    }
    const double t = std::chrono::duration<double>(now - start).count();
    const double cpu = 100.0 * static_cast<double>(ticks - last_ticks) / static_cast<double>(sysconf(_SC_CLK_TCK)) /
                       std::chrono::duration<double>(now - last).count();
    last_ticks = ticks;
    last = now;
    std::printf("%8.0f %12ld %10.1f\n", t, kib, cpu);
    std::fflush(stdout);
    if (t < 60.0) continue;  // fonts, GL buffers and rings fill in the first minute
    if (settled_kib < 0) settled_kib = min_kib = max_kib = kib;
    min_kib = std::min(min_kib, kib);
    max_kib = std::max(max_kib, kib);
  }
  bool screenshot = false;
  if (alive) {
    kill(app, SIGUSR1);
    for (int i = 0; i < 50 && !screenshot; ++i) {
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
      for (const auto& entry : fs::directory_iterator(home))
        screenshot = screenshot || entry.path().extension() == ".png";
    }
  }
  stop(app);
  stop(sim);

  const bool flat = settled_kib >= 0 && max_kib - settled_kib <= kFlatKib;
  std::printf("resident after the first minute: %ld KiB, then %ld..%ld KiB (%+ld KiB): %s\n", settled_kib, min_kib,
              max_kib, max_kib - settled_kib, flat ? "flat" : "GROWING");
  std::printf("app still running at the end: %s; a screenshot on SIGUSR1: %s\n", alive ? "yes" : "NO",
              screenshot ? (home.string() + "/*.png").c_str() : "NONE");
  const bool ok = alive && flat && screenshot;
  std::printf("verdict: %s\n", ok ? "pass" : "FAIL");
  if (ok)
    std::printf("(the screenshot stays for a look; remove %s when done)\n", home.c_str());
  else
    fs::remove_all(home);
  return ok ? 0 : 1;
}
