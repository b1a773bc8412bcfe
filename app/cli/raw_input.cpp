#include "app/cli/raw_input.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <condition_variable>
#include <cstdio>
#include <cstring>
#include <mutex>
#include <stdexcept>
#include <thread>
#include <vector>

#include "app/common/arguments.h"

namespace ydscope::cli {
namespace {

constexpr std::size_t kReadChunk = 1 << 20;

// Says `line` on stderr when a wait (waiting() .. arrived()) lasts kWaitNotice, once per wait. A
// thread of its own: the wait is a blocking open() or read() the main thread cannot leave.
class WaitNotice {
 public:
  explicit WaitNotice(std::string line) : line_(std::move(line)), thread_([this] { run(); }) {}
  ~WaitNotice() {
    {
      std::lock_guard lock(mutex_);
      done_ = true;
    }
    wake_.notify_all();
    thread_.join();
  }
  void waiting() {
    std::lock_guard lock(mutex_);
    waiting_ = true;
    said_ = false;
    since_ = std::chrono::steady_clock::now();
    wake_.notify_all();
  }
  void arrived() {
    std::lock_guard lock(mutex_);
    waiting_ = false;
  }

 private:
  void run() {
    std::unique_lock lock(mutex_);
    while (!done_) {
      if (!waiting_ || said_) {
        wake_.wait(lock);
        continue;
      }
      const auto due = since_ + kWaitNotice;
      wake_.wait_until(lock, due, [&] { return done_ || !waiting_ || since_ + kWaitNotice != due; });
      if (!done_ && waiting_ && !said_ && std::chrono::steady_clock::now() >= since_ + kWaitNotice) {
        std::fprintf(stderr, "%s\n", line_.c_str());
        std::fflush(stderr);
        said_ = true;
      }
    }
  }

  std::string line_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool done_ = false;
  bool waiting_ = false;
  bool said_ = false;
  std::chrono::steady_clock::time_point since_;
  std::thread thread_;  // last: starts once the state above exists
};

}  // namespace

RawInput::RawInput(const std::string& path, std::string program) : path_(path), program_(std::move(program)) {
  if (path == "-") {
    fd_ = STDIN_FILENO;
    what_ = "standard input";
    struct stat info {};
    regular_ = ::fstat(fd_, &info) == 0 && S_ISREG(info.st_mode);
    return;
  }
  require_existing_file(path, "input file");
  struct stat info {};
  if (::stat(path.c_str(), &info) != 0) throw std::runtime_error("cannot open '" + path + "': " + std::strerror(errno));
  if (S_ISDIR(info.st_mode))
    throw std::runtime_error("'" + path + "' is a folder; pass a file or - for standard input");
  regular_ = S_ISREG(info.st_mode);
  what_ = (S_ISFIFO(info.st_mode) ? "FIFO " : S_ISSOCK(info.st_mode) ? "socket " : "device ") + path;
  if (!regular_) return;  // opened in read(): opening a FIFO waits for its writer
  fd_ = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd_ < 0) throw std::runtime_error("cannot open '" + path + "': " + std::strerror(errno));
}

RawInput::~RawInput() {
  if (fd_ >= 0 && fd_ != STDIN_FILENO) ::close(fd_);
}

void RawInput::read(FunctionRef<void(std::span<const std::uint8_t>)> on_chunk) {
  WaitNotice notice(program_ + ": waiting for bytes from " + what_ + " (none for " +
                    std::to_string(kWaitNotice.count() / 1000) + " s); is the program that writes them running?");
  if (fd_ < 0) {
    notice.waiting();
    fd_ = ::open(path_.c_str(), O_RDONLY | O_CLOEXEC);
    if (fd_ < 0) throw std::runtime_error("cannot open '" + path_ + "': " + std::strerror(errno));
  }
  std::vector<std::uint8_t> buffer(kReadChunk);
  for (;;) {
    if (!regular_) notice.waiting();
    const ssize_t got = ::read(fd_, buffer.data(), buffer.size());
    notice.arrived();
    if (got < 0 && errno == EINTR) continue;
    if (got < 0) throw std::runtime_error("reading '" + path_ + "' failed: " + std::strerror(errno));
    if (got == 0) return;
    on_chunk({buffer.data(), static_cast<std::size_t>(got)});
  }
}

}  // namespace ydscope::cli
