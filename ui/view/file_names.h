#pragma once
// Names for what the app saves (screenshots, CSV exports, recordings): timestamped, and never the
// name of a file that is already there, so nothing the user saved earlier is overwritten.
#include <ctime>
#include <filesystem>
#include <string>

namespace ydscope::ui {

// "<dir>/ydscope-20261122-021500.<extension>", or "...-021500-2.<extension>" (and on) when that
// file exists. `dir` empty: the current directory, or $HOME when that is not writable.
std::string timestamped_name(const char* extension, const std::filesystem::path& dir = {});
// The same for a given time, for tests.
std::string timestamped_name_at(std::time_t when, const char* extension, const std::filesystem::path& dir);

}  // namespace ydscope::ui
