#pragma once
// What the Lidar tab shows of "Run check" (the acceptance check `ydscope-cli check` runs, run by
// the app on the selected lidar): nothing yet, its progress while it runs, then its verdict, the
// criteria that failed and where the report went. The app fills it; the panel only draws it.
#include <cstdint>
#include <string>
#include <vector>

namespace ydscope::ui {

struct UnitCheckView {
  enum class State : std::uint8_t { None, Running, Done };
  State state = State::None;
  bool available = false;             // the source is a lidar (a port or the virtual one), not a recording
  std::string progress;               // while running: "measuring: 2.0 of 10.0 s, ..."
  std::string verdict;                // when done: PASS, FAIL or INCOMPLETE (the CLI's words)
  std::string summary;                // "G6 0471655879731342: all 7 criteria passed"
  std::vector<std::string> failures;  // one line per failed criterion: "scan rate: 8.6 Hz ... (limit ...)"
  std::string report;                 // the report's path, empty when none was written
  std::string report_note;            // "opened in the browser", "xdg-open is not here: open it yourself", ...
};

}  // namespace ydscope::ui
