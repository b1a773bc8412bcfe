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

// What the Record tab writes: every byte as .ydrec, the live topics as MCAP, or both at once.
enum class RecordFormat { Ydrec, Mcap, Both };
struct RecordingPaths {
  std::string ydrec;  // empty: not written
  std::string mcap;
};
// Where a recording in `format` goes. `typed` (the Record tab's field) names the file; with both,
// the MCAP is the same name with .mcap for its extension (and the .ydrec keeps its own, or takes
// .ydrec when .mcap was typed). Empty `typed`: timestamped names in `dir`.
RecordingPaths recording_paths(RecordFormat format, const std::string& typed, const std::filesystem::path& dir = {});

}  // namespace ydscope::ui
