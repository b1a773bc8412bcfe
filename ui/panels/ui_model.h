#pragma once
// What the panels read and write each frame. The app fills the measured part from the session and
// the laps; the panels turn clicks into typed requests (ui_request.h) that the app carries out
// after the frame, device commands included, whose outcome comes back in the snapshot.
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "core/analysis/dropout_ring.h"
#include "core/analysis/zone_watch.h"
#include "core/snapshot/session_snapshot.h"
#include "ui/panels/ui_request.h"
#include "ui/view/scene/colour_legend.h"
#include "ui/view/status/command_feedback.h"
#include "ui/view/status/health_alerts.h"
#include "ui/view/status/unit_check_view.h"
#include "ui/view/history/health_timeline.h"
#include "ui/view/scene/point_cloud.h"
#include "ui/view/scene/source_alignment.h"
#include "ui/view/history/rate_meters.h"
#include "ui/view/history/run_plots.h"
#include "ui/view/history/sector_watch.h"
#include "ui/view/settings/sidebar_tab.h"
#include "ui/view/settings/settings.h"
#include "ui/view/status/view_state.h"

namespace ydscope::ui {

struct PortEntry {
  std::string path;   // what to connect to
  std::string label;  // "/dev/ttyUSB0 — Silicon Labs CP2102 (0001)"
};

struct ReplayControl {
  bool available = false;  // a replay is the current source
  bool paused = false;
  bool loop = true;
  float speed = 1.0f;
  double position_s = 0.0;  // filled by the app from the replay's status
  double duration_s = 0.0;
  std::uint64_t passes = 0;  // times it went round to its start
  bool ended = false;        // played to its end without loop: nothing more comes
};

// The speeds the Replay tab's slider offers (and --speed accepts).
inline constexpr float kMinReplaySpeedShown = 0.25f;
inline constexpr float kMaxReplaySpeedShown = 8.0f;

// The Connection panel's tabs: the first three are ConnectRequest::Kind's.
enum class SourceTab { Port, Virtual, Replay, Record, Share };

// The Share toggle: the current source served to Foxglove (filled by the app).
struct ShareState {
  bool on = false;
  std::string address;      // "ws://127.0.0.1:8765" while on
  std::size_t clients = 0;  // connected now
  std::string error;        // why the last start failed ("cannot listen on ...: address in use")
};

// A file the app records live: the MCAP, or the .ydrec of every lidar shown (a session's own .ydrec
// recording is in its snapshot).
struct McapRecordingState {
  bool active = false;
  std::string path;
  std::uint64_t bytes = 0;
  std::uint64_t laps = 0;
};

// One line of the Sources panel and of the view's legend.
struct SourceRow {
  SourceLook look;
  std::string legend;  // "G6: no data 5 s, reconnecting"
  bool dim = false;    // its data stopped
};

struct UiModel {
  // ---- filled by the app each frame -------------------------------------------------------------
  SessionSnapshot snap;
  std::string source_text;      // "virtual G6 (demo scene) on /dev/pts/4", "recording demo.ydrec"
  std::string banner;           // shown over the view, e.g. "No lidar found — showing the virtual G6 (demo scene)"
  double banner_since_s = 0.0;  // when this banner first showed (the booth view fades it)
  std::string start_error;      // why the chosen source did not start (then there is no source)
  bool start_error_replay = false;           // ... and it was a recording
  std::vector<std::string> source_warnings;  // wrong with the source but not stopping it
  std::vector<PortEntry> ports;
  bool sim_active = false;
  double now_s = 0.0;                       // since start, for the health timeline
  std::optional<double> seconds_since_lap;  // empty until this source's first lap
  ScanRateMeter scan_rate;
  RunningMean frame_ms;
  RunningMean frame_interval_ms;  // start to start of frames: how often the view redraws
  RunningMean latency_ms;         // lap's last byte -> the frame that first shows it
  std::uint64_t laps_shown = 0;
  std::uint64_t laps_skipped = 0;  // drained but never shown (its LapRing::skipped)
  std::size_t points_in_lap = 0;
  std::size_t laps_on_screen = 0;  // the persistence's laps the view draws now
  PointCloudStats cloud;
  std::size_t points_drawn_total = 0;
  std::optional<std::uint8_t> ct_health;  // G1 CT health of the newest lap that carried it
  bool ct_health_trusted = true;          // false when that lap's CRC8 failed
  std::uint64_t crc_mismatch_laps = 0;
  HealthTimeline timeline;
  CounterRate bytes_rate, packets_rate, laps_rate;
  RunPlots plots;                    // the Plots panel's history
  std::vector<SectorWatch> sectors;  // the Sectors panel's, in settings order
  UnitCheckView unit_check;          // the Check panel's: Run check's progress, then its verdict
  ZoneWatch zones;                   // the zones, watched from this source (its pose)
  DropoutRing dropouts;              // no returns per degree, blocked sectors: the ring and the Lidar tab
  ReplayControl replay;
  bool paused_view = false;         // the view holds the current laps
  ViewState view_state;             // live, or dimmed with the reason in words
  std::vector<HealthAlert> alerts;  // worst first, for the status line and the badge
  ShareState share;
  McapRecordingState mcap_recording;
  McapRecordingState ydrec_recording;  // the .ydrec of every lidar shown (app/gui/source_outputs.h)
  bool booth = false;                  // the full-screen view: large type and a legend
  ColourLegend legend;                 // what the colours mean, for the booth view
  std::string booth_title;             // settings' line for visitors, over the booth view (empty: none)
  std::string booth_figure;            // the large live figure ("3 visitors"), empty when none chosen
  // Outcomes of device commands for the panel beside the control that issued them. Shared with
  // the session's completion callbacks, which run on the I/O thread.
  std::shared_ptr<CommandFeedback> feedback = std::make_shared<CommandFeedback>();
  // Opens a tab of the Connection panel once (SourceTab: 0 port, 1 virtual, 2 replay, then the
  // Record and Share tabs); -1 none.
  int show_source_tab = -1;
  // Opens a sidebar tab once (SidebarTab); -1 none.
  int show_sidebar_tab = -1;

  // How old the values shown are once laps stopped arriving; empty while live or before any lap.
  std::optional<double> stale_for_s() const { return view_state.live ? std::nullopt : seconds_since_lap; }

  // A .ydrec or an MCAP recording runs (the REC badge).
  bool recording() const { return snap.recording || mcap_recording.active || ydrec_recording.active; }

  // Every source in list order, and which one these panels show (filled each frame by the app).
  std::vector<SourceRow> sources;
  std::size_t selected_source = 0;
  bool several_sources() const { return sources.size() > 1; }
  // Align's answer, shown in the Sources tab until applied or discarded (filled by the app).
  std::optional<AlignmentProposal> alignment;

  // ---- requests from the panels, keys and mouse, carried out in order and cleared by the app -----
  std::vector<UiRequest> requests;
  std::string status_message;  // outcome of the last local action (file saved, ...)

  // ---- feedback the app keeps for the panels (their edit state is PanelEdits) ----------------
  std::string sector_error;  // why the typed sector was refused
  double record_started_s = 0.0;
};

}  // namespace ydscope::ui
