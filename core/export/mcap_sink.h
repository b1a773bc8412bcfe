#pragma once
// Where an McapWriter's bytes go: a file (flushed to the kernel at every chunk, so a killed
// writer leaves its finished chunks readable) or memory (tests, fuzzing, the bridge).
#include <cstdint>
#include <cstdio>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace ydscope {

class McapSink {
 public:
  virtual ~McapSink() = default;
  // False plus error() once writing failed; later writes do nothing.
  virtual bool write(std::span<const std::uint8_t> bytes) = 0;
  virtual bool flush() = 0;
  virtual const std::string& error() const = 0;
};

class McapFileSink final : public McapSink {
 public:
  // Creates (or truncates) `path`; null plus a sentence in `error` when it cannot.
  static std::unique_ptr<McapFileSink> create(const std::string& path, std::string& error);
  ~McapFileSink() override;
  bool write(std::span<const std::uint8_t> bytes) override;
  bool flush() override;
  // Flushes and closes; false (with error()) if that failed.
  bool close();
  const std::string& error() const override { return error_; }

 private:
  McapFileSink(std::FILE* file, std::string path) : file_(file), path_(std::move(path)) {}
  void fail(const char* what);
  std::FILE* file_;
  std::string path_;
  std::string error_;
};

class McapMemorySink final : public McapSink {
 public:
  bool write(std::span<const std::uint8_t> bytes) override {
    bytes_.insert(bytes_.end(), bytes.begin(), bytes.end());
    return true;
  }
  bool flush() override { return true; }
  const std::string& error() const override { return error_; }
  const std::vector<std::uint8_t>& bytes() const { return bytes_; }

 private:
  std::vector<std::uint8_t> bytes_;
  std::string error_;
};

}  // namespace ydscope
