// App, the source list: several lidars at once, each with its own session, panels and look, one
// selected for the panels; started from the command line, added, removed and posed while running,
// and drawn together in the common frame.
#include <algorithm>
#include <cstdio>

#include "app/gui/app.h"
#include "app/gui/command_line_sources.h"
#include "app/gui/source_origin.h"
#include "ui/view/settings/remembered_sources.h"

namespace ydscope::gui {
namespace {

// How long the automatic start waits for laps from a discovered port before showing the sim.
constexpr double kAutoProbeSeconds = 8.0;

}  // namespace

std::string App::start_source() {
  if (options_.share) model().requests.push_back(ui::SetShare{true});  // carried out after the first frame
  if (options_.check) model().requests.push_back(ui::RunCheck{});
  std::string banner;
  if (options_.sources.empty() && options_.source == SourceKind::Auto) {
    // The last run had several lidars: the same ones again, as they were placed.
    std::vector<SourceChoice> last = last_run_choices(settings_);
    if (last.empty()) {
      start_clean();
      sel().has_source = true;
      model().banner = sel().source.start_auto();
      model().source_text = sel().source.description();
      model().sim_active = sel().source.sim_active();
      model().show_source_tab = model().sim_active ? 1 : 0;
      return {};
    }
    options_.sources = std::move(last);
    // Short: centred over the view, it must clear the legend in its top-left corner.
    banner = "the last run's " + std::to_string(options_.sources.size()) + " lidars, as placed";
  }
  const std::string error = start_listed();
  if (!banner.empty()) model().banner = banner;
  return error;
}

std::string App::start_listed() {
  struct Listed {
    ui::SourceLook look;
    ui::ConnectRequest request;
  };
  std::vector<Listed> listed;
  if (options_.sources.empty()) {
    // The lone --port, --sim or --replay: a layer at the identity pose, its look as the settings
    // left it, its Connection tab filled in to show what runs.
    start_clean();
    listed.push_back({sel().look, command_line_request(options_, sel().edits)});
    const ui::ConnectRequest& request = listed.back().request;
    if (request.kind == ui::ConnectRequest::Kind::Replay) settings_.last_replay_file = request.address;
    model().show_source_tab = static_cast<int>(request.kind);
  }
  const std::vector<Pose> spread = ui::spread_poses(options_.sources.size());
  std::uint32_t sims = 0;  // virtual lidars so far: each answers with a serial of its own
  for (std::size_t i = 0; i < options_.sources.size(); ++i) {
    const SourceChoice& choice = options_.sources[i];
    ui::SourceLook look;
    look.name = choice.name.empty() ? choice.model.value_or("lidar") : choice.name;
    look.pose = choice.pose.value_or(spread[i]);
    look.serial = choice.serial;  // --serial: this name and pose belong to that unit, on any port
    ui::recall_look(settings_, sources_.looks(), look, choice.pose.has_value());
    listed.push_back({std::move(look), connect_request_for(choice, options_.scene)});
    if (listed.back().request.kind == ui::ConnectRequest::Kind::Sim) listed.back().request.sim_unit = sims++;
  }
  // Several lidars are told apart by colour first; by-range stays one click away. (One port
  // given a --name or --pose is still one lidar, drawn as always.)
  const bool several = listed.size() > 1;
  if (several) settings_.colours.mode = ui::ColourMode::Source;
  std::string first_error;
  for (std::size_t i = 0; i < listed.size(); ++i) {
    ui::SourceLook& look = listed[i].look;
    if (i == 0) {
      look.colour = look.colour == ui::Rgba8{} ? sel().look.colour : look.colour;
      sel().look = look;
    } else {
      sources_.add(std::move(look), static_cast<std::size_t>(settings_.persistence_laps));
    }
    sources_.select(i);  // the panels' model filled as it starts is this source's
    const std::string error = sel().start(listed[i].request);
    if (error.empty()) continue;
    // Several: each failure named on stderr, the first returned with its name.
    if (several) std::fprintf(stderr, "ydscope: %s: %s\n", sel().look.name.c_str(), error.c_str());
    if (first_error.empty()) first_error = several ? sel().look.name + ": " + error : error;
  }
  sources_.select(0);
  sync_sectors();  // several: the first source's sectors are no longer outlined round the origin
  return first_error;
}

void App::leave_source() {
  outputs_.leave_source(sources_, sources_.selected_index());
  sel().source.stop();
  start_clean();
}

void App::start_clean() {
  sel().clear();
  shown_phase_ = 0.0f;
  stage_.view().invalidate();
}

void App::select_source(std::size_t index) {
  if (index >= sources_.size() || index == sources_.selected_index()) return;
  // Share and Record cover every source: selecting another changes neither.
  sources_.select(index);
  shown_banner_ = model().banner;
  sync_sectors();
  stage_.view().invalidate();
}

void App::change_sources(const ui::SelectSource& request) { select_source(request.index); }

void App::change_sources(const ui::SetSourceLook& request) {
  if (request.index >= sources_.size()) return;
  SourceSlot& slot = sources_[request.index];
  slot.look = request.look;
  slot.model.paused_view = request.look.paused;
  stage_.view().invalidate();
}

void App::change_sources(const ui::AddSource& request) {
  ui::SourceLook look;
  look.name = request.name.empty() ? request.request.model.value_or("lidar") : request.name;
  look.pose = ui::free_spread_pose(sources_.poses());  // beside the others, not on top of them
  ui::recall_look(settings_, sources_.looks(), look, false);
  outputs_.before_change(sources_);
  SourceSlot& added = sources_.add(std::move(look), static_cast<std::size_t>(settings_.persistence_laps));
  const std::string error = added.start(request.request);
  if (!error.empty()) model().status_message = added.look.name + ": " + error;
  select_source(sources_.size() - 1);
  outputs_.after_change(sources_);
  if (settings_.colours.mode != ui::ColourMode::Source && sources_.size() == 2)
    settings_.colours.mode = ui::ColourMode::Source;
}

void App::change_sources(const ui::RemoveSource& request) {
  if (request.index >= sources_.size() || !sources_.several()) return;  // the list is never empty
  if (request.index == sources_.selected_index()) select_source(request.index == 0 ? 1 : 0);
  outputs_.before_change(sources_);  // nothing may serve or record the removed session
  sources_.remove(request.index);
  outputs_.after_change(sources_);
  sync_sectors();  // back to one lidar: its sectors are outlined again
  stage_.view().invalidate();
}

void App::update_model(SourceSlot& slot) {
  slot.model.now_s = seconds_since_start(std::chrono::steady_clock::now());
  slot.model.snap = slot.session.snapshot();
  if (slot.source.auto_probing()) {
    // The automatic choice found a port: keep it once laps flow, else show the virtual lidar.
    if (slot.model.snap.state == LinkState::Scanning) {
      slot.source.auto_probe_done();
      slot.model.banner.clear();
    } else if (slot.model.now_s > kAutoProbeSeconds) {  // only ever the lone, selected source
      outputs_.leave_source(sources_, sources_.selected_index());
      start_clean();
      slot.model.banner = slot.source.fall_back_to_sim();
      slot.model.source_text = slot.source.description();
      slot.model.snap = slot.session.snapshot();
    }
  }
  // A new banner's age starts now (the booth view fades it); the selected source's is shown.
  if (&slot == &sel() && slot.model.banner != shown_banner_) {
    shown_banner_ = slot.model.banner;
    slot.model.banner_since_s = slot.model.now_s;
  }
  slot.refresh_model();
  // Every slot is refreshed once the last one is: the units' serials can be compared now.
  if (&slot != sources_.slots().back().get()) return;
  // With no unit bound by serial, the only thing to say is that some units share one (two real
  // units, or virtual lidars started apart with one seed): worth a line on stderr, not a banner
  // over the view of lidars kept by port.
  const bool some_bound = std::any_of(sources_.slots().begin(), sources_.slots().end(),
                                      [](const auto& s) { return !s->look.serial.empty(); });
  const std::vector<std::string> notes = units_.follow(sources_);
  if (notes.empty()) return;
  std::string said;
  for (const std::string& note : notes) said += (said.empty() ? "" : " ") + note + ".";
  std::fprintf(stderr, "ydscope: %s\n", said.c_str());
  if (!some_bound) return;
  model().banner = said;
  stage_.view().invalidate();
}

}  // namespace ydscope::gui
