// App, the part of each frame that fills the view model from the session: link state, the
// health timeline and alerts, and what the view must say about the picture (ui/view/view_state.h).
#include <chrono>
#include <cstdio>

#include "app/gui/app.h"
#include "core/protocol/commands.h"
#include "ui/view/health_names.h"

namespace ydscope::gui {
namespace {

// How long the automatic start waits for laps from a discovered port before showing the sim.
constexpr double kAutoProbeSeconds = 8.0;

}  // namespace

void App::update_model(SourceSlot& slot) {
  slot.model.now_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  slot.model.snap = slot.session.snapshot();
  if (slot.source.auto_probing()) {
    // The automatic choice found a port: keep it once laps flow, else show the virtual lidar.
    if (slot.model.snap.state == LinkState::Scanning) {
      slot.source.auto_probe_done();
      slot.model.banner.clear();
    } else if (slot.model.now_s > kAutoProbeSeconds) {  // only ever the lone, selected source
      outputs_.leave_source(slot);
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
  slot.model.sim_active = slot.source.sim_active();
  const SessionSnapshot& s = slot.model.snap;
  // The target field starts from the device's set value whenever that changes.
  if (s.scan_hz && s.scan_hz != slot.last_set_scan_hz) slot.edits.scan_target_hz = static_cast<float>(*s.scan_hz);
  slot.last_set_scan_hz = s.scan_hz;
  slot.model.timeline.observe("link", static_cast<std::uint32_t>(s.state), slot.model.now_s,
                              std::string(link_state_name(s.state)));
  slot.model.plots.sample_counters(
      {slot.model.now_s, s.counters.bytes_per_s, s.counters.checksum_errors, s.counters.crc8_failures});
  if (s.health) {
    const Model m = s.device && s.device->profile ? s.device->profile->model : Model::G6;
    const char* source = s.health->command == Command::HealthStatusBits ? "A5 92" : "A5 91";
    std::string text = ui::reports_health_bits(m) ? ui::describe_health_bits(m, s.health->status)
                                                  : std::string(ui::health_status_info(s.health->status).name);
    const std::uint32_t value = static_cast<std::uint32_t>(s.health->status) << 16 | s.health->error_code;
    if (!ui::reports_health_bits(m) && s.health->error_code) {
      char code[24];
      std::snprintf(code, sizeof code, ", error 0x%04X", static_cast<unsigned>(s.health->error_code));
      text += code;
    }
    slot.model.timeline.observe(source, value, slot.model.now_s, text);
  }
  update_view_state(slot);
}

void App::update_view_state(SourceSlot& slot) {
  const SessionSnapshot& s = slot.model.snap;
  ui::ViewStateInput in;
  in.state = s.state;
  in.link_message = s.message;
  in.address = slot.model.source_text;
  in.has_source = slot.has_source;
  in.start_error = slot.model.start_error;
  in.replay = slot.model.replay.available || (!slot.has_source && slot.model.start_error_replay);
  in.replay_paused = slot.model.replay.available && slot.model.replay.paused;
  in.replay_passes = slot.model.replay.passes;
  if (s.device && s.device->profile) in.model = s.device->profile->name;
  in.source_warnings = slot.model.source_warnings;
  if (slot.last_lap_at)
    in.seconds_since_lap = std::chrono::duration<double>(std::chrono::steady_clock::now() - *slot.last_lap_at).count();
  slot.model.view_state = ui::describe_view_state(in);
  if (slot.model.view_state.give_up && slot.model.replay.available && !slot.model.replay.paused) {
    slot.source.replay().set_paused(true);  // another pass would only spin
    slot.model.replay.paused = true;
    const ui::ViewState& v = slot.model.view_state;
    std::fprintf(stderr, "ydscope: %s; %s\n", v.subtitle.c_str(), v.detail.c_str());
  }

  ui::HealthAlertInput health;
  health.model = s.device && s.device->profile ? s.device->profile->model : Model::G6;
  if (s.health) {
    health.answer_status = s.health->status;
    health.answer_error_code = s.health->error_code;
    health.answer_is_bits = s.health->command == Command::HealthStatusBits;
  }
  health.ct_bits = slot.model.ct_health;
  health.ct_trusted = slot.model.ct_health_trusted;
  health.crc8_failures = s.counters.crc8_failures;
  slot.model.alerts = ui::health_alerts(health);
}

}  // namespace ydscope::gui
