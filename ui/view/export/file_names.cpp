#include "ui/view/export/file_names.h"

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

RecordingPaths recording_paths(RecordFormat format, const std::string& typed, const std::filesystem::path& dir) {
  const bool ydrec = format != RecordFormat::Mcap, mcap = format != RecordFormat::Ydrec;
  RecordingPaths paths;
  if (typed.empty()) {
    if (ydrec) paths.ydrec = timestamped_name("ydrec", dir);
    if (mcap) paths.mcap = timestamped_name("mcap", dir);
    return paths;
  }
  if (!(ydrec && mcap)) {
    (ydrec ? paths.ydrec : paths.mcap) = typed;
    return paths;
  }
  std::filesystem::path name(typed);
  paths.ydrec = name.extension() == ".mcap" ? std::filesystem::path(name).replace_extension(".ydrec").string() : typed;
  paths.mcap = name.replace_extension(".mcap").string();
  return paths;
}

}  // namespace ydscope::ui
