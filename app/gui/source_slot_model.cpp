// SourceSlot, the panels' model of a source from its session's snapshot: the health timeline and
// alerts, the counters' plots, the replay's position, and what the view must say about the
// picture (ui/view/status/view_state.h).
#include <chrono>
#include <cstdio>

#include "app/gui/source_slot.h"
#include "core/protocol/commands.h"
#include "ui/view/status/health_names.h"

namespace ydscope::gui {

void SourceSlot::refresh_model() {
  model.sim_active = source.sim_active();
  // A session that failed lets the check try and say why it could not.
  if (check_when_scanning && (model.snap.state == LinkState::Scanning || model.snap.state == LinkState::Failed)) {
    check_when_scanning = false;
    unit_check.start(session, source.config(), report_folder());
  }
  model.unit_check = unit_check.view();
  if (check_when_scanning) {
    model.unit_check.state = ui::UnitCheckView::State::Running;
    model.unit_check.progress = "waiting for the lidar to scan ...";
  }
  model.unit_check.available = has_source && !source.replay_active();
  const SessionSnapshot& s = model.snap;
  // The target field starts from the device's set value whenever that changes.
  if (s.scan_hz && s.scan_hz != last_set_scan_hz) edits.scan_target_hz = static_cast<float>(*s.scan_hz);
  last_set_scan_hz = s.scan_hz;
  model.timeline.observe("link", static_cast<std::uint32_t>(s.state), model.now_s,
                         std::string(link_state_name(s.state)));
  model.plots.sample_counters({model.now_s, s.counters.bytes_per_s, s.counters.checksum_errors,
                               s.counters.crc8_failures, s.counters.reconnects});
  if (s.health) {
    const Model m = s.device && s.device->profile ? s.device->profile->model : Model::G6;
    const char* command = s.health->command == Command::HealthStatusBits ? "A5 92" : "A5 91";
    std::string text = ui::reports_health_bits(m) ? ui::describe_health_bits(m, s.health->status)
                                                  : std::string(ui::health_status_info(s.health->status).name);
    const std::uint32_t value = static_cast<std::uint32_t>(s.health->status) << 16 | s.health->error_code;
    if (!ui::reports_health_bits(m) && s.health->error_code) {
      char code[24];
      std::snprintf(code, sizeof code, ", error 0x%04X", static_cast<unsigned>(s.health->error_code));
      text += code;
    }
    model.plots.note_health(ui::HealthSource::HealthAnswer, value, model.now_s);
    model.timeline.observe(command, value, model.now_s, text);
  }
  describe_view();
}

void SourceSlot::describe_view() {
  const SessionSnapshot& s = model.snap;
  ui::ViewStateInput in;
  in.state = s.state;
  in.link_message = s.message;
  in.address = model.source_text;
  in.has_source = has_source;
  in.start_error = model.start_error;
  in.replay = model.replay.available || (!has_source && model.start_error_replay);
  in.replay_paused = model.replay.available && model.replay.paused;
  in.replay_passes = model.replay.passes;
  if (s.device && s.device->profile) in.model = s.device->profile->name;
  in.decoded = {s.counters.bytes_received, s.counters.packets, s.counters.zero_packets};
  // A long gap the replay skipped (or waits out) is news beside the recording's other notices.
  std::vector<std::string> notices = model.source_warnings;
  if (const auto status = model.replay.available ? source.replay().status() : std::nullopt)
    if (std::string gap = gap_notice(status->last_gap, status->skip_gaps, status->position_ns); !gap.empty())
      notices.push_back(std::move(gap));
  in.source_warnings = notices;
  in.seconds_since_lap = seconds_since_lap(std::chrono::steady_clock::now());
  model.seconds_since_lap = in.seconds_since_lap;
  model.view_state = ui::describe_view_state(in);
  if (model.view_state.give_up && model.replay.available && !model.replay.paused) {
    source.replay().set_paused(true);  // another pass would only spin
    model.replay.paused = true;
    const ui::ViewState& v = model.view_state;
    std::fprintf(stderr, "ydscope: %s; %s\n", v.subtitle.c_str(), v.detail.c_str());
  }

  ui::HealthAlertInput health;
  health.model = s.device && s.device->profile ? s.device->profile->model : Model::G6;
  if (s.health) {
    health.answer_status = s.health->status;
    health.answer_error_code = s.health->error_code;
    health.answer_is_bits = s.health->command == Command::HealthStatusBits;
  }
  health.ct_bits = model.ct_health;
  health.ct_trusted = model.ct_health_trusted;
  health.crc8_failures = s.counters.crc8_failures;
  model.alerts = ui::health_alerts(health);
}

void SourceSlot::follow_replay() {
  ui::UiModel& m = model;
  if (!m.replay.available) return;
  if (const auto status = source.replay().status()) {
    m.replay.position_s = static_cast<double>(status->position_ns) * 1e-9;
    m.replay.duration_s = static_cast<double>(status->duration_ns) * 1e-9;
    m.replay.passes = status->loops;
    // The tab shows what the link does. Taken only when the link's value changes, so a slider
    // being dragged is not pulled back to the value the I/O thread has not caught up with.
    if (!last_replay_status || last_replay_status->speed != status->speed)
      m.replay.speed = static_cast<float>(status->speed);
    if (!last_replay_status || last_replay_status->loop != status->loop) m.replay.loop = status->loop;
    if (!last_replay_status || last_replay_status->paused != status->paused) m.replay.paused = status->paused;
    last_replay_status = status;
  }
  // Without loop the session closes the link at the recording's end and does not reopen it.
  m.replay.ended = m.snap.state == LinkState::Failed && last_lap_at.has_value();
}

}  // namespace ydscope::gui
