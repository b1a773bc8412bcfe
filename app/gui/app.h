#pragma once
// The desktop app's state and one frame of work: drain the lap queue, update what the panels show,
// draw the polar view and the panels, and carry out what the user asked for.
#include <algorithm>
#include <chrono>
#include <memory>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "app/gui/app_options.h"
#include "app/gui/booth_window.h"
#include "app/gui/lidar_source.h"
#include "app/gui/source_outputs.h"
#include "app/gui/source_slot.h"
#include "core/link/session.h"
#include "ui/panels/ui_model.h"
#include "ui/render/polar_view.h"
#include "ui/view/booth_calm.h"
#include "ui/view/lap_history.h"
#include "ui/view/lap_phase.h"
#include "ui/view/motion_background.h"
#include "ui/view/settings.h"
#include "ui/view/source_cloud.h"

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

  std::uint64_t laps_shown() const { return model().laps_shown; }
  // Laps are arriving (the link is scanning).
  bool streaming() const {
    return std::any_of(sources_.begin(), sources_.end(),
                       [](const auto& s) { return s->model.snap.state == LinkState::Scanning; });
  }
  // The picture changes between laps (persistence or a booth banner fading): the loop draws at
  // the display's rate.
  bool animating() const {
    return fading_source() != nullptr ||
           ui::banner_fading(model().now_s - model().banner_since_s, booth_.on() && !model().banner.empty());
  }
  const std::string& last_error() const { return model().status_message; }
  bool quit_requested() const { return quit_; }
  // No lap will come until the user picks another source: it did not start, or it is a replay
  // that went round without one.
  bool no_laps_coming() const { return !model().start_error.empty() || model().view_state.give_up; }
  // With several sources, a line per source (laps from the device, drawn, lost) and the frame
  // work, for the end of a run; nothing with one.
  std::vector<std::string> summary() const;
  // Saves a timestamped PNG after the next frame, as the S key does (SIGUSR1 asks for it).
  void request_screenshot() { model().requests.push_back(ui::SaveScreenshot{}); }

 private:
  // The source whose laps pace the fading persistence: the selected one while it streams, else
  // another that does (one lidar unplugged must not stop the others' smooth drawing); or none.
  const SourceSlot* fading_source() const {
    const auto fading = [&](const SourceSlot& s) {
      return settings_.smooth && s.model.snap.state == LinkState::Scanning && !s.model.paused_view &&
             s.history.size() > 1;
    };
    if (fading(sel())) return &sel();
    for (const auto& slot : sources_)
      if (fading(*slot)) return slot.get();
    return nullptr;
  }
  SourceSlot& sel() { return *sources_[selected_]; }
  const SourceSlot& sel() const { return *sources_[selected_]; }
  ui::UiModel& model() { return sel().model; }
  const ui::UiModel& model() const { return sel().model; }
  ui::PanelEdits& edits() { return sel().edits; }
  Session& session() { return sel().session; }
  LidarSource& source() { return sel().source; }
  ui::LapHistory& history() { return sel().history; }
  const ui::LapHistory& history() const { return sel().history; }
  // The source list (app_sources.cpp). A new source at the end, its name made unique and, where
  // `look` leaves it empty, the first palette colour no source has.
  SourceSlot& add_slot(ui::SourceLook look);
  ui::ConnectRequest connect_request_for(const SourceChoice& choice) const;
  // Every source's look, in list order (for settings.ini's memory of them, remembered_sources.h).
  std::vector<ui::SourceLook> looks() const;
  // --sim G1,G6,TG30 or several --port: every one started, at its pose. Empty, or the first failure.
  std::string start_several();
  // The panels show, and command, source `index` from now on.
  void select_source(std::size_t index);
  void change_sources(const ui::SelectSource& request);
  void change_sources(const ui::SetSourceLook& request);
  void change_sources(const ui::AddSource& request);
  void change_sources(const ui::RemoveSource& request);
  // The Sources panel's rows and the legend's lines, into the selected source's panel model.
  void fill_source_rows();
  // What the view draws this frame: each shown source's laps at its pose (and its mark).
  std::span<const ui::SourceLayer> source_layers();

  // The view takes the newest lap each frame; the measurements take every lap, in order, from a
  // ring of their own, so a slow frame skips pictures but never a lap in the statistics.
  void drain_laps(SourceSlot& slot);
  void measure_lap(SourceSlot& slot, const Lap& lap);
  void update_model(SourceSlot& slot);
  // Keys (app_keys.cpp): GLFW's callback queues each press; handle_keys acts on them in order.
  void install_key_callback();
  void remove_key_callback();
  void handle_keys();
  // The view of a frame (app_view.cpp): every source in one common view, or (app_split_view.cpp)
  // two to four side by side when View > split is on and there are several.
  void lay_out_common_view(float left, float width, float height);
  bool split_active() const;
  void lay_out_split_view(float left, float width, float height);
  // Changes whenever the GL layer of the view (or of the split view's tiles) would draw otherwise.
  std::uint64_t gl_generation() const;
  // The frame's requests from panels, keys and mouse, in order (app_requests.cpp).
  void carry_out_requests(int framebuffer_width, int framebuffer_height);
  // Renders the GL layer and ImGui's draw data unless the frame would repeat the last one.
  bool render_if_changed(float framebuffer_scale, int framebuffer_width, int framebuffer_height);
  void carry_out(const ui::UiRequest& request, int framebuffer_width, int framebuffer_height);
  // The replay's position for its panel, while a replay is the source.
  void follow_replay();
  void export_shown_laps_mcap();
  // "lap 12" or "8 laps (5 to 12)", and " as frozen" while frozen: what an export of the shown laps holds.
  std::string shown_laps_words(std::size_t laps) const;
  double seconds_since_start(std::chrono::steady_clock::time_point t) const {
    return std::chrono::duration<double>(t - start_).count();
  }
  // A new source or a Disconnect: everything measured from the old one goes.
  void start_clean();
  // Starts `request` (after start_clean) and puts the outcome where the user looks: the overlay,
  // the status line and the Connection panel; a source's warnings also go to stderr in the
  // words ydscope-cli uses. Empty, or the sentence of why it did not start.
  std::string start(const ui::ConnectRequest& request);
  void update_view_state(SourceSlot& slot);
  // The watched sectors (app_sectors.cpp): restored at start, changed by the Sectors panel and
  // Shift+drag on the view, kept in settings.ini.
  void restore_sectors();
  void unwatch_sector(std::size_t index);
  // settings.ini's list and the view's outlines follow model().sectors.
  void sync_sectors();

  GLFWwindow* window_;
  BoothWindow booth_{window_};  // F11: the full-screen booth view
  struct KeyPress {
    int key;
    int mods;
  };
  std::vector<KeyPress> key_presses_;  // since the last frame, in order
  void (*imgui_key_callback_)(GLFWwindow*, int, int, int, int) = nullptr;
  AppOptions options_;
  SourceOutputs outputs_{options_.share_port, options_.record};  // Share and the Record tab, of the selected source
  bool persist_;
  std::string settings_path_;
  std::string imgui_ini_path_;
  ui::ViewSettings settings_;
  // The source list, never empty; the panels show (and command) the selected one.
  std::vector<std::unique_ptr<SourceSlot>> sources_;
  std::size_t selected_ = 0;
  std::vector<ui::SourceLayer> layers_;  // this frame's, reused
  std::vector<ui::SourceMark> marks_;
  std::vector<std::pair<Pose, bool>> drawn_layers_key_;  // pose and dimming the cloud was built with
  float shown_phase_ = 0.0f;                             // the phase the cloud was last drawn at (held while frozen)
  std::string shown_banner_;                             // the banner whose age model() holds
  std::unique_ptr<ui::PolarView> view_;
  std::vector<std::unique_ptr<ui::PolarView>> tiles_;  // the split view's, one per source shown
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_frame_;  // start of the current frame
  std::optional<std::chrono::steady_clock::time_point> last_present_;
  bool drew_ = false;
  std::uint64_t drawn_signature_ = 0;  // draw_signature of the last frame rendered
  bool window_damaged_ = true;         // the window system asks for the picture again
  bool quit_ = false;
};

}  // namespace ydscope::gui
