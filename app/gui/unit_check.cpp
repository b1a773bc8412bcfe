#include "app/gui/unit_check.h"

#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>

#include "app/common/check_report.h"
#include "core/analysis/text_format.h"

extern char** environ;

namespace ydscope::gui {

namespace {

// Whether `program` is an executable somewhere on PATH.
bool on_path(const std::string& program) {
  const char* path = std::getenv("PATH");
  if (!path) return false;
  std::string folders = path;
  for (std::size_t start = 0; start <= folders.size();) {
    const std::size_t end = std::min(folders.find(':', start), folders.size());
    const std::string candidate = (std::filesystem::path(folders.substr(start, end - start)) / program).string();
    if (end > start && ::access(candidate.c_str(), X_OK) == 0) return true;
    start = end + 1;
  }
  return false;
}

// Hands the report to the desktop's browser; says what happened in a few words.
std::string open_report(const std::string& path) {
  if (!on_path("xdg-open")) return "there is no xdg-open here: open the report from the path above";
  pid_t child = -1;
  const char* argv[] = {"xdg-open", path.c_str(), nullptr};
  if (::posix_spawnp(&child, "xdg-open", nullptr, nullptr, const_cast<char* const*>(argv), environ) != 0)
    return "xdg-open did not start: open the report from the path above";
  // xdg-open hands over to the browser and returns; reaping it here leaves no zombie behind.
  int status = 0;
  ::waitpid(child, &status, 0);
  return WIFEXITED(status) && WEXITSTATUS(status) == 0 ? "opened with xdg-open"
                                                       : "xdg-open could not open it: open it from the path above";
}

std::string login_name() {
  const char* user = std::getenv("USER");
  return user ? user : "";
}

std::string host_name() {
  char name[256] = {};
  return ::gethostname(name, sizeof name - 1) == 0 ? name : "";
}

}  // namespace

std::string report_folder() {
  if (::access(".", W_OK) == 0) return std::filesystem::current_path().string();
  const char* home = std::getenv("HOME");
  return home ? home : ".";
}

std::string equivalent_check_command(const SessionConfig& config) {
  std::string line = "ydscope-cli check --port " + config.address;
  if (config.model) line += " --model " + std::string(profile_for(*config.model).name);
  if (config.baud) line += " --baud " + std::to_string(*config.baud);
  return line + " (run from the ydscope app's Lidar tab)";
}

UnitCheck::~UnitCheck() {
  stop_.store(true);
  if (thread_.joinable()) thread_.join();
}

bool UnitCheck::running() const {
  std::lock_guard lock(mutex_);
  return view_.state == ui::UnitCheckView::State::Running;
}

ui::UnitCheckView UnitCheck::view() const {
  std::lock_guard lock(mutex_);
  return view_;
}

void UnitCheck::set(const std::function<void(ui::UnitCheckView&)>& change) {
  std::lock_guard lock(mutex_);
  change(view_);
}

void UnitCheck::start(Session& session, const SessionConfig& config, const std::string& report_folder) {
  if (running()) return;
  if (thread_.joinable()) thread_.join();  // the last run has finished
  set([](ui::UnitCheckView& v) {
    v = {};
    v.state = ui::UnitCheckView::State::Running;
    v.progress = "letting go of the port ...";
  });
  stop_.store(false);
  thread_ = std::thread([this, &session, config, report_folder] { run(session, config, report_folder); });
}

void UnitCheck::run(Session& session, SessionConfig config, std::string report_folder) {
  // The session gives the port up first: a serial port is opened by one program at a time.
  session.disconnect();
  session.wait_until(
      [](const SessionSnapshot& s) { return s.state == LinkState::Idle || s.state == LinkState::Failed; },
      std::chrono::seconds(5));
  CheckPlan plan;
  plan.session = config;
  plan.session.scan = true;
  plan.session.reconnect = false;  // a check reports a fault instead of waiting it out
  plan.context = {equivalent_check_command(config), login_name(), host_name()};
  plan.progress = [this](const std::string& line) { set([&line](ui::UnitCheckView& v) { v.progress = line; }); };
  ui::UnitCheckView done;
  done.state = ui::UnitCheckView::State::Done;
  try {
    const CheckRecord record = run_check(plan, stop_);
    const CheckOutcome outcome = check_outcome(record);
    done.verdict = outcome == CheckOutcome::Pass ? "PASS" : outcome == CheckOutcome::Fail ? "FAIL" : "INCOMPLETE";
    const ModelProfile* profile = record.observations.profile;
    std::string unit = profile ? std::string(profile->name) : "lidar";
    if (record.started.device) unit += " " + record.started.device->serial;
    std::size_t failed = 0;
    for (const CriterionResult& r : record.results) {
      if (r.verdict == Verdict::Pass) continue;
      ++failed;
      done.failures.push_back(r.title + ": " + r.measured + " (limit: " + r.limit + ")");
    }
    done.summary = outcome == CheckOutcome::Incomplete ? unit + ": " + incomplete_reason(record)
                   : failed == 0
                       ? format_text("%s: all %zu criteria passed", unit.c_str(), record.results.size())
                       : format_text("%s: %zu of %zu criteria failed", unit.c_str(), failed, record.results.size());
    try {
      done.report = check_report_path(report_folder, record);
      write_check_report(done.report, record);
      // A run cut short because the source changed or the app is closing opens nothing.
      if (!stop_.load()) done.report_note = open_report(done.report);
    } catch (const std::exception& e) {
      done.report.clear();
      done.report_note = std::string("the report was not written: ") + e.what();
    }
  } catch (const std::exception& e) {  // the unit failed before anything was measured
    done.verdict = "INCOMPLETE";
    done.summary = std::string("the check did not run: ") + e.what();
  }
  // The lidar back in the view, as it was before the check.
  if (!stop_.load()) session.connect(config);
  set([&done](ui::UnitCheckView& v) { v = std::move(done); });
}

}  // namespace ydscope::gui
