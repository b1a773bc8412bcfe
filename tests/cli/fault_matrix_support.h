#pragma once
// The fault matrix's tools: what the virtual lidar really sent (its ground truth, packet by
// packet, with which packets a fault kept off the line or broke), the laps ydscope-cli printed
// (its JSON lines), the match between the two, and the CLI run as a child process with a hang
// guard (a bound, never an assertion on time).
#include <fcntl.h>
#include <poll.h>
#include <signal.h>
#include <spawn.h>
#include <sys/syscall.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <mutex>
#include <string>
#include <vector>

#include "core/sim/virtual_lidar.h"

extern char** environ;

namespace ydscope::test {

// A lap as its points would print: count and sum of ranges (the scene moves, so two laps with the
// same count and sum are the same lap).
struct LapSignature {
  std::size_t points = 0;
  double range_sum = 0;
  bool same_as(const LapSignature& other) const {
    // The CLI rounds each range to 0.01 mm.
    return points == other.points &&
           std::abs(range_sum - other.range_sum) <= 0.006 * static_cast<double>(points) + 0.01;
  }
};

// Collects the device's truth packets (called on the sim's thread) and makes laps of them.
class TruthRecorder {
 public:
  void add(const TruthPacket& packet) {
    std::lock_guard lock(mutex_);
    packets_.push_back(packet);
  }
  struct TruthLap {
    LapSignature signature;
    bool touched = false;  // a packet of it, or the zero packet closing it, was lost or broken
  };
  // Every closed lap of every scan, in order. A scan's lap 0 starts at its first zero packet.
  std::vector<TruthLap> laps() const {
    std::lock_guard lock(mutex_);
    std::vector<TruthLap> laps;
    bool open = false;
    for (const TruthPacket& p : packets_) {
      // A packet whose flipped bytes cancel in its checksum arrives as good with other values:
      // its lap was touched too, though no decoder can tell.
      const bool damaged = p.lost || p.corrupted || p.altered;
      if (p.index == 0) {
        if (open && p.lap > 0) {
          laps.back().touched = laps.back().touched || damaged;  // its closing zero packet
        } else if (open) {
          laps.pop_back();  // a new scan began: the open lap never closed
        }
        laps.push_back({});
        open = true;
      }
      if (!open) continue;
      TruthLap& lap = laps.back();
      lap.touched = lap.touched || damaged;
      lap.signature.points += p.points.size();
      for (const LapPoint& point : p.points) lap.signature.range_sum += point.range_mm;
    }
    if (open) laps.pop_back();  // still open when the scan ended
    return laps;
  }

