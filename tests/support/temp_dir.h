#pragma once
// A fresh directory of the test's own under the system's temporary folder, removed with
// everything in it when the test ends: tests that run at once (ctest -j) never share a path.
#include <stdlib.h>

#include <filesystem>
#include <string>
#include <system_error>

namespace ydscope::test {

class TempDir {
 public:
  // `tag` names the directory (ydscope-TAG-XXXXXX), so one left by a crashed test says whose it is.
  explicit TempDir(const std::string& tag = "test") {
    std::string pattern = (std::filesystem::temp_directory_path() / ("ydscope-" + tag + "-XXXXXX")).string();
    if (::mkdtemp(pattern.data()) == nullptr)
      throw std::filesystem::filesystem_error("mkdtemp", pattern, std::error_code(errno, std::generic_category()));
    path_ = pattern;
  }
  ~TempDir() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;

  const std::filesystem::path& path() const { return path_; }
  std::string string() const { return path_.string(); }
  std::filesystem::path operator/(const std::string& name) const { return path_ / name; }
  // A path inside it, as text for a command line or an API taking strings.
  std::string file(const std::string& name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};

}  // namespace ydscope::test
