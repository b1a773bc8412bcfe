// SourceSlot, what the panels ask of one source: its device's commands (each outcome shown beside
// the control that asked), its replay's controls and its virtual lidar's faults and cable.
#include "app/gui/source_slot.h"
#include "ui/panels/panels.h"

namespace ydscope::gui {

void SourceSlot::carry_out(const ui::ControlReplay& request) {
  if (!model.replay.available) return;
  ReplayHandle& replay = source.replay();
  replay.set_paused(request.paused);
  replay.set_speed(request.speed);
  replay.set_loop(request.loop);
}

void SourceSlot::carry_out(const ui::SetSimFaults& request) {
  if (SimServer* sim = source.sim()) sim->set_faults(request.faults);
}

void SourceSlot::carry_out(const ui::UnplugSim&) {
  if (SimServer* sim = source.sim()) sim->unplug();
}

void SourceSlot::carry_out(const ui::ReplugSim&) {
  if (SimServer* sim = source.sim()) sim->replug();
}

void SourceSlot::carry_out(const ui::SetScanHz& request) {
  session.set_scan_hz(request.hz, ui::track_command(model, ui::CommandControl::ScanFrequency));
}

void SourceSlot::carry_out(const ui::SetRangingKhz& request) {
  session.set_ranging_khz(request.khz, ui::track_command(model, ui::CommandControl::RangingFrequency));
}

void SourceSlot::carry_out(const ui::RefreshHealth&) {
  session.refresh_health(ui::track_command(model, ui::CommandControl::Health));
}

void SourceSlot::carry_out(const ui::RunCheck&) {
  if (!has_source || source.replay_active()) return;  // the panel offers it only for a lidar
  // Once the session is scanning (refresh_model starts it): a session still opening the port
  // would hold it beside the check's, and each would read half the bytes.
  check_when_scanning = true;
}

void SourceSlot::carry_out(const ui::SetDistanceScale& request) { session.set_distance_scale(request.mm_per_count); }
void SourceSlot::carry_out(const ui::SetReading& request) { session.set_reading(request.reading); }

}  // namespace ydscope::gui
