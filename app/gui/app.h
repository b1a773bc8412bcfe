#pragma once
// The desktop app's state and one frame of work: drain the lap queue, update what the panels show,
// draw the polar view and the panels, and carry out what the user asked for.
#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "app/gui/app_options.h"
#include "app/gui/lidar_source.h"
#include "core/bridge/live_topics.h"
#include "core/bridge/session_share.h"
#include "core/link/session.h"
#include "ui/panels/ui_model.h"
#include "ui/render/polar_view.h"
#include "ui/view/booth_calm.h"
#include "ui/view/lap_history.h"
#include "ui/view/lap_phase.h"
#include "ui/view/motion_background.h"
#include "ui/view/settings.h"

struct GLFWwindow;

namespace ydscope::gui {

class App {
 public:
  App(GLFWwindow* window, const AppOptions& options, bool persist_settings);
  ~App();
  App(const App&) = delete;
  App& operator=(const App&) = delete;

  // Starts the source the command line named (or the automatic choice). Empty, or one sentence.
  std::string start_source();
  // One frame: input, drain, draw (ImGui frame included). Does not swap buffers.
  void frame();
  // Whether the frame rendered: one that would look exactly like the last is not drawn, and
  // then there is nothing to swap.
  bool drew() const { return drew_; }
  // After the swap: latency of the laps this frame showed.
  void after_present();

  std::uint64_t laps_shown() const { return model_.laps_shown; }
  // Laps are arriving (the link is scanning).
  bool streaming() const { return model_.snap.state == LinkState::Scanning; }
  // The picture changes between laps (persistence or a booth banner fading): the loop draws at
  // the display's rate.
  bool animating() const {
    const bool fading_laps = settings_.smooth && streaming() && !model_.paused_view && history_.size() > 1;
    return fading_laps || ui::banner_fading(model_.now_s - model_.banner_since_s, fullscreen_ && !model_.banner.empty());
  }
  const std::string& last_error() const { return model_.status_message; }
  bool quit_requested() const { return quit_; }
  // No lap will come until the user picks another source: it did not start, or it is a replay
  // that went round without one.
  bool no_laps_coming() const { return !model_.start_error.empty() || model_.view_state.give_up; }
  // Saves a timestamped PNG after the next frame, as the S key does (SIGUSR1 asks for it).
  void request_screenshot() { model_.requests.push_back(ui::SaveScreenshot{}); }

 private:
  // The view takes the newest lap each frame; the measurements take every lap, in order, from a
  // ring of their own, so a slow frame skips pictures but never a lap in the statistics.
  void drain_laps();
  void measure_lap(const Lap& lap);
  void update_model();
  // Keys (app_keys.cpp): GLFW's callback queues each press; handle_keys acts on them in order.
  void install_key_callback();
  void remove_key_callback();
  void handle_keys();
  // The frame's requests from panels, keys and mouse, in order (app_requests.cpp).
  void carry_out_requests(int framebuffer_width, int framebuffer_height);
  // Renders the GL layer and ImGui's draw data unless the frame would repeat the last one.
  bool render_if_changed(float framebuffer_scale, int framebuffer_width, int framebuffer_height);
  void carry_out(const ui::UiRequest& request, int framebuffer_width, int framebuffer_height);
  // The replay's position for its panel, while a replay is the source.
  void follow_replay();
  // Out of the app, live (app_share.cpp): Share serves the source to Foxglove and follows a new
  // one; a recording writes .ydrec (the session), MCAP (LiveTopics), or both.
  void start_share();
  void stop_share();
  void start_recording(const ui::StartRecording& request);
  void stop_recording(const std::string& why = {});
  // Each frame: the share's address and clients, the MCAP recording's size, and a share that
  // waits for the new source to be up before serving it.
  void follow_share_and_recording();
  // A new source (or none) is about to start: the old one's recordings end, the share waits.
  void leave_source();
  void export_shown_laps_mcap();
  // "lap 12" or "8 laps (5 to 12)", and " as frozen" while frozen: what an export of the shown laps holds.
  std::string shown_laps_words(std::size_t laps) const;
  void toggle_fullscreen();
  double seconds_since_start(std::chrono::steady_clock::time_point t) const {
    return std::chrono::duration<double>(t - start_).count();
  }
  // The booth view hides the pointer once it rests; any move brings it back.
  void follow_pointer();
  // A new source or a Disconnect: everything measured from the old one goes.
  void start_clean();
  // Starts `request` (after start_clean) and puts the outcome where the user looks: the overlay,
  // the status line and the Connection panel; a source's warnings also go to stderr in the
  // words ydscope-cli uses. Empty, or the sentence of why it did not start.
  std::string start(const ui::ConnectRequest& request);
  void update_view_state();
  // The watched sectors (app_sectors.cpp): restored at start, changed by the Sectors panel and
  // Shift+drag on the view, kept in settings.ini.
  void restore_sectors();
  void unwatch_sector(std::size_t index);
  // Empty, or why `spec` is not watched (a mistake, a duplicate, too many).
  std::string watch_sector(const std::string& spec);
  // settings.ini's list and the view's outlines follow model_.sectors.
  void sync_sectors();

  GLFWwindow* window_;
  struct KeyPress {
    int key;
    int mods;
  };
  std::vector<KeyPress> key_presses_;  // since the last frame, in order
  void (*imgui_key_callback_)(GLFWwindow*, int, int, int, int) = nullptr;
  AppOptions options_;
  bool persist_;
  std::string settings_path_;
  std::string imgui_ini_path_;
  ui::ViewSettings settings_;
  ui::UiModel model_;
  Session session_;
  std::unique_ptr<LapSubscription> measured_laps_;  // every lap, for rates, plots, sectors, health
  Lap measured_lap_;
  LidarSource source_;
  ui::LapHistory history_;
  ui::LapPhase lap_phase_;   // how far between two laps, for fading persistence at display rate
  float shown_phase_ = 0.0f;  // the phase the cloud was last drawn at (held while frozen)
  ui::MotionBackground motion_;  // the room, learned from the laps the view shows
  std::optional<ui::ColourMode> windowed_colour_mode_;  // restored on leaving the booth view
  std::optional<int> windowed_persistence_;              // likewise
  std::string shown_banner_;                             // the banner whose age model_ holds
  double pointer_moved_s_ = 0.0;                         // the booth view hides a resting pointer
  bool cursor_hidden_ = false;
  Lap lap_;
  std::unique_ptr<ui::PolarView> view_;
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_frame_;  // start of the current frame
  std::optional<std::chrono::steady_clock::time_point> last_present_;
  bool drew_ = false;
  std::uint64_t drawn_signature_ = 0;  // draw_signature of the last frame rendered
  bool window_damaged_ = true;         // the window system asks for the picture again
  std::int64_t pending_latency_rx_ns_ = 0;  // newest lap drawn this frame, measured after present
  std::unique_ptr<SessionShare> share_;               // while Share is on
  std::unique_ptr<LiveTopics> mcap_recording_;        // while an MCAP recording runs
  std::chrono::steady_clock::time_point share_polled_;  // clients are asked twice a second
  bool record_from_start_ = false;                      // --record, until the source connects
  std::optional<double> last_set_scan_hz_;
  std::optional<ReplayStatus> last_replay_status_;  // the replay link's, as follow_replay last saw it
  std::optional<std::chrono::steady_clock::time_point> last_lap_at_;  // newest lap of this source
  bool has_source_ = false;
  bool quit_ = false;
  bool fullscreen_ = false;
  int windowed_[4] = {100, 100, 1280, 800};
};

}  // namespace ydscope::gui