 private:
  mutable std::mutex mutex_;
  std::vector<TruthPacket> packets_;
};

struct PrintedLap {
  LapSignature signature;
  std::string line;
};

// The lap objects of `ydscope-cli scan`/`decode` JSON lines (schema: `decode --help`).
inline std::vector<PrintedLap> printed_laps(const std::string& jsonl) {
  std::vector<PrintedLap> laps;
  std::size_t at = 0;
  while ((at = jsonl.find("{\"type\":\"lap\"", at)) != std::string::npos) {
    const std::size_t end = jsonl.find('\n', at);
    PrintedLap lap;
    lap.line = jsonl.substr(at, end == std::string::npos ? std::string::npos : end - at);
    const std::size_t points = lap.line.find("\"points\":[");
    const char* p = lap.line.c_str() + (points == std::string::npos ? lap.line.size() : points + 10);
    while (*p == '[' || *p == ',') {  // [angle,range,flag]
      if (*p == ',') ++p;
      if (*p != '[') break;
      // A line cut off mid-point (the program was stopped while printing) ends the walk: every
      // step checks its separator before stepping past it, never past the string's end.
      char* next = nullptr;
      std::strtod(p + 1, &next);
      if (*next != ',') break;
      const double range = std::strtod(next + 1, &next);
      if (*next != ',') break;
      std::strtoul(next + 1, &next, 10);
      if (*next != ']') break;
      lap.signature.points += 1;
      lap.signature.range_sum += range;
      p = next + 1;  // past ']'
    }
    laps.push_back(std::move(lap));
    at = end == std::string::npos ? jsonl.size() : end;
  }
  return laps;
}

struct LapMatch {
  std::size_t printed = 0;            // laps printed
  std::size_t printed_unknown = 0;    // printed laps matching no lap the device sent
  std::size_t untouched_missing = 0;  // untouched laps the device sent (up to the last printed one) not printed
  std::size_t untouched = 0;          // untouched laps in that span
  // Touched laps in that span and as many laps after it as printed laps matched none (a printed
  // lap that is not a lap the device sent whole stands for at least one touched lap).
  std::size_t touched = 0;
};

// Which of the device's laps came out, up to the last one that did (the CLI stopped after that).
inline LapMatch match_laps(const std::vector<TruthRecorder::TruthLap>& truth, const std::vector<PrintedLap>& printed) {
  LapMatch match;
  match.printed = printed.size();
  std::vector<bool> seen(truth.size(), false);
  std::size_t last = 0;
  bool any = false;
  for (const PrintedLap& lap : printed) {
    bool found = false;
    for (std::size_t i = 0; i < truth.size() && !found; ++i)
      if (!seen[i] && truth[i].signature.same_as(lap.signature)) {
        seen[i] = found = true;
        if (!any || i > last) last = i;
        any = true;
      }
    if (!found) ++match.printed_unknown;
  }
  for (std::size_t i = 0; any && i < truth.size() && i <= last + match.printed_unknown; ++i) {
    if (truth[i].touched) {
      ++match.touched;
    } else if (i <= last) {
      ++match.untouched;
      if (!seen[i]) ++match.untouched_missing;
    }
  }
  return match;
}

inline std::string slurp(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), {});
}

// ydscope-cli as a child process, stdout and stderr to files.
class CliProcess {
 public:
  CliProcess(const std::vector<std::string>& args, std::string out_path, std::string err_path)
      : out_path_(std::move(out_path)), err_path_(std::move(err_path)) {
    std::vector<std::string> text{YDSCOPE_CLI_PATH};
    text.insert(text.end(), args.begin(), args.end());
    std::vector<char*> argv;
    for (auto& a : text) argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 0, "/dev/null", O_RDONLY, 0);
    posix_spawn_file_actions_addopen(&actions, 1, out_path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    posix_spawn_file_actions_addopen(&actions, 2, err_path_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    if (::posix_spawn(&pid_, argv[0], &actions, nullptr, argv.data(), environ) != 0) pid_ = -1;
    posix_spawn_file_actions_destroy(&actions);
  }
  ~CliProcess() {
    if (pid_ > 0 && !done_) {
      ::kill(pid_, SIGKILL);
      ::waitpid(pid_, nullptr, 0);
    }
  }
  bool started() const { return pid_ > 0; }
  std::string out() const { return slurp(out_path_); }
  std::string err() const { return slurp(err_path_); }

  // Waits for the exit, at most `patience` (a hang guard): the exit status, 128 + signal when a
  // signal ended it, or -1 when it hung (it is then killed).
  int wait(std::chrono::milliseconds patience) {
    const int pidfd = static_cast<int>(::syscall(SYS_pidfd_open, pid_, 0));
    if (pidfd >= 0) {
      pollfd fd{pidfd, POLLIN, 0};
      const int ready = ::poll(&fd, 1, static_cast<int>(patience.count()));
      ::close(pidfd);
      if (ready == 0) {
        ::kill(pid_, SIGKILL);
        ::waitpid(pid_, nullptr, 0);
        done_ = true;
        return -1;
      }
    }
    int status = 0;
    ::waitpid(pid_, &status, 0);
    done_ = true;
    return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
  }

 private:
  std::string out_path_, err_path_;
  pid_t pid_ = -1;
  bool done_ = false;
};

}  // namespace ydscope::test
