#include "ui/view/file_names.h"

#include <unistd.h>

#include <cstdlib>

namespace ydscope::ui {

std::string timestamped_name_at(std::time_t when, const char* extension, const std::filesystem::path& dir) {
  char stamp[32];
  std::tm local{};
  localtime_r(&when, &local);
  std::strftime(stamp, sizeof stamp, "%Y%m%d-%H%M%S", &local);
  const std::string base = std::string("ydscope-") + stamp;
  std::error_code ec;
  for (int n = 1;; ++n) {
    const std::string name = base + (n > 1 ? "-" + std::to_string(n) : std::string()) + "." + extension;
    const std::filesystem::path path = dir.empty() ? std::filesystem::path(name) : dir / name;
    if (!std::filesystem::exists(path, ec) || n >= 1000) return path.string();
  }
}

std::string timestamped_name(const char* extension, const std::filesystem::path& dir) {
  std::filesystem::path where = dir;
  if (where.empty() && access(".", W_OK) != 0) {
    if (const char* home = std::getenv("HOME")) where = home;
  }
  return timestamped_name_at(std::time(nullptr), extension, where);
}

}  // namespace ydscope::ui
