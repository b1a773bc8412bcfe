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

void App::update_model() {
  model_.now_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  model_.snap = session_.snapshot();
  if (source_.auto_probing()) {
    // The automatic choice found a port: keep it once laps flow, else show the virtual lidar.
    if (model_.snap.state == LinkState::Scanning) {
      source_.auto_probe_done();
      model_.banner.clear();
    } else if (model_.now_s > kAutoProbeSeconds) {
      leave_source();
      start_clean();
      model_.banner = source_.fall_back_to_sim();
      model_.source_text = source_.description();
      model_.snap = session_.snapshot();
    }
  }
  if (model_.banner != shown_banner_) {  // a new banner's age starts now (the booth view fades it)
    shown_banner_ = model_.banner;
    model_.banner_since_s = model_.now_s;
  }
  model_.sim_active = source_.sim_active();
  const SessionSnapshot& s = model_.snap;
  // The target field starts from the device's set value whenever that changes.
  if (s.scan_hz && s.scan_hz != last_set_scan_hz_) model_.scan_target_hz = static_cast<float>(*s.scan_hz);
  last_set_scan_hz_ = s.scan_hz;
  model_.timeline.observe("link", static_cast<std::uint32_t>(s.state), model_.now_s, std::string(link_state_name(s.state)));
  model_.plots.sample_counters({model_.now_s, s.counters.bytes_per_s, s.counters.checksum_errors, s.counters.crc8_failures});
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
    model_.timeline.observe(source, value, model_.now_s, text);
  }
  update_view_state();
}

void App::update_view_state() {
  const SessionSnapshot& s = model_.snap;
  ui::ViewStateInput in;
  in.state = s.state;
  in.link_message = s.message;
  in.address = model_.source_text;
  in.has_source = has_source_;
  in.start_error = model_.start_error;
  in.replay = model_.replay.available || (!has_source_ && model_.start_error_replay);
  in.replay_paused = model_.replay.available && model_.replay.paused;
  in.replay_passes = model_.replay.passes;
  if (s.device && s.device->profile) in.model = s.device->profile->name;
  in.source_warnings = model_.source_warnings;
  if (last_lap_at_) in.seconds_since_lap = std::chrono::duration<double>(std::chrono::steady_clock::now() - *last_lap_at_).count();
  model_.view_state = ui::describe_view_state(in);
  if (model_.view_state.give_up && model_.replay.available && !model_.replay.paused) {
    source_.replay().set_paused(true);  // another pass would only spin
    model_.replay.paused = true;
    const ui::ViewState& v = model_.view_state;
    std::fprintf(stderr, "ydscope: %s; %s\n", v.subtitle.c_str(), v.detail.c_str());
  }

  ui::HealthAlertInput health;
  health.model = s.device && s.device->profile ? s.device->profile->model : Model::G6;
  if (s.health) {
    health.answer_status = s.health->status;
    health.answer_error_code = s.health->error_code;
    health.answer_is_bits = s.health->command == Command::HealthStatusBits;
  }
  health.ct_bits = model_.ct_health;
  health.ct_trusted = model_.ct_health_trusted;
  health.crc8_failures = s.counters.crc8_failures;
  model_.alerts = ui::health_alerts(health);
}

}  // namespace ydscope::gui
