#include "app/gui/app.h"
#include "app/gui/zone_setup.h"

#include <algorithm>
#include <cstdio>
#include <variant>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>

#include "ui/panels/panels.h"
#include "ui/render/gl.h"
#include "ui/view/settings/remembered_sources.h"

namespace ydscope::gui {
namespace {

std::int64_t steady_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

}  // namespace

App::App(GLFWwindow* window, const AppOptions& options, bool persist_settings)
    : window_(window),
      presenter_(window, reinterpret_cast<const char*>(glGetString(GL_RENDERER))),
      options_(options),
      store_(persist_settings),
      sources_([] { glfwPostEmptyEvent(); }),
      stage_(options.screenshot_path.empty()),
      start_(std::chrono::steady_clock::now()),
      last_frame_(start_) {
  if (options_.split) settings_.split_view = true;
  if (options_.fullscreen) {
    settings_.show_panels = false;
    booth_.toggle(settings_, sources_.size());  // before the first source: none yet
  }
  sources_.add({}, static_cast<std::size_t>(settings_.persistence_laps));
  std::snprintf(sel().edits.replay_text, sizeof sel().edits.replay_text, "%s", settings_.last_replay_file.c_str());
  model().show_sidebar_tab = static_cast<int>(settings_.sidebar_tab);  // the tab it was left on
  model().ports = discover_ports();
  restore_watched_sectors(model().sectors, settings_, options_.sector);
  zones_ = zones_to_watch(settings_.zones, options_.zones);
  sync_sectors();
}

App::~App() {
  if (booth_.on()) booth_.toggle(settings_, sources_.size());  // leave the monitor before the window goes away
  // Files get their summaries and the clients a closed server before the source goes.
  outputs_.stop_recording(sources_);
  outputs_.stop_share(sources_);
  for (const auto& slot : sources_.slots()) slot->source.stop();
  ui::remember_looks(settings_, sources_.looks());
  store_.save(settings_);
}

void App::frame() {
  last_frame_ = std::chrono::steady_clock::now();
  const double now_s = seconds_since_start(last_frame_);
  for (const auto& slot : sources_.slots()) {
    // Each source watches the zones from its own pose; one added since gets them here.
    if (slot->model.zones.zones().size() != zones_.size()) slot->model.zones = ZoneWatch(zones_);
    slot->zone_beep = settings_.zone_beep || options_.zone_beep;
    // The view sees a new lap by its history's generation, and builds only that lap.
    slot->take_laps(now_s);
    update_model(*slot);
    if (static_cast<int>(slot->history.depth()) != settings_.persistence_laps)
      slot->history.set_depth(static_cast<std::size_t>(settings_.persistence_laps));
  }

  ImGui_ImplOpenGL3_NewFrame();
  ImGui_ImplGlfw_NewFrame();
  ImGui::NewFrame();
  handle_keys();
  const ImGuiIO& io = ImGui::GetIO();
  booth_.follow_pointer(model().now_s, io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f);

  int win_w = 0, win_h = 0, fb_w = 0, fb_h = 0;
  glfwGetWindowSize(window_, &win_w, &win_h);
  glfwGetFramebufferSize(window_, &fb_w, &fb_h);
  const float fb_scale = win_w > 0 ? static_cast<float>(fb_w) / static_cast<float>(win_w) : 1.0f;

  model().sources = sources_.rows(std::chrono::steady_clock::now());
  model().selected_source = sources_.selected_index();
  model().alignment = alignment_;
  const float sidebar = settings_.show_panels ? ui::draw_sidebar(model(), sel().edits, settings_) : 0.0f;
  const float view_w = static_cast<float>(win_w) - sidebar;
  if (const SourceSlot* pacing = fading_source())
    shown_phase_ = pacing->lap_phase.at(now_s);
  else if (!settings_.smooth)
    shown_phase_ = 0.0f;
  const bool booth_legend = booth_.on() && settings_.colours.mode == ui::ColourMode::Source;
  stage_.lay_out(sources_, settings_,
                 {sidebar, view_w, static_cast<float>(win_h), glfwGetWindowAttrib(window_, GLFW_HOVERED) == GLFW_TRUE,
                  now_s, shown_phase_, booth_legend, booth_.on()});
  ui::draw_view_header(model(), sidebar, view_w);
  model().booth = booth_.on();
  refresh_legend();
  if (model().booth) {
    model().legend = legend_;
    model().booth_title = settings_.booth_title;
    model().booth_figure =
        settings_.booth_figure == ui::BoothFigureKind::None
            ? std::string()
            : ui::booth_figure_text(settings_.booth_figure, ui::count_visitors(sel().lap, sel().motion));
    // By source, the legend in large type names each lidar and its state (only the app knows them).
    if (booth_legend)
      for (const ui::SourceRow& row : model().sources) model().legend.swatches.push_back({row.look.colour, row.legend});
    ui::draw_booth_overlay(model(), sidebar, view_w, static_cast<float>(win_h));
  } else if (settings_.colours.mode != ui::ColourMode::Source) {  // by source, the source legend says it
    ui::draw_window_legend(legend_, sidebar, view_w, static_cast<float>(win_h));
  }
  ImGui::Render();
  // A screenshot reads the frame it is taken in, so that frame is always drawn; so is one the
  // window system lost (uncovered, resized).
  const bool screenshot = !options_.screenshot_path.empty() ||
                          std::any_of(model().requests.begin(), model().requests.end(), [](const ui::UiRequest& r) {
                            return std::holds_alternative<ui::SaveScreenshot>(r);
                          });
  const bool damaged = events_.take_damage();
  drawn_ =
      stage_.render_if_changed(settings_, fb_scale, fb_w, fb_h, screenshot || damaged, presenter_.keeps_last_picture());
  carry_out_requests(fb_w, fb_h);
  outputs_.follow(sources_);
}

void App::refresh_legend() {
  const std::pair<ui::ColourParams, int> now{stage_.view().colours_in_use(), settings_.persistence_laps};
  if (legend_for_ == now) return;
  legend_ = ui::describe_legend(now.first, now.second);
  legend_for_ = now;
}

void App::handle_keys() {
  const std::vector<KeyPress> presses = events_.take_presses();
  // Typing in a text field is not a shortcut (ImGui's word from the frame that took the keys).
  if (ImGui::GetIO().WantTextInput) return;
  for (const KeyPress& press : presses) {
    const bool ctrl = (press.mods & GLFW_MOD_CONTROL) != 0;
    switch (press.key) {
      case GLFW_KEY_F11: booth_.toggle(settings_, sources_.size()); break;
      case GLFW_KEY_TAB: settings_.show_panels = !settings_.show_panels; break;
      case GLFW_KEY_R: model().requests.push_back(ui::ResetView{}); break;
      case GLFW_KEY_A: settings_.auto_range = true; break;
      case GLFW_KEY_P: model().paused_view = !model().paused_view; break;
      case GLFW_KEY_S: model().requests.push_back(ui::SaveScreenshot{}); break;
      case GLFW_KEY_E: model().requests.push_back(ui::ExportLapCsv{true}); break;
      case GLFW_KEY_M: model().requests.push_back(ui::ExportLapMcap{}); break;
      case GLFW_KEY_W: model().requests.push_back(ui::SetShare{!model().share.on}); break;
      case GLFW_KEY_ESCAPE: stage_.view().clear_ruler(); break;
      // The next of several sources: the panels' and Alt/Ctrl+drag's, also with the panels hidden.
      case GLFW_KEY_N:
        model().requests.push_back(ui::SelectSource{(sources_.selected_index() + 1) % sources_.size()});
        break;
      case GLFW_KEY_Q:
        if (ctrl) quit_ = true;
        break;
      default: break;
    }
  }
}

void App::present() {
  presenter_.present(drawn_);
  after_present();
}

std::string App::frames_shown_line() const {
  const double seconds =
      first_present_ && last_present_ ? std::chrono::duration<double>(*last_present_ - *first_present_).count() : 0.0;
  char line[128];
  std::snprintf(line, sizeof line, "%llu frames shown in %.1f s (%.1f a second)",
                static_cast<unsigned long long>(frames_shown_), seconds,
                seconds > 0.0 ? static_cast<double>(frames_shown_ - 1) / seconds : 0.0);
  return line;
}

void App::after_present() {
  // Frame time = the work of a frame (draining, drawing, presenting), not the wait between frames.
  const auto now = std::chrono::steady_clock::now();
  model().frame_ms.add(std::chrono::duration<double, std::milli>(now - last_frame_).count());
  if (last_present_)
    model().frame_interval_ms.add(std::chrono::duration<double, std::milli>(now - *last_present_).count());
  last_present_ = now;
  if (!first_present_) first_present_ = now;
  ++frames_shown_;
  if (sel().pending_latency_rx_ns != 0) {
    const double latency_ms = static_cast<double>(steady_ns() - sel().pending_latency_rx_ns) * 1e-6;
    model().latency_ms.add(latency_ms);
    model().plots.add_latency_ms(latency_ms, model().now_s);
    sel().pending_latency_rx_ns = 0;
  }
}

}  // namespace ydscope::gui
