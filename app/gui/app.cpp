#include "app/gui/app.h"

#include <algorithm>
#include <variant>

#include <cstdio>

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>

#include "app/gui/screenshot.h"
#include "app/gui/source_origin.h"
#include "ui/panels/panels.h"
#include "ui/render/draw_signature.h"
#include "ui/render/gl.h"
#include "ui/render/theme.h"
#include "ui/view/booth_calm.h"
#include "ui/view/remembered_sources.h"
#include "ui/view/health_names.h"

namespace ydscope::gui {
namespace {

// The Connection panel's model choice for a model name: 0 none, then all_profiles() order from 1.
int model_choice(const std::optional<std::string>& model, int none) {
  const ModelProfile* profile = model ? find_profile(*model) : nullptr;
  const auto profiles = all_profiles();
  for (std::size_t i = 0; i < profiles.size(); ++i)
    if (profile == &profiles[i]) return static_cast<int>(i) + 1;
  return none;
}

std::int64_t steady_ns() {
  return std::chrono::duration_cast<std::chrono::nanoseconds>(std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

}  // namespace

App::App(GLFWwindow* window, const AppOptions& options, bool persist_settings)
    : window_(window),
      options_(options),
      persist_(persist_settings),
      view_(std::make_unique<ui::PolarView>(options.screenshot_path.empty())),
      start_(std::chrono::steady_clock::now()),
      last_frame_(start_) {
  const auto dir = ui::config_directory();
  if (persist_ && !dir.empty()) {
    settings_path_ = (dir / "settings.ini").string();
    imgui_ini_path_ = (dir / "imgui.ini").string();
    std::vector<std::string> notes;
    settings_ = ui::load_settings(settings_path_, &notes);
    for (const auto& note : notes) std::fprintf(stderr, "ydscope: %s: %s\n", settings_path_.c_str(), note.c_str());
    std::error_code ec;
    std::filesystem::create_directories(dir, ec);
    ImGui::GetIO().IniFilename = imgui_ini_path_.c_str();
  } else {
    ImGui::GetIO().IniFilename = nullptr;  // screenshot runs must not depend on a user's layout
  }
  if (options_.split) settings_.split_view = true;
  if (options_.fullscreen) {
    settings_.show_panels = false;
    booth_.toggle(settings_, sources_.size());
  }
  add_slot({});
  std::snprintf(edits().replay_text, sizeof edits().replay_text, "%s", settings_.last_replay_file.c_str());
  model().ports = discover_ports();
  restore_sectors();
  install_key_callback();
}

App::~App() {
  remove_key_callback();
  if (booth_.on()) booth_.toggle(settings_, sources_.size());  // leave the monitor before the window goes away
  // Files get their summaries and the clients a closed server before the source goes.
  outputs_.stop_recording(sel());
  outputs_.stop_share(sel());
  for (auto& slot : sources_) slot->source.stop();
  ui::remember_looks(settings_, looks());
  if (persist_ && !settings_path_.empty()) ui::save_settings(settings_path_, settings_);
  // ImGui keeps only a pointer to our path string: save now and let it forget the path.
  if (!imgui_ini_path_.empty()) ImGui::SaveIniSettingsToDisk(imgui_ini_path_.c_str());
  ImGui::GetIO().IniFilename = nullptr;
}

std::string App::start_source() {
  if (options_.share) model().requests.push_back(ui::SetShare{true});  // carried out after the first frame
  if (!options_.sources.empty()) return start_several();
  if (options_.source == SourceKind::Auto) {
    // The last run had several lidars: the same ones again, as they were placed.
    if (std::vector<SourceChoice> last = last_run_choices(settings_); !last.empty()) {
      options_.sources = std::move(last);
      const std::string error = start_several();
      // Short: centred over the view, it must clear the legend in its top-left corner.
      model().banner = "the last run's " + std::to_string(sources_.size()) + " lidars, as placed";
      return error;
    }
  }
  ui::ConnectRequest request;
  start_clean();
  sel().has_source = true;
  switch (options_.source) {
    case SourceKind::Auto:
      model().banner = source().start_auto();
      model().source_text = source().description();
      model().sim_active = source().sim_active();
      model().show_source_tab = model().sim_active ? 1 : 0;
      return {};
    case SourceKind::Port:
      request.kind = ui::ConnectRequest::Kind::Port;
      request.address = options_.port;
      if (options_.model && *options_.model != "auto") request.model = options_.model;
      if (options_.baud) request.baud = *options_.baud;
      // The Port tab shows what runs, so Connect there reconnects to it.
      std::snprintf(edits().port_text, sizeof edits().port_text, "%s", options_.port.c_str());
      break;
    case SourceKind::Sim: {
      request.kind = ui::ConnectRequest::Kind::Sim;
      request.model = options_.model;
      request.scene = options_.scene;
      // The Virtual tab shows what runs.
      edits().sim_model_choice = model_choice(options_.model, edits().sim_model_choice);
      edits().sim_scene_choice = options_.scene == "room" ? 0 : options_.scene == "booth" ? 2 : 1;
      break;
    }
    case SourceKind::Replay:
      request.kind = ui::ConnectRequest::Kind::Replay;
      request.address = options_.replay_file;
      request.model = options_.model;
      request.replay_speed = options_.replay_speed;
      request.replay_loop = !options_.replay_once;
      settings_.last_replay_file = options_.replay_file;
      std::snprintf(edits().replay_text, sizeof edits().replay_text, "%s", options_.replay_file.c_str());
      edits().replay_model_choice = model_choice(options_.model, 0);  // the Replay tab shows the model it decodes as
      break;
  }
  model().show_source_tab = static_cast<int>(request.kind);
  return start(request);
}

std::string App::start(const ui::ConnectRequest& request) {
  const std::string error = source().start(request);
  sel().look.origin = origin_of(request);
  sel().has_source = error.empty();
  model().start_error = error;
  model().start_error_replay = request.kind == ui::ConnectRequest::Kind::Replay;
  model().status_message = error;
  model().source_text = source().description();
  model().sim_active = source().sim_active();
  model().replay.available = source().replay_active();
  // The Replay tab shows what the new link plays from its first frame, not the defaults.
  model().replay.speed = static_cast<float>(request.replay_speed);
  model().replay.loop = request.replay_loop;
  model().source_warnings = source().warnings();
  for (const std::string& warning : model().source_warnings)
    std::fprintf(stderr, "ydscope: warning: %s\n", warning.c_str());
  return error;
}

void App::drain_laps(SourceSlot& s) {
  while (s.measured_laps->try_pop(s.measured_lap))
    if (!s.model.paused_view) measure_lap(s, s.measured_lap);
  const std::size_t drained = s.session.laps().drain_newest(s.lap);
  s.model.laps_skipped = s.session.laps().skipped();
  if (drained > 0) s.last_lap_at = std::chrono::steady_clock::now();
  if (drained == 0 || s.model.paused_view) return;
  s.history.push(s.lap);
  s.lap_phase.on_lap(seconds_since_start(last_frame_));
  s.motion.add_lap(s.lap);
  view_->invalidate();
  ++s.model.laps_shown;
  s.model.points_in_lap = s.lap.points.size();
  s.pending_latency_rx_ns = s.lap.last_rx_ns;
}

void App::measure_lap(SourceSlot& s, const Lap& lap) {
  s.model.scan_rate.add_lap_end(lap.index, lap.last_rx_ns);
  s.model.plots.add_lap({s.model.scan_rate.hz(), s.model.snap.scan_hz, lap.points.size()});
  for (ui::SectorWatch& sector : s.model.sectors) sector.add_lap(lap);
  if (lap.health_bits) {
    s.model.ct_health = lap.health_bits;
    s.model.ct_health_trusted = lap.ct_info_trusted();
    if (lap.ct_info_trusted()) {
      s.model.timeline.observe("CT health", *lap.health_bits, s.model.now_s,
                               ui::describe_health_bits(Model::G1, *lap.health_bits));
    }
  }
  if (lap.crc == CrcVerdict::Mismatch) ++s.model.crc_mismatch_laps;
}

void App::start_clean() {
  ui::UiModel& m = model();
  m.snap = {};
  m.scan_rate.reset();
  m.frame_ms = {};
  m.latency_ms = {};
  m.laps_shown = 0;
  m.laps_skipped = 0;
  m.points_in_lap = 0;
  m.cloud = {};
  m.points_drawn_total = 0;
  m.ct_health.reset();
  m.ct_health_trusted = true;
  m.crc_mismatch_laps = 0;
  m.timeline.clear();
  m.plots.clear();
  for (ui::SectorWatch& sector : m.sectors) sector.clear();
  m.replay = {};
  m.paused_view = false;
  m.feedback->clear();
  m.start_error.clear();
  m.source_warnings.clear();
  if (edits().distance_scale_override) {
    edits().distance_scale_override = false;
    session().set_distance_scale(std::nullopt);  // posted before the connect, so it applies to it
  }
  sel().last_set_scan_hz.reset();
  sel().last_replay_status.reset();
  sel().last_lap_at.reset();
  sel().pending_latency_rx_ns = 0;
  history().clear();
  sel().lap_phase.reset();
  shown_phase_ = 0.0f;
  sel().motion.clear();
  sel().lap = {};
  while (sel().measured_laps->try_pop(sel().measured_lap)) {
  }  // the old source's laps measure nothing of the new one
  view_->invalidate();
}

void App::frame() {
  last_frame_ = std::chrono::steady_clock::now();

  for (auto& slot : sources_) {
    drain_laps(*slot);
    update_model(*slot);
    if (static_cast<int>(slot->history.depth()) != settings_.persistence_laps) {
      slot->history.set_depth(static_cast<std::size_t>(settings_.persistence_laps));
      view_->invalidate();
    }
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

  fill_source_rows();
  const float sidebar = settings_.show_panels ? ui::draw_sidebar(model(), edits(), settings_) : 0.0f;
  const float view_w = static_cast<float>(win_w) - sidebar;
  if (const SourceSlot* pacing = fading_source())
    shown_phase_ = pacing->lap_phase.at(seconds_since_start(last_frame_));
  else if (!settings_.smooth)
    shown_phase_ = 0.0f;
  if (split_active())
    lay_out_split_view(sidebar, view_w, static_cast<float>(win_h));
  else
    lay_out_common_view(sidebar, view_w, static_cast<float>(win_h));
  ui::draw_view_header(model(), sidebar, view_w);
  model().booth = booth_.on();
  if (model().booth) {
    model().legend = ui::describe_legend(view_->colours_in_use(), settings_.persistence_laps);
    // By source, the legend in large type names each lidar and its state (only the app knows them).
    if (settings_.colours.mode == ui::ColourMode::Source)
      for (const ui::SourceRow& row : model().sources) model().legend.swatches.push_back({row.look.colour, row.legend});
    ui::draw_booth_overlay(model(), sidebar, view_w, static_cast<float>(win_h));
  }
  ImGui::Render();
  drew_ = render_if_changed(fb_scale, fb_w, fb_h);
  carry_out_requests(fb_w, fb_h);
  outputs_.follow(sel());
}

bool App::render_if_changed(float fb_scale, int fb_w, int fb_h) {
  std::uint64_t signature = ui::draw_signature(*ImGui::GetDrawData());
  for (const std::uint64_t part :
       {gl_generation(), static_cast<std::uint64_t>(fb_w), static_cast<std::uint64_t>(fb_h),
        static_cast<std::uint64_t>(settings_.show_grid), static_cast<std::uint64_t>(settings_.point_size_px * 1000.0f)})
    signature = ui::mix_signature(signature, part);
  // A screenshot reads the frame it is taken in, so that frame is always drawn; so is one the
  // window system lost (uncovered, resized).
  const bool screenshot = !options_.screenshot_path.empty() ||
                          std::any_of(model().requests.begin(), model().requests.end(), [](const ui::UiRequest& r) {
                            return std::holds_alternative<ui::SaveScreenshot>(r);
                          });
  if (signature == drawn_signature_ && !screenshot && !window_damaged_) return false;
  drawn_signature_ = signature;
  window_damaged_ = false;
  glViewport(0, 0, fb_w, fb_h);
  glClearColor(ui::kBackground[0], ui::kBackground[1], ui::kBackground[2], ui::kBackground[3]);
  glClear(GL_COLOR_BUFFER_BIT);
  if (split_active()) {
    for (const auto& tile : tiles_) tile->draw_gl(settings_, fb_scale, fb_h);
  } else {
    view_->draw_gl(settings_, fb_scale, fb_h);
  }
  glViewport(0, 0, fb_w, fb_h);
  ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
  return true;
}

void App::after_present() {
  // Frame time = the work of a frame (draining, drawing, presenting), not the wait between frames.
  const auto now = std::chrono::steady_clock::now();
  model().frame_ms.add(std::chrono::duration<double, std::milli>(now - last_frame_).count());
  if (last_present_)
    model().frame_interval_ms.add(std::chrono::duration<double, std::milli>(now - *last_present_).count());
  last_present_ = now;
  if (sel().pending_latency_rx_ns != 0) {
    const double latency_ms = static_cast<double>(steady_ns() - sel().pending_latency_rx_ns) * 1e-6;
    model().latency_ms.add(latency_ms);
    model().plots.add_latency_ms(latency_ms);
    sel().pending_latency_rx_ns = 0;
  }
}

}  // namespace ydscope::gui
