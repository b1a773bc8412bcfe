// ydscope: the desktop window. main owns GLFW, the GL context, ImGui and the loop; App does a frame.
#include <array>
#include <chrono>
#include <cstdint>
#include <csignal>
#include <signal.h>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <malloc.h>
#include <string>
#include <vector>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include "app/gui/app.h"
#include "app/gui/app_options.h"
#include "app/gui/sanitizer_pins.h"
#include "app/gui/screenshot.h"
#include "core/version.h"
#include "ui/render/gl.h"
#include "ui/render/theme.h"
#include "ui/view/window/app_icon.h"
#include "ui/view/window/frame_pacing.h"
#include "ui/view/window/window_fit.h"

namespace {

// Ctrl-C or a service manager's SIGTERM ends the loop normally, so settings are saved.
volatile std::sig_atomic_t g_stop_requested = 0;
void on_stop_signal(int) { g_stop_requested = 1; }
// SIGUSR1 saves a screenshot like the S key: for a kiosk's remote check, and for the UI tests.
volatile std::sig_atomic_t g_screenshot_requested = 0;
void on_screenshot_signal(int) { g_screenshot_requested = 1; }
// The window's content scale, as GLFW last reported it (main thread only).
float g_content_scale = 1.0f;

void on_glfw_error(int code, const char* description) {
  // Without a window manager (Xvfb) GLFW cannot iconify a full-screen window on focus loss; harmless.
  if (std::strstr(description, "Iconification") != nullptr) return;
  std::fprintf(stderr, "ydscope: GLFW error %d: %s\n", code, description);
}

// The taskbar and window switcher show the app's icon at the sizes they pick from.
void set_window_icon(GLFWwindow* window) {
  constexpr std::array kSizes{16, 32, 48, 64, 128};
  std::array<std::vector<std::uint8_t>, kSizes.size()> pixels;
  std::array<GLFWimage, kSizes.size()> images{};
  for (std::size_t i = 0; i < kSizes.size(); ++i) {
    pixels[i] = ydscope::ui::app_icon_rgba(kSizes[i]);
    images[i] = {kSizes[i], kSizes[i], pixels[i].data()};
  }
  glfwSetWindowIcon(window, static_cast<int>(images.size()), images.data());  // copied by GLFW
}

// The rate to animate at: the refresh rate of the monitor showing the window (full screen) or
// of the primary one, held lower on a software renderer. The monitor may change under a moved
// window; the renderer (`gl_renderer`, read once) does not.
double refresh_hz(GLFWwindow* window, const char* gl_renderer) {
  GLFWmonitor* monitor = glfwGetWindowMonitor(window);
  if (monitor == nullptr) monitor = glfwGetPrimaryMonitor();
  const GLFWvidmode* mode = monitor != nullptr ? glfwGetVideoMode(monitor) : nullptr;
  return ydscope::ui::animation_hz(mode != nullptr ? mode->refreshRate : 0.0, gl_renderer);
}

int run(const ydscope::gui::AppOptions& options) {
  using namespace ydscope::gui;
  glfwSetErrorCallback(on_glfw_error);
  if (!glfwInit()) {
    std::fprintf(stderr, "ydscope: cannot open a window: no display (is DISPLAY set? under CI use xvfb-run).\n");
    return 1;
  }
  const bool screenshot_mode = !options.screenshot_path.empty();
  glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
  glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 3);
  glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
  glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
  glfwWindowHint(GLFW_SAMPLES, 0);
  // The first window fits the monitor's work area (ui/view/window/window_fit.h); a window manager may
  // then maximise one that had to shrink.
  ydscope::ui::ScreenRect work_area;
  float monitor_scale = 1.0f;
  if (GLFWmonitor* monitor = glfwGetPrimaryMonitor()) {
    glfwGetMonitorWorkarea(monitor, &work_area.x, &work_area.y, &work_area.width, &work_area.height);
    float unused = 1.0f;
    glfwGetMonitorContentScale(monitor, &monitor_scale, &unused);
  }
  const ydscope::ui::ScreenRect first = ydscope::ui::first_window_rect(work_area, monitor_scale);
  if (ydscope::ui::window_was_shrunk(work_area, monitor_scale)) glfwWindowHint(GLFW_MAXIMIZED, GLFW_TRUE);
  GLFWwindow* window = glfwCreateWindow(first.width, first.height, "ydscope", nullptr, nullptr);
  if (!window) {
    std::fprintf(stderr,
                 "ydscope: cannot create an OpenGL 3.3 core window; try LIBGL_ALWAYS_SOFTWARE=1 for Mesa's software "
                 "renderer.\n");
    glfwTerminate();
    return 1;
  }
  glfwSetWindowPos(window, first.x, first.y);
  set_window_icon(window);
  glfwMakeContextCurrent(window);
  // Screenshot runs go as fast as laps arrive; interactive runs follow the display.
  glfwSwapInterval(screenshot_mode ? 0 : 1);

  IMGUI_CHECKVERSION();
  ImGui::CreateContext();
  float scale_x = 1.0f, scale_y = 1.0f;
  glfwGetWindowContentScale(window, &scale_x, &scale_y);
  ydscope::ui::apply_theme(scale_x);
  float theme_scale = scale_x;
  g_content_scale = scale_x;
  // A move to a monitor of another scale rebuilds the fonts and sizes at the next frame.
  glfwSetWindowContentScaleCallback(window, [](GLFWwindow*, float x, float) { g_content_scale = x; });
  ImGui_ImplGlfw_InitForOpenGL(window, true);
  ImGui_ImplOpenGL3_Init("#version 330 core");

