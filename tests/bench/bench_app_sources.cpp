// Several lidars into the desktop app, measured from outside: N virtual G6 (demo scene unless
// --scene says another, 8 Hz),
// each from its own `ydscope-cli sim` process on a pseudo-terminal (so their CPU is not counted),
// and `ydscope --port ... --port ...` showing them all in one view. Over a measured window after a
// warm-up it reads /proc: the app's CPU, the sessions' I/O threads together ("ydscope-io"), the
// main thread (input, the view model, the vertex build) and llvmpipe's threads (the software GL);
// then it stops the app, which prints each source's laps (from the device, drawn, lost) and the
// frame work. Smooth on (30 frames/s on llvmpipe) and off (a frame per lap).
//   xvfb-run -a -s "-screen 0 1280x800x24" build/release/tests/bench/bench_app_sources [--seconds 20] [--lidars 4] [--scene room]
// Not a Google Benchmark: it measures other processes, so it has its own main.
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>
#include <vector>

#include "bench_options.h"
#include "process_probe.h"

namespace fs = std::filesystem;
using namespace ydscope::bench;

namespace {

// Share of one core, in percent, of `ticks` clock ticks over `seconds`.
double share(long ticks, double seconds) {
  return 100.0 * static_cast<double>(ticks) / static_cast<double>(sysconf(_SC_CLK_TCK)) / seconds;
}

}  // namespace

int main(int argc, char** argv) {
  int seconds = 20;
  int lidars = 4;
  std::string scene = "demo";
  BenchOptions options("bench_app_sources", "several virtual G6 into one app: CPU by thread and lost laps");
  options.add("--seconds", seconds, "how long to measure, after 5 s").add("--lidars", lidars, "virtual G6 lidars");
  options.add("--scene", scene, "the virtual lidars' scene: demo, room or booth");
  options.parse(argc, argv);
  if (seconds < 1 || lidars < 1) options.fail("needs --seconds and --lidars of 1 or more");
  if (!is_sim_scene(scene)) options.fail("knows the scenes demo, room and booth");
  const auto binaries = find_app_binaries("bench_app_sources");
  if (!binaries) return 1;
  const fs::path home = fs::temp_directory_path() / ("ydscope-sources-" + std::to_string(getpid()));
  fs::create_directories(home / "ydscope");
  setenv("XDG_CONFIG_HOME", home.c_str(), 1);

  std::vector<pid_t> sims;
  std::vector<std::string> app_argv{binaries->app};
  for (int i = 0; i < lidars; ++i) {
    const std::string link = (home / ("g6_" + std::to_string(i))).string();
    sims.push_back(spawn({binaries->cli, "sim", "--model", "G6", "--scene", scene, "--pty", link}, true));
    for (int wait = 0; wait < 50 && !fs::exists(link); ++wait)
      std::this_thread::sleep_for(std::chrono::milliseconds(100));
    app_argv.insert(app_argv.end(), {"--port", link});
  }
  app_argv.insert(app_argv.end(), {"--model", "G6"});

  std::printf("%d virtual G6 (%s scene) in other processes into one app; share of one core over %d s after 5 s\n",
              lidars, scene.c_str(), seconds);
  for (const bool smooth : {true, false}) {
    std::ofstream(home / "ydscope" / "settings.ini") << "smooth = " << (smooth ? "true" : "false") << "\n";
    std::printf("-- smooth %s\n", smooth ? "on (30 frames/s on llvmpipe)" : "off (a frame per lap)");
    std::fflush(stdout);
    const pid_t app = spawn(app_argv, false);  // its summary at the end goes to our stdout
    std::this_thread::sleep_for(std::chrono::seconds(5));
    const long all0 = cpu_ticks(app), io0 = thread_ticks(app, "ydscope-io"), main0 = thread_ticks(app, "ydscope"),
               gl0 = thread_ticks(app, "llvmpipe");
    const auto w0 = std::chrono::steady_clock::now();
    std::this_thread::sleep_for(std::chrono::seconds(seconds));
    const long all1 = cpu_ticks(app), io1 = thread_ticks(app, "ydscope-io"), main1 = thread_ticks(app, "ydscope"),
               gl1 = thread_ticks(app, "llvmpipe");
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count();
    if (!running(app)) {
      std::printf("the app exited during the run\n");
      break;
    }
    // "ydscope" is a prefix of "ydscope-io": the main thread is what is left of it.
    std::printf("app %6.2f %%   I/O threads together %5.2f %%   main thread %6.2f %%   llvmpipe %6.2f %%\n",
                share(all1 - all0, wall), share(io1 - io0, wall), share((main1 - main0) - (io1 - io0), wall),
                share(gl1 - gl0, wall));
    std::fflush(stdout);
    stop(app);
  }
  for (const pid_t sim : sims) stop(sim);
  fs::remove_all(home);
  return 0;
}
