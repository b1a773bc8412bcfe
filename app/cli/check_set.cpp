#include "app/cli/check_set.h"

#include <cstdio>
#include <exception>
#include <thread>

#include "app/cli/check_output.h"
#include "app/cli/cli_command.h"
#include "app/common/arguments.h"
#include "app/common/check_report.h"

namespace ydscope::cli {
namespace {

// Each unit's run on its own thread; a unit that fails before measuring keeps the sentence why.
std::vector<UnitCheck> check_all(const CheckSetPlan& plan, const std::atomic<bool>& stop) {
  std::vector<UnitCheck> units(plan.lidars.size());
  std::vector<std::exception_ptr> usage(plan.lidars.size());
  std::vector<std::thread> runs;
  for (std::size_t i = 0; i < plan.lidars.size(); ++i) {
    units[i].name = plan.lidars[i].info.name;
    units[i].port = plan.lidars[i].config.address;
    CheckPlan check = plan.check;
    check.session = plan.lidars[i].config;
    check.progress = nullptr;  // the lines of several runs at once would overwrite one another
    if (plan.check.warning)
      check.warning = [warn = plan.check.warning, name = units[i].name](const std::string& text) {
        warn(name + ": " + text);
      };
    runs.emplace_back([&unit = units[i], &mistake = usage[i], check = std::move(check), &stop] {
      try {
        unit.record = run_check(check, stop);
        unit.tested = true;
      } catch (const UsageError&) {
        mistake = std::current_exception();
      } catch (const std::exception& e) {
        unit.record.failure = e.what();
      }
    });
  }
  for (std::thread& run : runs) run.join();
  for (const std::exception_ptr& mistake : usage)
    if (mistake) std::rethrow_exception(mistake);
  return units;
}

}  // namespace

int run_check_set(const CheckSetPlan& plan, const std::atomic<bool>& stop) {
  std::vector<UnitCheck> units = check_all(plan, stop);
  bool unwritten = false;
  if (plan.reports_folder)
    for (UnitCheck& unit : units) {
      if (!unit.tested) continue;
      const std::string path = check_report_path(*plan.reports_folder, unit.record);
      try {
        write_check_report(path, unit.record);
        unit.report = path;
      } catch (const std::exception& e) {
        std::fprintf(stderr, "ydscope-cli check: %s: %s\n", unit.name.c_str(), e.what());
        unwritten = true;
      }
    }
  if (plan.json)
    print_check_set_json(stdout, units);
  else
    print_check_set_text(stdout, units);
  std::fflush(stdout);

  bool interrupted = false, failed = unwritten;
  for (const UnitCheck& unit : units) {
    if (!unit.record.failure.empty()) {
      std::fprintf(stderr, "ydscope-cli check: %s: %s\n", unit.name.c_str(), unit.record.failure.c_str());
      failed = true;
    }
    interrupted = interrupted || unit.record.interrupted;
  }
  if (interrupted) {
    std::fprintf(stderr, "ydscope-cli check: interrupted after %.1f of %.1f s; the verdicts cover only that\n",
                 units.front().record.measured_seconds, plan.check.seconds);
    return kExitInterrupted;
  }
  if (failed) return kExitFailure;
  return set_outcome(units) == CheckOutcome::Pass ? kExitOk : kExitLidarFault;
}

}  // namespace ydscope::cli