  int exit_code = 0;
  {
    std::unique_ptr<App> app;
    try {
      app = std::make_unique<App>(window, options, !screenshot_mode);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "ydscope: %s\n", e.what());
      exit_code = 1;
    }
    if (app) {
      // A source that does not start (or a replay without a lap) is said on stderr and on screen
      // (the overlay); a screenshot run still saves that picture, then exits 1.
      if (const std::string error = app->start_source(); !error.empty())
        std::fprintf(stderr, "ydscope: %s\n", error.c_str());
      // Screenshot mode: at least N frames, and at least a few laps drawn, but never forever.
      constexpr std::uint64_t kLapsBeforeScreenshot = 5;
      const auto started = std::chrono::steady_clock::now();
      const auto deadline = started + std::chrono::seconds(30);
      int frames = 0;
      auto frame_started = started;
      const auto* gl_renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
      std::signal(SIGINT, on_stop_signal);
      std::signal(SIGTERM, on_stop_signal);
      std::signal(SIGUSR1, on_screenshot_signal);
      // A launcher may have blocked it until the handler is in place (the UI tests do).
      sigset_t usr1;
      sigemptyset(&usr1);
      sigaddset(&usr1, SIGUSR1);
      sigprocmask(SIG_UNBLOCK, &usr1, nullptr);
      while (exit_code == 0 && !glfwWindowShouldClose(window) && !app->quit_requested() && !g_stop_requested) {
        // Wait for input or the session's wake-up (laps post an empty event); the timeout paces
        // the fading between laps at the display's rate, or keeps the statistics ticking.
        const ydscope::ui::FrameNeeds needs{screenshot_mode, app->animating(), app->streaming()};
        const double since_frame_s =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - frame_started).count();
        glfwWaitEventsTimeout(ydscope::ui::frame_wait_s(needs, since_frame_s, refresh_hz(window, gl_renderer)));
        frame_started = std::chrono::steady_clock::now();
        if (g_content_scale != theme_scale) {
          theme_scale = g_content_scale;
          ImGui_ImplOpenGL3_DestroyFontsTexture();
          ImGui::GetIO().Fonts->Clear();
          ydscope::ui::apply_theme(theme_scale);
          ImGui_ImplOpenGL3_CreateFontsTexture();
        }
        if (g_screenshot_requested) {
          g_screenshot_requested = 0;
          app->request_screenshot();
        }
        app->frame();
        ++frames;
        if (screenshot_mode) {
          const bool enough =
              frames >= options.frames && (app->laps_shown() >= kLapsBeforeScreenshot || app->no_laps_coming());
          const bool timed_out = std::chrono::steady_clock::now() > deadline;
          if (enough || timed_out) {
            int w = 0, h = 0;
            glfwGetFramebufferSize(window, &w, &h);
            const std::string error = save_framebuffer_png(options.screenshot_path, w, h);
            const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
            if (error.empty())
              std::printf("ydscope: wrote %s after %d frames and %llu laps in %.2f s (%.1f ms per frame)\n",
                          options.screenshot_path.c_str(), frames, static_cast<unsigned long long>(app->laps_shown()),
                          seconds, 1e3 * seconds / frames);
            if (!error.empty()) {
              std::fprintf(stderr, "ydscope: %s\n", error.c_str());
              exit_code = 1;
            } else if (!enough) {
              std::fprintf(stderr, "ydscope: only %llu laps arrived in 30 s; the screenshot was saved anyway.\n",
                           static_cast<unsigned long long>(app->laps_shown()));
              exit_code = 1;
            } else if (app->no_laps_coming()) {
              exit_code = 1;
            }
            break;
          }
        }
        if (!app->drew()) continue;  // the picture on screen is still right
        app->present();
      }
      for (const std::string& line : app->summary()) std::printf("ydscope: %s\n", line.c_str());
      if (!screenshot_mode) std::printf("ydscope: %s\n", app->frames_shown_line().c_str());
    }
  }
  ydscope::pin_loaded_libraries_for_leak_reports();
  ImGui_ImplOpenGL3_Shutdown();
  ImGui_ImplGlfw_Shutdown();
  ImGui::DestroyContext();
  glfwDestroyWindow(window);
  glfwTerminate();
  return exit_code;
}

}  // namespace

int main(int argc, char** argv) {
  // A software renderer (llvmpipe) allocates and frees megabytes at every frame. By default glibc
  // hands such blocks back to the kernel (mmap, or trimming the heap's top) and takes them again
  // the next frame, page by page; on a virtual machine those page faults were about a tenth of the
  // app's CPU with smooth drawing (docs/performance.md). Keep them in the heap instead: the
  // resident memory stays at the frame's peak rather than dropping between frames.
  mallopt(M_MMAP_THRESHOLD, 32 << 20);
  mallopt(M_TRIM_THRESHOLD, 256 << 20);
  const std::vector<std::string> args(argv + 1, argv + argc);
  // Help and version win over everything else on the line, as in ydscope-cli.
  if (ydscope::asks_for_help(args)) {
    std::fputs(ydscope::gui::kAppHelp, stdout);
    return 0;
  }
  if (ydscope::asks_for_version(args)) {
    std::printf("ydscope %s\n", ydscope::kVersion);
    return 0;
  }
  ydscope::gui::AppOptions options;
  try {
    options = ydscope::gui::parse_app_options(args);
  } catch (const ydscope::UsageError& e) {
    std::fprintf(stderr, "ydscope: %s\n", e.what());
    return 2;
  }
  return run(options);
}
