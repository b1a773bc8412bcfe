#pragma once
// Test helper: runs ydscope-cli as a user would from a shell, with stdout and stderr apart or
// folded together.
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace ydscope::test {

struct CliResult {
  int status = -1;  // exit status, -1 when killed by a signal
  std::string out;
  std::string err;
};

// Runs a shell command line, keeping its stdout in `out` and its exit status.
inline CliResult run_shell(const std::string& command) {
  CliResult result;
  std::FILE* pipe = ::popen(command.c_str(), "r");
  if (!pipe) return result;
  char buffer[65536];
  std::size_t got = 0;
  while ((got = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) result.out.append(buffer, got);
  const int status = ::pclose(pipe);
  result.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

// `arguments` goes through the shell: quote paths with spaces.
inline CliResult run_cli_apart(const std::string& arguments) {
  const auto err_path = std::filesystem::temp_directory_path() / ("ydscope-cli-err-" + std::to_string(::getpid()));
  CliResult result =
      run_shell(std::string("'") + YDSCOPE_CLI_PATH + "' " + arguments + " 2>'" + err_path.string() + "'");
  std::ifstream err(err_path, std::ios::binary);
  result.err.assign(std::istreambuf_iterator<char>(err), {});
  std::filesystem::remove(err_path);
  return result;
}

// Both streams in `out`, in the order they were written (err stays empty).
inline CliResult run_cli(const std::string& arguments) {
  return run_shell(std::string("'") + YDSCOPE_CLI_PATH + "' " + arguments + " 2>&1");
}

// How many times `what` occurs in `text` (overlaps counted): lines of a program's output, say.
inline std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (std::size_t at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

}  // namespace ydscope::test
