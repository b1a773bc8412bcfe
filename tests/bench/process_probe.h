#pragma once
// Another process (or thread) as `top` sees it, for the benchmarks that measure from outside:
// start it, read its CPU time and resident memory from /proc, stop it as a service manager would.
#include <fcntl.h>
#include <pthread.h>
#include <signal.h>
#include <sys/wait.h>
#include <time.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

namespace ydscope::bench {

// CLOCK_MONOTONIC in ns: the clock the virtual lidar's zero-packet log (`sim --zero-log`) uses.
inline std::int64_t monotonic_now_ns() {
  timespec ts{};
  clock_gettime(CLOCK_MONOTONIC, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1'000'000'000 + ts.tv_nsec;
}

// A thread's own CPU time in ns (its thread CPU clock); -1 when it cannot be read.
inline std::int64_t thread_cpu_ns(pthread_t thread) {
  clockid_t clock;
  if (pthread_getcpuclockid(thread, &clock) != 0) return -1;
  timespec ts{};
  clock_gettime(clock, &ts);
  return static_cast<std::int64_t>(ts.tv_sec) * 1'000'000'000 + ts.tv_nsec;
}

// quiet: its stdout and stderr go to /dev/null; stdout_fd >= 0: its stdout goes there instead;
// a stderr_file: its stderr goes to that file.
inline pid_t spawn(const std::vector<std::string>& argv, bool quiet, int stdout_fd = -1,
                   const std::filesystem::path& stderr_file = {}) {
  std::fflush(nullptr);  // the child must not repeat our buffered output
  const pid_t pid = fork();
  if (pid == 0) {
    if (quiet) {
      std::freopen("/dev/null", "w", stdout);
      std::freopen("/dev/null", "w", stderr);
    }
    if (stdout_fd >= 0) dup2(stdout_fd, STDOUT_FILENO);
    if (!stderr_file.empty()) {
      const int err = open(stderr_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      if (err >= 0) dup2(err, STDERR_FILENO);
    }
    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    execv(args[0], args.data());
    _exit(127);
  }
  return pid;
}

// Zero packets a virtual lidar wrote (its --zero-log: index and ns per line) within
// [from_ns, to_ns): the laps it closed then.
inline long laps_closed(const std::filesystem::path& zero_log, std::int64_t from_ns, std::int64_t to_ns) {
  std::ifstream in(zero_log);
  std::uint64_t index = 0;
  std::int64_t ns = 0;
  long laps = 0;
  while (in >> index >> ns) laps += ns >= from_ns && ns < to_ns ? 1 : 0;
  return laps;
}

// utime + stime in clock ticks from a /proc stat file (a process's or a thread's); -1 when gone.
inline long stat_ticks(const std::filesystem::path& stat_file) {
  std::ifstream stat(stat_file);
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

// utime + stime in clock ticks; -1 when the process is gone.
inline long cpu_ticks(pid_t pid) { return stat_ticks("/proc/" + std::to_string(pid) + "/stat"); }

// utime + stime in seconds; negative when the process is gone.
inline double cpu_seconds(pid_t pid) {
  return static_cast<double>(cpu_ticks(pid)) / static_cast<double>(sysconf(_SC_CLK_TCK));
}

// utime + stime of the process's threads whose name (comm) starts with `prefix`, summed.
inline long thread_ticks(pid_t pid, const std::string& prefix) {
  long total = 0;
  std::error_code ec;
  for (const auto& task : std::filesystem::directory_iterator("/proc/" + std::to_string(pid) + "/task", ec)) {
    std::ifstream comm_file(task.path() / "comm");
    std::string comm;
    std::getline(comm_file, comm);
    if (comm.rfind(prefix, 0) != 0) continue;
    if (const long ticks = stat_ticks(task.path() / "stat"); ticks > 0) total += ticks;
  }
  return total;
}

// VmRSS in KiB; -1 when the process is gone.
inline long resident_kib(pid_t pid) {
  std::ifstream status("/proc/" + std::to_string(pid) + "/status");
  std::string line;
  while (std::getline(status, line))
    if (line.rfind("VmRSS:", 0) == 0) return std::stol(line.substr(6));
  return -1;
}

inline bool running(pid_t pid) {
  int status = 0;
  return waitpid(pid, &status, WNOHANG) == 0;
}

// Share of one core, in percent, over `seconds` after `warmup_s`; -1 if the process exited.
inline double measure_cpu(pid_t pid, int warmup_s, int seconds) {
  std::this_thread::sleep_for(std::chrono::seconds(warmup_s));
  const long t0 = cpu_ticks(pid);
  const auto w0 = std::chrono::steady_clock::now();
  std::this_thread::sleep_for(std::chrono::seconds(seconds));
  const long t1 = cpu_ticks(pid);
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - w0).count();
  if (t0 < 0 || t1 < 0 || !running(pid)) return -1.0;  // it exited: no number
  return 100.0 * static_cast<double>(t1 - t0) / static_cast<double>(sysconf(_SC_CLK_TCK)) / wall;
}

// SIGTERM, as a service manager stops it; SIGKILL after 5 s.
inline void stop(pid_t pid) {
  kill(pid, SIGTERM);
  int status = 0;
  for (int i = 0; i < 50 && waitpid(pid, &status, WNOHANG) == 0; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  if (waitpid(pid, &status, WNOHANG) == 0) {
    kill(pid, SIGKILL);
    waitpid(pid, &status, 0);
  }
}

struct AppBinaries {
  std::string app;  // ydscope
  std::string cli;  // ydscope-cli
};

// The app and the CLI of the build this benchmark belongs to, with a display to run the app on;
// otherwise one sentence on stderr (naming `who`) and nothing.
inline std::optional<AppBinaries> find_app_binaries(const char* who) {
  if (!std::getenv("DISPLAY")) {
    std::fprintf(stderr, "%s: no DISPLAY; run it under xvfb-run.\n", who);
    return std::nullopt;
  }
  namespace fs = std::filesystem;
  const fs::path build = fs::canonical("/proc/self/exe").parent_path().parent_path().parent_path();
  AppBinaries found{(build / "app" / "ydscope").string(), (build / "app" / "ydscope-cli").string()};
  if (!fs::exists(found.app) || !fs::exists(found.cli)) {
    std::fprintf(stderr, "%s: build ydscope and ydscope-cli first (looked in %s).\n", who, (build / "app").c_str());
    return std::nullopt;
  }
  return found;
}

}  // namespace ydscope::bench
