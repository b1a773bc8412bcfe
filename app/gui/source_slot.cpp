// SourceSlot: starting a source, forgetting the last one, and taking its laps each frame.
#include "app/gui/source_slot.h"
#include "app/gui/zone_setup.h"

#include <cstdio>

#include "app/gui/source_origin.h"
#include "ui/view/status/health_names.h"

namespace ydscope::gui {

std::string SourceSlot::start(const ui::ConnectRequest& request) {
  const std::string error = source.start(request);
  look.origin = origin_of(request);
  has_source = error.empty();
  model.start_error = error;
  model.start_error_replay = request.kind == ui::ConnectRequest::Kind::Replay;
  model.status_message = error;
  model.source_text = source.description();
  model.sim_active = source.sim_active();
  model.replay.available = source.replay_active();
  // The Replay tab shows what the new link plays from its first frame, not the defaults.
  model.replay.speed = static_cast<float>(request.replay_speed);
  model.replay.loop = request.replay_loop;
  model.source_warnings = source.warnings();
  for (const std::string& warning : model.source_warnings)
    std::fprintf(stderr, "ydscope: warning: %s\n", warning.c_str());
  return error;
}

void SourceSlot::clear() {
  unit_check.abandon();  // a check of the old source must not take the port back from the new one
  check_when_scanning = false;
  ui::UiModel& m = model;
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
  m.dropouts.clear();
  m.zones.clear();
  m.replay = {};
  m.paused_view = false;
  m.feedback->clear();
  m.start_error.clear();
  m.source_warnings.clear();
  if (edits.distance_scale_override) {
    edits.distance_scale_override = false;
    session.set_distance_scale(std::nullopt);  // posted before the connect, so it applies to it
  }
  last_set_scan_hz.reset();
  last_replay_status.reset();
  last_lap_at.reset();
  pending_latency_rx_ns = 0;
  history.clear();
  recent_laps.clear();
  lap_phase.reset();
  motion.clear();
  lap = {};
  while (measured_laps->try_pop(measured_lap)) {
  }  // the old source's laps measure nothing of the new one
}

void SourceSlot::take_laps(double now_s) {
  while (measured_laps->try_pop(measured_lap))
    if (!model.paused_view) measure(measured_lap);
  const std::size_t drained = session.laps().drain_newest(lap);
  model.laps_skipped = session.laps().skipped();
  if (drained > 0) last_lap_at = std::chrono::steady_clock::now();
  if (drained == 0 || model.paused_view) return;
  history.push(lap);
  lap_phase.on_lap(now_s);
  motion.add_lap(lap);
  ++model.laps_shown;
  model.points_in_lap = lap.points.size();
  pending_latency_rx_ns = lap.last_rx_ns;
}

void SourceSlot::measure(const Lap& measured) {
  recent_laps.push(measured);
  // A lap cut short or held up by a stall does not time the motor: the rate starts again after it.
  if (measured.whole())
    model.scan_rate.add_lap_end(measured.index, measured.last_rx_ns);
  else
    model.scan_rate.reset();
  model.plots.add_lap(
      {model.now_s, model.scan_rate.hz(), model.snap.scan_hz, measured.points.size(), !measured.whole()});
  for (ui::SectorWatch& sector : model.sectors) sector.add_lap(measured);
  model.dropouts.add_lap(measured);
  model.zones.set_pose(look.pose);
  if (raises_a_zone(model.zones, model.zones.add_lap(measured)) && zone_beep) ring_bell();
  if (measured.health_bits) {
    model.ct_health = measured.health_bits;
    model.ct_health_trusted = measured.ct_info_trusted();
    if (measured.ct_info_trusted()) {
      model.plots.note_health(ui::HealthSource::CtBits, *measured.health_bits, model.now_s);
      model.timeline.observe("CT health", *measured.health_bits, model.now_s,
                             ui::describe_health_bits(Model::G1, *measured.health_bits));
    }
  }
  if (measured.crc == CrcVerdict::Mismatch) ++model.crc_mismatch_laps;
}

}  // namespace ydscope::gui
