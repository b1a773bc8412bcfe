#pragma once
// Runs one of the built programs as a user would, capturing stdout, stderr and the exit status.
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

namespace ydscope::test {

struct ProgramRun {
  int status = -1;  // exit status, or -1 when the program did not exit normally
  std::string out;
  std::string err;
};

// `arguments` is shell text (quote paths yourself); the program's path is quoted here.
inline ProgramRun run_program(const std::string& program, const std::string& arguments) {
  static int serial = 0;
  const std::filesystem::path err_path = std::filesystem::temp_directory_path() /
      ("ydscope_app_test_" + std::to_string(getpid()) + "_" + std::to_string(serial++) + ".err");
  const std::string command = "'" + program + "' " + arguments + " 2>'" + err_path.string() + "' </dev/null";
  ProgramRun run;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return run;
  char buffer[4096];
  std::size_t got;
  while ((got = std::fread(buffer, 1, sizeof buffer, pipe)) > 0) run.out.append(buffer, got);
  const int status = pclose(pipe);
  run.status = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  std::ifstream in(err_path);
  std::stringstream text;
  text << in.rdbuf();
  run.err = text.str();
  std::filesystem::remove(err_path);
  return run;
}

}  // namespace ydscope::test
