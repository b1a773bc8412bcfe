#pragma once
// Runs one of the built programs as a user would from a shell, capturing stdout, stderr and the
// exit status. The one runner every suite uses (the CLI's tests through cli_run_support.h).
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace ydscope::test {

struct ProgramRun {
  int status = -1;  // exit status, or -1 when the program did not exit normally
  std::string out;
  std::string err;  // empty when folded into `out`
};

struct RunOptions {
  bool fold_stderr = false;      // both streams in `out`, in the order they were written
  bool stdin_from_null = false;  // never waits for a terminal (leave off when `arguments` redirects stdin)
  std::string working_dir{};     // where it runs (empty: here)
  std::string config_home{};     // XDG_CONFIG_HOME for it (empty: inherited)
};

// `arguments` is shell text (quote paths yourself); the program's path is quoted here.
inline ProgramRun run_program(const std::string& program, const std::string& arguments,
                              const RunOptions& options = {}) {
  static std::atomic<int> serial{0};
  const std::filesystem::path err_path =
      std::filesystem::temp_directory_path() /
      ("ydscope-run-" + std::to_string(::getpid()) + "-" + std::to_string(serial++) + ".err");
  std::string command;
  if (!options.working_dir.empty()) command += "cd '" + options.working_dir + "' && ";
  if (!options.config_home.empty()) command += "XDG_CONFIG_HOME='" + options.config_home + "' ";
  command += "'" + program + "' " + arguments;
  command += options.fold_stderr ? " 2>&1" : " 2>'" + err_path.string() + "'";
  if (options.stdin_from_null) command += " </dev/null";
  ProgramRun run;
  std::FILE* pipe = ::popen(command.c_str(), "r");
  if (!pipe) return run;
  char buffer[65536];
  std::size_t got = 0;
  while ((got = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) run.out.append(buffer, got);
  const int status = ::pclose(pipe);
  run.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  if (!options.fold_stderr) {
    std::ifstream err(err_path, std::ios::binary);
    run.err.assign(std::istreambuf_iterator<char>(err), {});
    std::filesystem::remove(err_path);
  }
  return run;
}

}  // namespace ydscope::test
