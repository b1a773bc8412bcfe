#pragma once
// Test helper: runs ydscope-cli as a user would from a shell (support/program_run.h), with stdout
// and stderr apart or folded together.
#include <cstddef>
#include <string>

#include "support/program_run.h"

namespace ydscope::test {

using CliResult = ProgramRun;

// `arguments` goes through the shell: quote paths with spaces.
inline CliResult run_cli_apart(const std::string& arguments) { return run_program(YDSCOPE_CLI_PATH, arguments); }

// Both streams in `out`, in the order they were written (err stays empty).
inline CliResult run_cli(const std::string& arguments) {
  RunOptions options;
  options.fold_stderr = true;
  return run_program(YDSCOPE_CLI_PATH, arguments, options);
}

// How many times `what` occurs in `text` (overlaps counted): lines of a program's output, say.
inline std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

}  // namespace ydscope::test
