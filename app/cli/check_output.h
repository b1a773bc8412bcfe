#pragma once
// How `ydscope-cli check` tells its verdict: one text line per criterion, or one JSON object for
// scripts (schema in `ydscope-cli check --help`); for several lidars checked at once, each unit's
// verdict under its name, then the set's.
#include <cstdio>
#include <string>
#include <vector>

#include "app/common/check_run.h"

namespace ydscope::cli {

void print_check_text(std::FILE* out, const CheckRecord& record);
void print_check_json(std::FILE* out, const CheckRecord& record);

// "G6 0471655879731342": the unit's model and serial as read ("lidar" and none when not read).
std::string unit_name(const CheckRecord& record);

// One lidar of a check of several (check_set.h).
struct UnitCheck {
  std::string name;     // --name, else lidar0, lidar1, ... in --port order
  std::string port;     // as given
  bool tested = false;  // false: it failed before measuring; record.failure says why
  CheckRecord record;
  std::string report;  // the report written for it; empty: none
};

// Fail when any unit failed, else incomplete when any was not judged to the end, else pass.
CheckOutcome set_outcome(const std::vector<UnitCheck>& units);
void print_check_set_text(std::FILE* out, const std::vector<UnitCheck>& units);
void print_check_set_json(std::FILE* out, const std::vector<UnitCheck>& units);

}  // namespace ydscope::cli
