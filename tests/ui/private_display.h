#pragma once
// An X server of the test's own. The suite's tests share one Xvfb (xvfb-run around ctest) and run
// two at a time; without a window manager every app window sits at 0,0, so a test that moves the
// pointer or types to "the ydscope window" could reach another test's app. A test that uses
// X11Hands starts its own Xvfb and points DISPLAY at it (for itself and the app it spawns).
#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <string>
#include <vector>

extern char** environ;

namespace ydscope::test {

class PrivateDisplay {
 public:
  explicit PrivateDisplay(const std::string& screen = "1280x800x24") {
    int fds[2];
    if (::pipe(fds) != 0) return;
    // Xvfb writes the display number it chose to -displayfd once it accepts connections.
    const std::string fd = std::to_string(fds[1]);
    std::vector<std::string> args{"Xvfb", "-displayfd", fd, "-screen", "0", screen, "-nolisten", "tcp"};
    std::vector<char*> argv;
    for (auto& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    posix_spawn_file_actions_t actions;
    posix_spawn_file_actions_init(&actions);
    posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addclose(&actions, fds[0]);
    if (::posix_spawnp(&pid_, "Xvfb", &actions, nullptr, argv.data(), environ) != 0) pid_ = -1;
    posix_spawn_file_actions_destroy(&actions);
    ::close(fds[1]);
    std::string number;
    char c = 0;
    while (pid_ > 0 && ::read(fds[0], &c, 1) == 1 && c != '\n') number += c;
    ::close(fds[0]);
    if (number.empty()) return;
    if (const char* old = std::getenv("DISPLAY")) previous_ = old;
    ::setenv("DISPLAY", (":" + number).c_str(), 1);
    ready_ = true;
  }
  ~PrivateDisplay() {
    if (ready_) {
      if (previous_.empty())
        ::unsetenv("DISPLAY");
      else
        ::setenv("DISPLAY", previous_.c_str(), 1);
    }
    if (pid_ > 0) {
      ::kill(pid_, SIGTERM);
      ::waitpid(pid_, nullptr, 0);
    }
  }
  PrivateDisplay(const PrivateDisplay&) = delete;
  PrivateDisplay& operator=(const PrivateDisplay&) = delete;
  explicit operator bool() const { return ready_; }

 private:
  pid_t pid_ = -1;
  bool ready_ = false;
  std::string previous_;
};

}  // namespace ydscope::test
