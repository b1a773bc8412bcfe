#pragma once
// One lidar of the app's source list: how the view shows it (name, colour, pose, hidden), the
// session and where its bytes come from, its laps for the view and for the measurements, and the
// panels' model of it. Each source keeps its own, so the selector switches the panels from one
// to another without losing what either measured.
#include <chrono>
#include <cstdint>
#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>

#include "app/gui/lidar_source.h"
#include "app/gui/unit_check.h"
#include "core/session/session.h"
#include "ui/panels/panel_edits.h"
#include "ui/panels/ui_model.h"
#include "ui/view/scene/lap_history.h"
#include "ui/view/scene/lap_phase.h"
#include "ui/view/scene/motion_background.h"
#include "ui/view/scene/source_set.h"

namespace ydscope::gui {

struct SourceSlot {
  // `wake` runs on the I/O thread after each lap (the window's empty event).
  SourceSlot(ui::SourceLook look_in, std::function<void()> wake)
      : look(std::move(look_in)),
        session(16, std::move(wake), "view"),
        measured_laps(session.lap_stream().subscribe("statistics", 32)),
        source(session) {}
  SourceSlot(const SourceSlot&) = delete;
  SourceSlot& operator=(const SourceSlot&) = delete;

  // How long since its newest lap, or nothing before the first.
  std::optional<double> seconds_since_lap(std::chrono::steady_clock::time_point now) const {
    if (!last_lap_at) return std::nullopt;
    return std::chrono::duration<double>(now - *last_lap_at).count();
  }

  // (source_slot.cpp) Starts `request` and puts the outcome where the user looks: the overlay,
  // the status line and the Connection panel; the source's warnings also go to stderr in the
  // words ydscope-cli uses. Empty, or the sentence of why it did not start.
  std::string start(const ui::ConnectRequest& request);
  // A new source or a Disconnect: everything measured from the old one goes.
  void clear();
  // The laps since the last frame: every one measured, in order, from a ring of its own (unless
  // the view is frozen), so a slow frame skips pictures but never a lap in the statistics; the
  // newest into the view's history (whose generation tells the view). `now_s`: the app's clock,
  // which paces the fading persistence.
  void take_laps(double now_s);

  // (source_slot_model.cpp) The panels' model from model.snap at model.now_s: the health
  // timeline, the plots, the alerts, and what the view must say about the picture.
  void refresh_model();
  // The replay's position for its panel, while a replay is the source.
  void follow_replay();

  // (source_slot_requests.cpp) What the panels ask of this source's device, replay or virtual
  // lidar; a device command's outcome is shown beside the control that asked.
  void carry_out(const ui::ControlReplay& request);
  void carry_out(const ui::SetSimFaults& request);
  void carry_out(const ui::UnplugSim& request);
  void carry_out(const ui::ReplugSim& request);
  void carry_out(const ui::SetScanHz& request);
  void carry_out(const ui::SetRangingKhz& request);
  void carry_out(const ui::RefreshHealth& request);
  void carry_out(const ui::RunCheck& request);
  void carry_out(const ui::SetDistanceScale& request);
  void carry_out(const ui::SetReading& request);

  ui::SourceLook look;
  ui::UiModel model;
  ui::PanelEdits edits;  // what its panels hold while the user types or picks
  Session session;
  std::unique_ptr<LapSubscription> measured_laps;  // every lap, for rates, plots, sectors, health
  Lap measured_lap;
  LidarSource source;                // after the session it drives, so it stops first
  UnitCheck unit_check;              // after the session it borrows, so a run is cut short first
  bool check_when_scanning = false;  // Run check asked for, to start once the session scans
  ui::LapHistory history;
  ui::LapHistory recent_laps{10};  // every lap's points, the newest 10: what Align matches
  ui::LapPhase lap_phase;          // how far between two laps, for fading persistence at display rate
  ui::MotionBackground motion;     // the room, learned from the laps the view shows
  Lap lap;                         // the newest drained
  std::optional<double> last_set_scan_hz;
  std::optional<ReplayStatus> last_replay_status;                    // the replay link's, as follow_replay last saw it
  std::optional<std::chrono::steady_clock::time_point> last_lap_at;  // newest lap of this source
  bool has_source = false;
  bool zone_beep = false;                  // ring the bell when one of this source's zones is raised
  std::int64_t pending_latency_rx_ns = 0;  // newest lap drawn this frame, measured after present

 private:
  void measure(const Lap& lap);
  void describe_view();
};

}  // namespace ydscope::gui
