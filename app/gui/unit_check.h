#pragma once
// The app's "Run check" (Lidar tab): the acceptance check of `ydscope-cli check`, the same code
// (app/common/check_run.h), run on the selected lidar on a thread of its own so the window keeps
// drawing. The lidar's session lets go of the port for the run and takes it back afterwards; the
// report is written under the unit's serial and time, as a test station names it, and opened with
// xdg-open where there is one.
#include <atomic>
#include <mutex>
#include <string>
#include <thread>

#include "app/common/check_run.h"
#include "core/session/session.h"
#include "ui/view/status/unit_check_view.h"

namespace ydscope::gui {

class UnitCheck {
 public:
  UnitCheck() = default;
  ~UnitCheck();  // a run still going is cut short (as Ctrl-C cuts the CLI's) and waited for
  UnitCheck(const UnitCheck&) = delete;
  UnitCheck& operator=(const UnitCheck&) = delete;

  // Checks the unit `session` reads with `config` (its port, model, baud), writing the report into
  // `report_folder`. Nothing happens while a run is going.
  void start(Session& session, const SessionConfig& config, const std::string& report_folder);
  bool running() const;
  // The source changed: a run going is cut short (its report says INCOMPLETE) and does not take
  // the port back. Returns at once; the run ends on its thread.
  void abandon() { stop_.store(true); }
  // Progress while running, then the verdict; `available` is the caller's to set.
  ui::UnitCheckView view() const;

 private:
  void run(Session& session, SessionConfig config, std::string report_folder);
  void set(const std::function<void(ui::UnitCheckView&)>& change);

  mutable std::mutex mutex_;
  ui::UnitCheckView view_;
  std::atomic<bool> stop_{false};
  std::thread thread_;
};

// Where the app's reports go: the current folder, or $HOME when that cannot be written, as the
// app's other saved files (ui/view/export/file_names.h).
std::string report_folder();

// The equivalent `ydscope-cli check` command line for the report: the same unit and settings.
std::string equivalent_check_command(const SessionConfig& config);

}  // namespace ydscope::gui
