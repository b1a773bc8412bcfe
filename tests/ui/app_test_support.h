#pragma once
// Shared by the tests that run the real app under the display CTest provides (xvfb-run): decoding
// its PNGs, telling scan points from text, and starting it (or the virtual lidar) as a process.
#include <signal.h>
#include <stb_image.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <memory>
#include <set>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include <gtest/gtest.h>

namespace ydscope::test {

// The polar view starts right of the panels (about 430 px of a 1280 px window).
inline constexpr int kViewLeft = 448;

struct Image {
  int width = 0;
  int height = 0;
  std::unique_ptr<unsigned char, void (*)(void*)> pixels{nullptr, stbi_image_free};
  const unsigned char* at(int x, int y) const { return pixels.get() + (static_cast<std::size_t>(y) * width + x) * 3; }
  explicit operator bool() const { return pixels != nullptr; }
};

inline Image load_png(const std::string& path) {
  Image image;
  int channels = 0;
  image.pixels.reset(stbi_load(path.c_str(), &image.width, &image.height, &channels, 3));
  return image;
}

// A saturated, bright pixel: a scan point (the grid, the panels and the overlay are greys, whites
// and dim blues).
inline bool is_point_pixel(const unsigned char* p) {
  const int hi = std::max({p[0], p[1], p[2]});
  const int lo = std::min({p[0], p[1], p[2]});
  return hi > 140 && hi - lo > 70;
}
inline bool is_text_pixel(const unsigned char* p) { return p[0] > 150 && p[1] > 150 && p[2] > 150; }
// The overlay's words are near-white; nothing in a live scan is.
inline bool is_white_pixel(const unsigned char* p) { return p[0] > 215 && p[1] > 215 && p[2] > 215; }

struct Rect {
  int x0, y0, x1, y1;  // half-open
};

template <class Predicate>
int count_pixels(const Image& image, Rect r, Predicate predicate) {
  int n = 0;
  for (int y = std::max(r.y0, 0); y < std::min(r.y1, image.height); ++y)
    for (int x = std::max(r.x0, 0); x < std::min(r.x1, image.width); ++x) n += predicate(image.at(x, y)) ? 1 : 0;
  return n;
}

// Scan points inside the disc of rings around the view's centre (the view is right of the panels).
inline int points_in_rings(const Image& image, int view_left) {
  const int cx = (view_left + image.width) / 2;
  const int cy = image.height / 2;
  const int radius = std::min(image.width - view_left, image.height) / 2;
  int points = 0;
  for (int y = 0; y < image.height; ++y) {
    for (int x = view_left; x < image.width; ++x) {
      const int dx = x - cx;
      const int dy = y - cy;
      if (dx * dx + dy * dy <= radius * radius) points += is_point_pixel(image.at(x, y));
    }
  }
  return points;
}

inline std::filesystem::path fresh_temp_dir(const std::string& name) {
  const std::filesystem::path dir = std::filesystem::path(testing::TempDir()) / (name + "-" + std::to_string(getpid()));
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

// Runs `argv` in `dir` with XDG_CONFIG_HOME there too (no user's settings); returns its pid.
inline pid_t spawn_in(const std::filesystem::path& dir, const std::vector<std::string>& argv) {
  // A SIGUSR1 sent before the app installs its handler would kill it: the child starts with it
  // blocked (the mask survives fork and exec) and the app unblocks it once its handler is in place.
  sigset_t usr1, previous;
  sigemptyset(&usr1);
  sigaddset(&usr1, SIGUSR1);
  sigprocmask(SIG_BLOCK, &usr1, &previous);
  const pid_t pid = fork();
  if (pid != 0) sigprocmask(SIG_SETMASK, &previous, nullptr);
  if (pid == 0) {
    if (chdir(dir.c_str()) != 0) _exit(127);
    setenv("XDG_CONFIG_HOME", dir.c_str(), 1);
    std::vector<char*> args;
    for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
    args.push_back(nullptr);
    execv(args[0], args.data());
    _exit(127);
  }
  return pid;
}

// Exit status of `pid` after `signal`, or -1 when it did not end within the timeout (then killed).
inline int stop_process(pid_t pid, int signal, std::chrono::seconds timeout = std::chrono::seconds(10)) {
  kill(pid, signal);
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  int status = 0;
  while (std::chrono::steady_clock::now() < deadline) {
    if (waitpid(pid, &status, WNOHANG) == pid) return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  kill(pid, SIGKILL);
  waitpid(pid, &status, 0);
  return -1;
}

inline bool wait_for_path(const std::filesystem::path& path, std::chrono::seconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  std::error_code ec;
  while (std::chrono::steady_clock::now() < deadline) {
    if (std::filesystem::exists(path, ec)) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  return false;
}

// Asks the running app for a screenshot (SIGUSR1) and returns the decoded PNG it writes into its
// working directory `dir`; empty after `timeout`. `seen` collects the names already used.
inline Image screenshot_of(pid_t app, const std::filesystem::path& dir, std::set<std::string>& seen,
                           std::chrono::seconds timeout = std::chrono::seconds(10)) {
  kill(app, SIGUSR1);
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (std::chrono::steady_clock::now() < deadline) {
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
      const std::string name = entry.path().filename().string();
      if (entry.path().extension() != ".png" || seen.count(name)) continue;
      // Whole once it has its name (ui/view/export/whole_file.h); one that does not decode is not taken.
      if (Image image = load_png(entry.path().string())) {
        seen.insert(name);
        return image;
      }
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
  }
  return {};
}

// Takes screenshots of `app` until `good(read(image))` holds for one or `timeout` passes; returns
// the last reading (a default one when no screenshot came).
template <class Read, class Good>
auto screenshot_until(pid_t app, const std::filesystem::path& dir, std::set<std::string>& seen, Read read, Good good,
                      std::chrono::seconds timeout) {
  decltype(read(std::declval<const Image&>())) last{};
  for (const auto deadline = std::chrono::steady_clock::now() + timeout; std::chrono::steady_clock::now() < deadline;) {
    const Image image = screenshot_of(app, dir, seen);
    if (!image) continue;
    last = read(image);
    if (good(last)) break;
  }
  return last;
}

}  // namespace ydscope::test
