// CPU the desktop app uses, measured from outside as a user would see it in `top`:
//   idle       the window open with a port that does not exist (the session retries with backoff);
//   streaming  a real-time G6 stream (demo scene) from `ydscope-cli sim` in ANOTHER process on a
//              pseudo-terminal, so the virtual lidar's own CPU is not counted; with the View tab's
//              "smooth" on (drawing at the display's rate), then off (a frame per lap).
// For each case the app runs under the current DISPLAY (use xvfb-run) for a warm-up, then its
// utime+stime from /proc/<pid>/stat over a measured window gives the share of one core. The frames
// it showed are counted too (the app says how many a second, over its run, when it stops), and CPU
// per frame: on a loaded machine the app gets fewer frames than it asks for, so its share of a core
// alone under-states a frame's cost.
//   xvfb-run -a -s "-screen 0 1280x800x24" build/release/tests/bench/bench_frame_cpu [--seconds 20] [--scene demo]
//     [--tab statistics --warm-up 125 --cases smooth]
// The scene is the virtual lidar's: demo (a turning flower: every lap lands elsewhere), room
// (walls that stay put, as on a bench or a robot: laps land on the same pixels) or booth. --tab
// opens the sidebar on another tab (statistics: the plots, redrawn as their values move).
// Not a Google Benchmark: it measures another process, so it has its own main.
#include <fcntl.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>
#include <thread>

#include "tests/bench/bench_options.h"
#include "tests/bench/process_probe.h"
#include "ui/view/settings/sidebar_tab.h"

namespace fs = std::filesystem;
using namespace ydscope::bench;

namespace {

// The frames/s the app said it showed when it stopped ("N frames shown in T s (F a second)"),
// counted by the app itself whatever the driver and however it presents; 0 if it said nothing.
double frames_per_second(const fs::path& app_stdout) {
  std::ifstream in(app_stdout);
  std::string line;
  double rate = 0.0;
  while (std::getline(in, line)) {
    const auto open = line.rfind(" (");
    if (line.find("frames shown in") != std::string::npos && open != std::string::npos)
      rate = std::strtod(line.c_str() + open + 2, nullptr);
  }
  return rate;
}

void print_frames(double cpu_percent, double fps) {
  if (fps > 0.0) std::printf("   %5.1f frames/s, %5.1f ms of CPU a frame", fps, 10.0 * cpu_percent / fps);
  std::printf("\n");
}

}  // namespace

int main(int argc, char** argv) {
  int seconds = 20;
  std::string scene = "demo";
  std::string tab = "lidar";
  int warm_up = 5;
  std::string cases = "all";
  BenchOptions options("bench_frame_cpu", "the app's CPU: idle, then a G6 stream with smooth drawing on and off");
  options.add("--seconds", seconds, "how long to measure each case, after the warm-up")
      .add("--scene", scene, "the virtual lidar's scene: demo, room or booth")
      .add("--tab", tab, "the sidebar's tab: lidar, view, statistics or sources")
      .add("--warm-up", warm_up, "seconds before measuring (the plots span up to 120 s of the run)")
      .add("--cases", cases, "all, or smooth: only the stream drawn smooth");
  options.parse(argc, argv);
  if (seconds < 1) options.fail("needs --seconds of 1 or more");
  if (!is_sim_scene(scene)) options.fail("knows the scenes demo, room and booth");
  if (!ydscope::ui::sidebar_tab_from_word(tab)) options.fail("knows the tabs lidar, view, statistics and sources");
  if (warm_up < 0) options.fail("needs --warm-up of 0 or more");
  if (cases != "all" && cases != "smooth") options.fail("knows the cases all and smooth");
  const auto binaries = find_app_binaries("bench_frame_cpu");
  if (!binaries) return 1;
  const std::string& app = binaries->app;
  const std::string& cli = binaries->cli;
  const fs::path home = fs::temp_directory_path() / ("ydscope-cpu-" + std::to_string(getpid()));
  fs::create_directories(home);
  setenv("XDG_CONFIG_HOME", home.c_str(), 1);

  std::printf("app CPU, share of one core over %d s after %d s warm-up\n", seconds, warm_up);
  const fs::path app_stdout = home / "app-stdout";
  if (cases == "all") {
    const pid_t pid = spawn({app, "--port", (home / "no-such-port").string()}, true);
    const double idle = measure_cpu(pid, warm_up, seconds);
    stop(pid);
    std::printf("idle (no device, window open):   %6.2f %%\n", idle);
  }
  for (const bool smooth : {true, false}) {
    if (!smooth && cases == "smooth") break;
    // settings.ini is where the View tab's "smooth" is kept, and the tab the sidebar opens on.
    fs::create_directories(home / "ydscope");
    std::ofstream(home / "ydscope" / "settings.ini") << "smooth = " << (smooth ? "true" : "false") << "\n"
                                                     << "sidebar_tab = " << tab << "\n";
    const std::string link = (home / "g6").string();
    const pid_t sim = spawn({cli, "sim", "--model", "G6", "--scene", scene, "--pty", link}, true);
    for (int i = 0; i < 50 && !fs::exists(link); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(100));
    const int out = open(app_stdout.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const pid_t pid = spawn({app, "--port", link, "--model", "G6"}, true, out);
    close(out);
    const double streaming = measure_cpu(pid, warm_up, seconds);
    const double sim_cpu = measure_cpu(sim, 0, 2);
    stop(pid);
    stop(sim);
    std::printf("streaming (G6 %s, %s tab, sim apart), smooth %-3s:  %6.2f %%   (the sim process itself: %.2f %%)",
                scene.c_str(), tab.c_str(), smooth ? "on" : "off", streaming, sim_cpu);
    print_frames(streaming, frames_per_second(app_stdout));
  }
  fs::remove_all(home);
  return 0;
}
