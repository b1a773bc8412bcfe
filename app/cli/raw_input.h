#pragma once
// Raw lidar bytes for decode: a file, standard input ("-"), a FIFO or a device. A regular file
// reads at once; the others may wait for a writer, and a FIFO nobody writes to once blocked
// without a word. So after kWaitNotice without a byte the wait is said on stderr, once per wait:
// "waiting for bytes from FIFO /tmp/lidar (none for 1 s; ...)".
#include <chrono>
#include <cstdint>
#include <span>
#include <string>

#include "core/protocol/function_ref.h"

namespace ydscope::cli {

inline constexpr std::chrono::milliseconds kWaitNotice{1000};

class RawInput {
 public:
  // Checks the input before anything else is, so a missing file or a folder is what the user
  // hears about (not a missing --model): UsageError when it does not exist, std::runtime_error
  // when it is a folder or a regular file that cannot be opened. `program` prefixes the notice.
  RawInput(const std::string& path, std::string program);
  ~RawInput();
  RawInput(const RawInput&) = delete;
  RawInput& operator=(const RawInput&) = delete;

  // Calls on_chunk for every chunk, in order, until the end of the input (a FIFO or device is
  // opened here, under the notice, as its open waits for a writer). Throws std::runtime_error
  // when reading fails.
  void read(FunctionRef<void(std::span<const std::uint8_t>)> on_chunk);
  // A regular file: it can be read twice (decode --mcap) and never waits.
  bool regular() const { return regular_; }

 private:
  std::string path_;
  std::string program_;
  std::string what_;  // "FIFO /tmp/lidar", "standard input", "device /dev/zero"
  bool regular_ = false;
  int fd_ = -1;
};

}  // namespace ydscope::cli
