#pragma once
// Test helper: runs ydscope-cli as a user would from a shell (support/program_run.h), with stdout
// and stderr apart or folded together.
#include <cstddef>
#include <string>
#include <vector>

#include <unistd.h>

#include "support/program_run.h"

namespace ydscope::test {

using CliResult = ProgramRun;

// `arguments` goes through the shell: quote paths with spaces.
inline CliResult run_cli_apart(const std::string& arguments) { return run_program(YDSCOPE_CLI_PATH, arguments); }

// As run_cli_apart, but killed after 20 s: for a command that could otherwise wait for ever.
inline CliResult run_cli_bounded(const std::string& arguments) {
  return run_program("timeout", "20 '" YDSCOPE_CLI_PATH "' " + arguments);
}

// Both streams in `out`, in the order they were written (err stays empty).
inline CliResult run_cli(const std::string& arguments) {
  RunOptions options;
  options.fold_stderr = true;
  return run_program(YDSCOPE_CLI_PATH, arguments, options);
}

// ydscope-cli started apart, its stdout on a pipe the test reads (and may close, as `head` does);
// the test signals and reaps the child itself. pid -1 when it could not be started.
struct StartedCli {
  pid_t pid = -1;
  int out_fd = -1;  // the pipe's read end
};
inline StartedCli start_cli(const std::vector<std::string>& arguments) {
  int out_pipe[2];
  if (pipe(out_pipe) != 0) return {};
  const pid_t child = fork();
  if (child == 0) {
    dup2(out_pipe[1], STDOUT_FILENO);
    close(out_pipe[0]);
    close(out_pipe[1]);
    std::vector<char*> argv{const_cast<char*>(YDSCOPE_CLI_PATH)};
    for (const std::string& a : arguments) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    execv(YDSCOPE_CLI_PATH, argv.data());
    _exit(127);
  }
  close(out_pipe[1]);
  if (child < 0) {
    close(out_pipe[0]);
    return {};
  }
  return {child, out_pipe[0]};
}

// How many times `what` occurs in `text` (overlaps counted): lines of a program's output, say.
inline std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

}  // namespace ydscope::test
