#pragma once
// The desktop app's state and one frame of work: take each source's laps, update what the panels
// show, lay out and draw the view and the panels, and carry out what the user asked for. What
// each part does lives in its own class: the sources (SourceList, SourceSlot), the view
// (ViewStage), Share and Record (SourceOutputs), the booth view (BoothWindow) and the window's
// keys (WindowEvents); App ties them into a frame.
#include <chrono>
#include <optional>
#include <string>
#include <vector>

#include "app/gui/app_options.h"
#include "core/analysis/zone.h"
#include "app/gui/booth_window.h"
#include "app/gui/source_list.h"
#include "app/gui/source_outputs.h"
#include "app/gui/unit_follow.h"
#include "app/gui/settings_store.h"
#include "app/gui/view_stage.h"
#include "app/gui/window_present.h"
#include "app/gui/watched_sectors.h"
#include "app/gui/window_events.h"
#include "ui/panels/ui_model.h"
#include "ui/view/status/booth_calm.h"
#include "ui/view/settings/settings.h"

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
  // One frame: input, drain, draw (ImGui frame included). Does not show it.
  void frame();
  // Whether the frame rendered: one that would look exactly like the last is not drawn, and
  // then there is nothing to show.
  bool drew() const { return drawn_.drew(); }
  // Shows what the frame drew (window_present.h), then takes the latency of the laps it showed.
  void present();
  // How many frames were shown, and over how long since the first: the app's frame rate.
  std::string frames_shown_line() const;

  std::uint64_t laps_shown() const { return model().laps_shown; }
  // Laps are arriving (the link is scanning).
  bool streaming() const { return sources_.any_scanning(); }
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
  // With several sources, a line per source and the frame work, for the end of a run.
  std::vector<std::string> summary() const { return sources_.summary(); }
  // Saves a timestamped PNG after the next frame, as the S key does (SIGUSR1 asks for it).
  void request_screenshot() { model().requests.push_back(ui::SaveScreenshot{}); }

 private:
  const SourceSlot* fading_source() const { return sources_.pacing_fade(settings_.smooth); }
  SourceSlot& sel() { return sources_.selected(); }
  const SourceSlot& sel() const { return sources_.selected(); }
  ui::UiModel& model() { return sel().model; }
  const ui::UiModel& model() const { return sel().model; }
  double seconds_since_start(std::chrono::steady_clock::time_point t) const {
    return std::chrono::duration<double>(t - start_).count();
  }

  // The source list (app_sources.cpp). Every lidar the command line names started, each a layer
  // at its pose: --sim G1,G6,TG30, one --port or several, or --replay (one lidar: the identity
  // pose). Empty, or the first failure.
  std::string start_listed();
  // Before a new source or after a Disconnect: the selected source's link stops (and its
  // recordings with it), and everything measured from it goes.
  void leave_source();
  // Everything measured from the selected source goes.
  void start_clean();
  // The panels show, and command, source `index` from now on.
  void select_source(std::size_t index);
  void change_sources(const ui::SelectSource& request);
  void change_sources(const ui::SetSourceLook& request);
  void change_sources(const ui::AddSource& request);
  void change_sources(const ui::RemoveSource& request);
  // (app_align.cpp) Align and the user's answer to it.
  void change_sources(const ui::AlignSources& request);
  void change_sources(const ui::AnswerAlignment& request);
  // A source's panels' model this frame; the automatic choice falls back to the virtual lidar here.
  void update_model(SourceSlot& slot);

  // The frame's keys (app.cpp), and its requests from panels, keys and mouse, in order (app_requests.cpp).
  void handle_keys();
  void carry_out_requests(int framebuffer_width, int framebuffer_height);
  void carry_out(const ui::UiRequest& request, int framebuffer_width, int framebuffer_height);
  // After the selected source's sectors or the source list changed (watched_sectors.h).
  void sync_sectors() { follow_watched_sectors(sources_, settings_, stage_.view()); }

  void after_present();

  GLFWwindow* window_;
  WindowPresenter presenter_;
  BoothWindow booth_{window_};    // F11: the full-screen booth view
  WindowEvents events_{window_};  // keys and repaints since the last frame
  AppOptions options_;
  std::vector<Zone> zones_;  // settings.ini's and --zone's, watched from every source
  SourceOutputs outputs_{options_.share_port, options_.record};  // Share and the Record tab, of every source
  SettingsStore store_;
  ui::ViewSettings settings_ = store_.load();
  SourceList sources_;
  std::optional<ui::AlignmentProposal> alignment_;  // Align's answer, until applied or discarded
  UnitFollow units_;                                // names and poses follow the units' serials
  ViewStage stage_;
  float shown_phase_ = 0.0f;  // the phase the cloud was last drawn at (held while frozen)
  // The colour legend, described again only when the colours or the persistence change.
  void refresh_legend();
  ui::ColourLegend legend_;
  std::optional<std::pair<ui::ColourParams, int>> legend_for_;
  std::string shown_banner_;  // the banner whose age model() holds
  std::chrono::steady_clock::time_point start_;
  std::chrono::steady_clock::time_point last_frame_;  // start of the current frame
  std::optional<std::chrono::steady_clock::time_point> first_present_, last_present_;
  std::uint64_t frames_shown_ = 0;
  ui::DrawnFrame drawn_;  // what this frame drew
  bool quit_ = false;
};

}  // namespace ydscope::gui
