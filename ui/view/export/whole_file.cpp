#include "ui/view/export/whole_file.h"

#include <filesystem>
#include <system_error>

namespace ydscope::ui {

std::string part_name(const std::string& path) { return path + ".part"; }

std::string finish_whole_file(const std::string& path, std::string error) {
  std::error_code ec;
  if (error.empty()) {
    std::filesystem::rename(part_name(path), path, ec);
    if (!ec) return {};
    error = "could not name the finished file " + path + ": " + ec.message() + ".";
  }
  std::filesystem::remove(part_name(path), ec);
  // The user knows the file by its final name only.
  const std::string part = part_name(path);
  for (std::size_t at = error.find(part); at != std::string::npos; at = error.find(part, at + path.size()))
    error.replace(at, part.size(), path);
  return error;
}

}  // namespace ydscope::ui
