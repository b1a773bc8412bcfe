#pragma once
// Where the test data lives. CTest hands the folders over in the environment (tests/CMakeLists.txt)
// rather than baking paths in at compile time, so a built test program can be pointed elsewhere.
#include <cstdlib>
#include <filesystem>
#include <stdexcept>
#include <string>

namespace ydscope::test {

inline std::filesystem::path folder_from_environment(const char* variable) {
  const char* value = std::getenv(variable);
  if (!value || !*value)
    throw std::runtime_error(std::string(variable) + " is not set: run the tests through ctest, or set it by hand");
  return value;
}

// Real device bytes: tests/data/captures.
inline std::filesystem::path captures_dir() { return folder_from_environment("YDSCOPE_CAPTURES_DIR"); }

// The committed assets (demo recording, icon, desktop entry): assets/.
inline std::filesystem::path assets_dir() { return folder_from_environment("YDSCOPE_ASSETS_DIR"); }

}  // namespace ydscope::test
