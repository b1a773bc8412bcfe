#pragma once
// How long the desktop app's loop may sleep in glfwWaitEventsTimeout before the next frame. Laps
// and input wake it early in every case; the timeout is what keeps the picture moving, or the
// statistics ticking, when nothing wakes it.
namespace ydscope::ui {

struct FrameNeeds {
  bool screenshot = false;  // --screenshot: as fast as the frames come
  bool animating = false;   // persistence is fading between laps: the display's rate
  bool streaming = false;   // laps arrive and wake the loop; a slow tick for the counters
};

// `since_frame_s`: time since the current frame started; `refresh_hz`: the rate to animate at
// (animation_hz). Never negative.
double frame_wait_s(const FrameNeeds& needs, double since_frame_s, double refresh_hz);

// The rate to animate at: the monitor's (a missing or absurd value counts as 60 Hz), but at most
// kSoftwareRendererHz when the GL renderer is a software one (Mesa's llvmpipe, softpipe, swrast;
// SwiftShader), where every frame of a G6 cloud costs about 10 ms of CPU.
inline constexpr double kSoftwareRendererHz = 30.0;
double animation_hz(double monitor_hz, const char* gl_renderer);

// Whether GL_RENDERER names a software renderer, where every pixel drawn costs the CPU.
bool is_software_renderer(const char* gl_renderer);

}  // namespace ydscope::ui
