#pragma once
// What the app saves in one go (screenshots, exports) appears whole or not at all: it is written
// under a ".part" name beside the final one and renamed once complete, so a program watching the
// folder (a sync tool, a script, a test) never reads half of a file, and a failed save leaves no
// broken file behind.
#include <string>

namespace ydscope::ui {

// The name to write while saving `path`.
std::string part_name(const std::string& path);
// After writing part_name(path): with `error` empty the part becomes `path` (empty, or the
// sentence of why the rename failed); otherwise the part is removed and `error` returned, with
// the part's name in it replaced by `path` (the user knows the file by that name only).
std::string finish_whole_file(const std::string& path, std::string error);

}  // namespace ydscope::ui
