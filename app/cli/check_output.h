#pragma once
// How `ydscope-cli check` tells its verdict: one text line per criterion, or one JSON object for
// scripts (schema in `ydscope-cli check --help`).
#include <cstdio>

#include "app/common/check_run.h"

namespace ydscope::cli {

void print_check_text(std::FILE* out, const CheckRecord& record);
void print_check_json(std::FILE* out, const CheckRecord& record);

}  // namespace ydscope::cli
