// CPU the desktop app uses, measured from outside as a user would see it in `top`:
//   idle       the window open with a port that does not exist (the session retries with backoff);
//   streaming  a real-time G6 stream (demo scene) from `ydscope-cli sim` in ANOTHER process on a
//              pseudo-terminal, so the virtual lidar's own CPU is not counted; with the View tab's
//              "smooth" on (drawing at the display's rate), then off (a frame per lap).
// For each case the app runs under the current DISPLAY (use xvfb-run) for a warm-up, then its
// utime+stime from /proc/<pid>/stat over a measured window gives the share of one core.
//   xvfb-run -a -s "-screen 0 1280x800x24" build/ui/tests/bench/bench_frame_cpu [seconds]
// Not a Google Benchmark: it measures another process, so it has its own main.
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace {

namespace fs = std::filesystem;

pid_t spawn(const std::vector<std::string>& argv, bool quiet) {
  std::fflush(nullptr);  // the child must not repeat our buffered output
  const pid_t pid = fork();
  if (pid == 0) {
    if (quiet) {
      std::freopen("/dev/null", "w", stdout);
      std::freopen("/dev/null", "w", stderr);
    }
    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    execv(args[0], args.data());
    _exit(127);
  }
  return pid;
}

// utime + stime in clock ticks; -1 when the process is gone.
long cpu_ticks(pid_t pid) {
  std::ifstream stat("/proc/" + std::to_string(pid) + "/stat");
  std::string text;
  if (!std::getline(stat, text)) return -1;
  // Fields after the command name (which may hold spaces) start after the last ')'.
  std::istringstream rest(text.substr(text.rfind(')') + 2));
  std::string field;
  long utime = 0, stime = 0;
  for (int i = 3; i <= 15 && rest >> field; ++i) {
    if (i == 14) utime = std::stol(field);
    if (i == 15) stime = std::stol(field);
  }
  return utime + stime;
}

double measure(pid_t pid, int warmup_s, int seconds) {
  std::this_thread::sleep_for(std::chrono::seconds(warmup_s));
  const long t0 = cpu_ticks(pid);
  const auto w0 = std::chrono::steady_clock::now();
  std::this_thread::sleep_for(std::chrono::seconds(seconds));
  const long t1 = cpu_ticks(pid);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count();
  int status = 0;
  if (t0 < 0 || t1 < 0 || waitpid(pid, &status, WNOHANG) != 0) return -1.0;  // it exited: no number
  return 100.0 * static_cast<double>(t1 - t0) / static_cast<double>(sysconf(_SC_CLK_TCK)) / wall;
}

void stop(pid_t pid) {
  kill(pid, SIGTERM);
  int status = 0;
  for (int i = 0; i < 50 && waitpid(pid, &status, WNOHANG) == 0; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(100));
  if (waitpid(pid, &status, WNOHANG) == 0) {
    kill(pid, SIGKILL);
    waitpid(pid, &status, 0);
  }
}

}  // namespace

int main(int argc, char** argv) {
  const int seconds = argc > 1 ? std::atoi(argv[1]) : 20;
  if (!std::getenv("DISPLAY")) {
    std::fprintf(stderr, "bench_frame_cpu: no DISPLAY; run it under xvfb-run.\n");
    return 1;
  }
  const fs::path build = fs::canonical("/proc/self/exe").parent_path().parent_path().parent_path();
  const std::string app = (build / "app" / "ydscope").string();
  const std::string cli = (build / "app" / "ydscope-cli").string();
  if (!fs::exists(app) || !fs::exists(cli)) {
    std::fprintf(stderr, "bench_frame_cpu: build ydscope and ydscope-cli first (looked in %s).\n", (build / "app").c_str());
    return 1;
  }
  const fs::path home = fs::temp_directory_path() / ("ydscope-cpu-" + std::to_string(getpid()));
  fs::create_directories(home);
  setenv("XDG_CONFIG_HOME", home.c_str(), 1);

  std::printf("app CPU, share of one core over %d s after 5 s warm-up\n", seconds);
  {
    const pid_t pid = spawn({app, "--port", (home / "no-such-port").string()}, true);
    const double idle = measure(pid, 5, seconds);
    stop(pid);
    std::printf("idle (no device, window open):   %6.2f %%\n", idle);
  }
  for (const bool smooth : {true, false}) {
    // settings.ini is where the View tab's "smooth" is kept.
    fs::create_directories(home / "ydscope");
    std::ofstream(home / "ydscope" / "settings.ini") << "smooth = " << (smooth ? "true" : "false") << "\n";
    const std::string link = (home / "g6").string();
    const pid_t sim = spawn({cli, "sim", "--model", "G6", "--scene", "demo", "--pty", link}, true);
    for (int i = 0; i < 50 && !fs::exists(link); ++i) std::this_thread::sleep_for(std::chrono::milliseconds(100));
    const pid_t pid = spawn({app, "--port", link, "--model", "G6"}, true);
    const double streaming = measure(pid, 5, seconds);
    const double sim_cpu = measure(sim, 0, 2);
    stop(pid);
    stop(sim);
    std::printf("streaming (G6 demo, sim apart), smooth %-3s:  %6.2f %%   (the sim process itself: %.2f %%)\n",
                smooth ? "on" : "off", streaming, sim_cpu);
  }
  fs::remove_all(home);
  return 0;
}
