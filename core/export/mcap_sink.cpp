#include "core/export/mcap_sink.h"

#include <cerrno>
#include <cstring>

namespace ydscope {

std::unique_ptr<McapFileSink> McapFileSink::create(const std::string& path, std::string& error) {
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (!file) {
    error = "cannot create " + path + ": " + std::strerror(errno);
    return nullptr;
  }
  return std::unique_ptr<McapFileSink>(new McapFileSink(file, path));
}

McapFileSink::~McapFileSink() { close(); }

void McapFileSink::fail(const char* what) {
  if (error_.empty()) error_ = std::string(what) + " " + path_ + " failed: " + std::strerror(errno);
}

bool McapFileSink::write(std::span<const std::uint8_t> bytes) {
  if (!file_ || !error_.empty()) return false;
  if (std::fwrite(bytes.data(), 1, bytes.size(), file_) != bytes.size()) fail("writing");
  return error_.empty();
}

bool McapFileSink::flush() {
  if (!file_ || !error_.empty()) return false;
  if (std::fflush(file_) != 0) fail("writing");
  return error_.empty();
}

bool McapFileSink::close() {
  if (!file_) return error_.empty();
  if (std::fclose(file_) != 0) fail("closing");
  file_ = nullptr;
  return error_.empty();
}

}  // namespace ydscope
